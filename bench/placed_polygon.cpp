#include "placed_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "joint_error.h"

namespace bench {

PlacedShape place(const BodyDesc& body, const Pose& pose) {
  PlacedShape placed{&body.shape, pose.position, {}};
  for (const Vec2d& v : body.shape.vertices) placed.vertices.push_back(worldPoint(pose, v));
  return placed;
}

Vec2d edgeNormal(const std::vector<Vec2d>& polygon, std::size_t i) {
  const Vec2d e = sub(polygon[(i + 1) % polygon.size()], polygon[i]);
  const double length = std::hypot(e.x, e.y);
  return {e.y / length, -e.x / length};
}

DeepestFace deepestFace(const std::vector<Vec2d>& a, const std::vector<Vec2d>& b) {
  DeepestFace deepest{-std::numeric_limits<double>::infinity(), 0};
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2d n = edgeNormal(a, i);
    double least = std::numeric_limits<double>::infinity();
    for (const Vec2d& p : b) least = std::min(least, dot(n, sub(p, a[i])));
    if (least > deepest.separation) deepest = {least, i};
  }
  return deepest;
}

}  // namespace bench
