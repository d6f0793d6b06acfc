#include "view_area.h"

#include <cmath>

namespace impulse::viewer {

AABB viewArea(const ViewTransform& view, float margin) {
  const PixelRect& port = view.viewport();
  // Pixels grow downwards: the top-left pixel is the area's upper-left corner.
  const Vec2 upperLeft = view.toWorld(port.x, port.y);
  const Vec2 lowerRight = view.toWorld(port.x + port.w, port.y + port.h);
  const Vec2 grow(margin, margin);
  return {Vec2(upperLeft.x(), lowerRight.y()) - grow, Vec2(lowerRight.x(), upperLeft.y()) + grow};
}

bool areaMoved(const AABB& sent, const AABB& wanted, float slack) {
  const Vec2 lower = (wanted.lower - sent.lower).cwiseAbs();
  const Vec2 upper = (wanted.upper - sent.upper).cwiseAbs();
  return lower.maxCoeff() > slack || upper.maxCoeff() > slack;
}

}  // namespace impulse::viewer
