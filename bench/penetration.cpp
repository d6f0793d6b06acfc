#include "penetration.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "placed_polygon.h"

namespace bench {

namespace {

double distanceToSegment(const Vec2d& p, const Vec2d& a, const Vec2d& b) {
  Vec2d ab = sub(b, a);
  double t = std::clamp(dot(sub(p, a), ab) / dot(ab, ab), 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * ab.x), p.y - (a.y + t * ab.y));
}

double circlePolygon(const Vec2d& centre, double radius, const std::vector<Vec2d>& polygon) {
  double inside = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    inside = std::max(inside, dot(edgeNormal(polygon, i), sub(centre, polygon[i])));
  }
  if (inside > radius) return 0;
  if (inside <= 0) return radius - inside;
  double distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    distance = std::min(distance, distanceToSegment(centre, polygon[i], polygon[(i + 1) % polygon.size()]));
  }
  return std::max(0.0, radius - distance);
}

double penetration(const PlacedShape& a, const PlacedShape& b) {
  bool circleA = a.shape->kind == ShapeKind::Circle, circleB = b.shape->kind == ShapeKind::Circle;
  if (circleA && circleB) {
    double d = std::hypot(a.centre.x - b.centre.x, a.centre.y - b.centre.y);
    return std::max(0.0, a.shape->radius + b.shape->radius - d);
  }
  if (circleA) return circlePolygon(a.centre, a.shape->radius, b.vertices);
  if (circleB) return circlePolygon(b.centre, b.shape->radius, a.vertices);
  double separation = std::max(deepestFace(a.vertices, b.vertices).separation,
                               deepestFace(b.vertices, a.vertices).separation);
  return std::max(0.0, -separation);
}

}  // namespace

PenetrationProbe::PenetrationProbe(const SceneDescription& scene) : scene_(scene) {
  double largest = 0;
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
    const BodyDesc& body = scene.bodies[static_cast<std::size_t>(i)];
    if (body.isStatic) {
      statics_.push_back(i);
    } else {
      dynamics_.push_back(i);
      largest = std::max(largest, body.shape.extent());
    }
  }
  cell_ = std::max(2 * largest, 1e-3);
}

double PenetrationProbe::maxPenetration(const EngineAdapter& engine) {
  std::vector<PlacedShape> placed(scene_.bodies.size());
  for (int i = 0; i < static_cast<int>(scene_.bodies.size()); ++i) {
    placed[static_cast<std::size_t>(i)] = place(scene_.bodies[static_cast<std::size_t>(i)], engine.pose(i));
  }
  double deepest = 0;
  // Few statics, possibly huge: test each against every dynamic body.
  for (int s : statics_) {
    for (int d : dynamics_) {
      deepest = std::max(deepest, penetration(placed[std::size_t(s)], placed[std::size_t(d)]));
    }
  }
  // Dynamic pairs through a uniform grid of cells twice the largest extent:
  // touching bodies are in the same or neighbouring cells.
  auto key = [](std::int64_t x, std::int64_t y) { return (x << 32) ^ (y & 0xffffffff); };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  for (int d : dynamics_) {
    const Vec2d& c = placed[std::size_t(d)].centre;
    if (!std::isfinite(c.x) || !std::isfinite(c.y)) continue;
    grid[key(std::int64_t(std::floor(c.x / cell_)), std::int64_t(std::floor(c.y / cell_)))].push_back(d);
  }
  for (int d : dynamics_) {
    const Vec2d& c = placed[std::size_t(d)].centre;
    if (!std::isfinite(c.x) || !std::isfinite(c.y)) continue;
    auto cx = std::int64_t(std::floor(c.x / cell_)), cy = std::int64_t(std::floor(c.y / cell_));
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        auto found = grid.find(key(cx + dx, cy + dy));
        if (found == grid.end()) continue;
        for (int other : found->second) {
          if (other <= d) continue;
          deepest = std::max(deepest, penetration(placed[std::size_t(d)], placed[std::size_t(other)]));
        }
      }
    }
  }
  return deepest;
}

}  // namespace bench
