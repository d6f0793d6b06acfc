#include "view_transform.h"

#include <algorithm>

namespace impulse::viewer {

ViewTransform::ViewTransform(int windowWidth, int windowHeight, Vec2 sceneSize)
    : sceneWidth_(sceneSize.x()), sceneHeight_(sceneSize.y()) {
  const float w = float(std::max(windowWidth, 1));
  const float h = float(std::max(windowHeight, 1));
  scale_ = std::min(w / sceneWidth_, h / sceneHeight_);
  offsetX_ = (w - sceneWidth_ * scale_) / 2;
  offsetY_ = (h - sceneHeight_ * scale_) / 2;
}

PixelPoint ViewTransform::toPixels(const Vec2& world) const {
  return {offsetX_ + world.x() * scale_, offsetY_ + (sceneHeight_ - world.y()) * scale_};
}

Vec2 ViewTransform::toWorld(float px, float py) const {
  return Vec2((px - offsetX_) / scale_, sceneHeight_ - (py - offsetY_) / scale_);
}

}  // namespace impulse::viewer
