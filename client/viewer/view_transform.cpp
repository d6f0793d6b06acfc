#include "view_transform.h"

#include <algorithm>

namespace impulse::viewer {

namespace {

constexpr float kMinZoom = 0.25f;
constexpr float kMaxZoom = 40.0f;

}  // namespace

ViewTransform::ViewTransform(PixelRect viewport, Vec2 sceneSize, Camera camera)
    : viewport_(viewport), sceneWidth_(sceneSize.x()), sceneHeight_(sceneSize.y()) {
  const float w = std::max(viewport.w, 1.0f);
  const float h = std::max(viewport.h, 1.0f);
  const float fitted = std::min(w / sceneWidth_, h / sceneHeight_);
  scale_ = fitted * camera.zoom;
  // Zoom about the viewport's centre, then pan.
  offsetX_ = viewport.x + (w - sceneWidth_ * scale_) / 2 + camera.panX;
  offsetY_ = viewport.y + (h - sceneHeight_ * scale_) / 2 + camera.panY;
}

PixelPoint ViewTransform::toPixels(const Vec2& world) const {
  return {offsetX_ + world.x() * scale_, offsetY_ + (sceneHeight_ - world.y()) * scale_};
}

Vec2 ViewTransform::toWorld(float px, float py) const {
  return Vec2((px - offsetX_) / scale_, sceneHeight_ - (py - offsetY_) / scale_);
}

Camera zoomAt(const Camera& camera, PixelRect viewport, Vec2 sceneSize, float factor, float px,
              float py) {
  const ViewTransform before(viewport, sceneSize, camera);
  const Vec2 anchor = before.toWorld(px, py);
  Camera zoomed = camera;
  zoomed.zoom = std::clamp(camera.zoom * factor, kMinZoom, kMaxZoom);
  // Pan so that the anchor lands back under the cursor.
  const PixelPoint moved = ViewTransform(viewport, sceneSize, zoomed).toPixels(anchor);
  zoomed.panX += px - moved.x;
  zoomed.panY += py - moved.y;
  return zoomed;
}

}  // namespace impulse::viewer
