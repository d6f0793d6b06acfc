#pragma once
/// World metres <-> window pixels: the 25 m x 18.75 m scene scaled to fit the
/// window (32 px/m in the default 800x600 window, so the seed's pixel layout
/// maps 1:1), centred, y up, origin at the scene's bottom-left.

#include "impulse/math.h"

namespace impulse::viewer {

struct PixelPoint {
  float x = 0;
  float y = 0;
};

class ViewTransform {
 public:
  /// Scene of `sceneSize` metres fitted into a window of the given pixels.
  ViewTransform(int windowWidth, int windowHeight, Vec2 sceneSize);

  PixelPoint toPixels(const Vec2& world) const;
  Vec2 toWorld(float px, float py) const;
  /// Pixels per metre.
  float scale() const { return scale_; }
  /// The scene's rectangle on screen.
  float left() const { return offsetX_; }
  float top() const { return offsetY_; }
  float width() const { return sceneWidth_ * scale_; }
  float height() const { return sceneHeight_ * scale_; }

 private:
  float scale_;
  float offsetX_;
  float offsetY_;
  float sceneWidth_;
  float sceneHeight_;
};

}  // namespace impulse::viewer
