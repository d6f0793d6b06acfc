#pragma once
/// World metres <-> window pixels. A frame (a world rectangle: the preset
/// scene, or where a room opens, scene_frame.h) is fitted into the scene
/// viewport (the window minus the side panel), centred, y up; the camera
/// then zooms and pans that fitted view.

#include "impulse/math.h"
#include "impulse/scenes/presets.h"

namespace impulse::viewer {

struct PixelPoint {
  float x = 0;
  float y = 0;
};

/// A rectangle of the window, pixels.
struct PixelRect {
  float x = 0;
  float y = 0;
  float w = 0;
  float h = 0;
  bool contains(float px, float py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

/// How far the user zoomed and panned away from the fitted view.
struct Camera {
  /// 1 = the frame fits the viewport.
  float zoom = 1;
  /// Pan of the view, pixels (added after fitting and zooming).
  float panX = 0;
  float panY = 0;
};

class ViewTransform {
 public:
  /// `frame` (world metres) fitted into `viewport`, then `camera` applied.
  ViewTransform(PixelRect viewport, const AABB& frame, Camera camera = {});

  PixelPoint toPixels(const Vec2& world) const;
  Vec2 toWorld(float px, float py) const;
  /// Pixels per metre.
  float scale() const { return scale_; }
  /// The frame's rectangle on screen (may extend past the viewport when zoomed).
  float left() const { return offsetX_; }
  float top() const { return offsetY_; }
  float width() const { return frameSize().x() * scale_; }
  float height() const { return frameSize().y() * scale_; }
  /// The world rectangle fitted before zoom and pan.
  const AABB& frame() const { return frame_; }
  /// Where the scene is drawn: nothing of the scene goes outside it.
  const PixelRect& viewport() const { return viewport_; }

 private:
  Vec2 frameSize() const { return frame_.upper - frame_.lower; }

  PixelRect viewport_;
  AABB frame_;
  float scale_;
  float offsetX_;
  float offsetY_;
};

/// Zooms by `factor` about the window pixel (px, py): the world point under
/// it stays under it. Zoom is kept within [0.25, 40].
Camera zoomAt(const Camera& camera, PixelRect viewport, const AABB& frame, float factor, float px,
              float py);

}  // namespace impulse::viewer
