#pragma once
// A body's convex polygon placed at a pose, and the separating-axis test on
// two of them: what the bench's pose-only probes (penetration.h,
// contact_slip.h) measure with, the same way for every engine.

#include <cstddef>
#include <vector>

#include "engine_adapter.h"

namespace bench {

inline double dot(const Vec2d& a, const Vec2d& b) { return a.x * b.x + a.y * b.y; }
inline Vec2d sub(const Vec2d& a, const Vec2d& b) { return {a.x - b.x, a.y - b.y}; }

/// A body's shape at a pose; `vertices` (world, anticlockwise) for polygons.
struct PlacedShape {
  const ShapeDesc* shape = nullptr;
  Vec2d centre;
  std::vector<Vec2d> vertices;
};

PlacedShape place(const BodyDesc& body, const Pose& pose);

/// The outward unit normal of edge i (from vertex i to vertex i + 1).
Vec2d edgeNormal(const std::vector<Vec2d>& polygon, std::size_t i);

/// The edge of polygon `a` that `b` lies farthest out from: the largest,
/// over a's edges, of the least separation of b's vertices from that edge
/// (negative: the polygons overlap, by at least its size along that edge's
/// normal).
struct DeepestFace {
  double separation = 0;
  std::size_t edge = 0;
};
DeepestFace deepestFace(const std::vector<Vec2d>& a, const std::vector<Vec2d>& b);

}  // namespace bench
