#include "view_transform.h"

#include <algorithm>

namespace impulse::viewer {

namespace {

constexpr float kMinZoom = 0.25f;
constexpr float kMaxZoom = 40.0f;

}  // namespace

ViewTransform::ViewTransform(PixelRect viewport, const AABB& frame, Camera camera)
    : viewport_(viewport), frame_(frame) {
  const float w = std::max(viewport.w, 1.0f);
  const float h = std::max(viewport.h, 1.0f);
  const Vec2 size = frameSize();
  const float fitted = std::min(w / size.x(), h / size.y());
  scale_ = fitted * camera.zoom;
  // Zoom about the viewport's centre, then pan.
  offsetX_ = viewport.x + (w - size.x() * scale_) / 2 + camera.panX;
  offsetY_ = viewport.y + (h - size.y() * scale_) / 2 + camera.panY;
}

PixelPoint ViewTransform::toPixels(const Vec2& world) const {
  return {offsetX_ + (world.x() - frame_.lower.x()) * scale_,
          offsetY_ + (frame_.upper.y() - world.y()) * scale_};
}

Vec2 ViewTransform::toWorld(float px, float py) const {
  return Vec2(frame_.lower.x() + (px - offsetX_) / scale_,
              frame_.upper.y() - (py - offsetY_) / scale_);
}

Camera zoomAt(const Camera& camera, PixelRect viewport, const AABB& frame, float factor, float px,
              float py) {
  const ViewTransform before(viewport, frame, camera);
  const Vec2 anchor = before.toWorld(px, py);
  Camera zoomed = camera;
  zoomed.zoom = std::clamp(camera.zoom * factor, kMinZoom, kMaxZoom);
  // Pan so that the anchor lands back under the cursor.
  const PixelPoint moved = ViewTransform(viewport, frame, zoomed).toPixels(anchor);
  zoomed.panX += px - moved.x;
  zoomed.panY += py - moved.y;
  return zoomed;
}

}  // namespace impulse::viewer
