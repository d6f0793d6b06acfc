#include "body_metrics.h"

#include <algorithm>
#include <vector>

#include "impulse/client/number_format.h"
#include "impulse/material.h"

namespace impulse::viewer {

MassProperties massOf(const BodyLook& look) {
  const Real density = look.isStatic ? 1 : materialProperties(look.material).density;
  std::vector<MassProperties> parts{computeMassProperties(look.shape, density)};
  for (const Shape& extra : look.extraShapes) parts.push_back(computeMassProperties(extra, density));
  MassProperties total = combineMassProperties(parts);
  // What never moves by a push carries no mass to set in motion.
  if (look.isStatic || look.isKinematic) {
    total.mass = 0;
    total.inertia = 0;
  }
  return total;
}

namespace {

Real distanceToSegment(const Vec2& point, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const Real t = std::clamp((point - a).dot(ab) / std::max(ab.squaredNorm(), Real(1e-12)), Real(0), Real(1));
  return (point - (a + t * ab)).norm();
}

bool shapeTouches(const Shape& shape, const Transform& xf, const Vec2& point, Real lineReach) {
  if (isSolid(shape.type())) return containsPoint(shape, xf, point);
  const Segment& line = shape.type() == ShapeType::Segment ? shape.segment() : shape.chainSegment().segment;
  return distanceToSegment(point, xf.apply(line.point1), xf.apply(line.point2)) <= lineReach;
}

}  // namespace

bool bodyTouches(const BodyLook& look, const Transform& xf, const Vec2& point, Real lineReach) {
  if (shapeTouches(look.shape, xf, point, lineReach)) return true;
  return std::any_of(look.extraShapes.begin(), look.extraShapes.end(),
                     [&](const Shape& shape) { return shapeTouches(shape, xf, point, lineReach); });
}

double kineticEnergy(std::span<const DrawnBody> bodies) {
  double energy = 0;
  for (const DrawnBody& body : bodies) {
    if (body.look->isStatic) continue;
    const MassProperties mass = massOf(*body.look);
    const double w = body.state.angularVelocity;
    energy += 0.5 * double(mass.mass) * double(body.state.velocity.squaredNorm()) +
              0.5 * double(mass.inertia) * w * w;
  }
  return energy;
}

std::string describeShape(const Shape& shape) {
  using client::formatNumber;
  switch (shape.type()) {
    case ShapeType::Circle: return "circle, radius " + formatNumber(shape.circle().radius, 3) + " m";
    case ShapeType::Capsule:
      return "capsule, " + formatNumber((shape.capsule().center2 - shape.capsule().center1).norm(), 3) +
             " m long, radius " + formatNumber(shape.capsule().radius, 3) + " m";
    case ShapeType::Segment:
      return "segment, " + formatNumber((shape.segment().point2 - shape.segment().point1).norm(), 3) + " m";
    case ShapeType::ChainSegment: {
      const Segment& segment = shape.chainSegment().segment;
      return "chain segment, " + formatNumber((segment.point2 - segment.point1).norm(), 3) + " m";
    }
    case ShapeType::Polygon: break;
  }
  const Polygon& polygon = shape.polygon();
  Vec2 lower = polygon.vertices[0];
  Vec2 upper = polygon.vertices[0];
  for (int i = 1; i < polygon.count; ++i) {
    lower = lower.cwiseMin(polygon.vertices[i]);
    upper = upper.cwiseMax(polygon.vertices[i]);
  }
  const Vec2 size = upper - lower;
  std::string text = "polygon, " + std::to_string(polygon.count) + " vertices, " + formatNumber(size.x(), 3) +
                     " x " + formatNumber(size.y(), 3) + " m";
  if (polygon.radius > 0) text += ", rounded " + formatNumber(polygon.radius, 3) + " m";
  return text;
}

namespace {

// The type's name as describeShape writes it, plural for a count above one.
std::string typeName(ShapeType type, std::size_t count) {
  const char* name = "polygon";
  switch (type) {
    case ShapeType::Circle: name = "circle"; break;
    case ShapeType::Capsule: name = "capsule"; break;
    case ShapeType::Segment: name = "segment"; break;
    case ShapeType::ChainSegment: name = "chain segment"; break;
    case ShapeType::Polygon: break;
  }
  return std::to_string(count) + " " + name + (count == 1 ? "" : "s");
}

}  // namespace

std::string describeShapes(std::span<const Shape> shapes) {
  using client::formatNumber;
  if (shapes.size() == 1) return describeShape(shapes.front());
  const bool chain = !shapes.empty() && std::all_of(shapes.begin(), shapes.end(), [](const Shape& s) {
    return s.type() == ShapeType::ChainSegment;
  });
  if (chain) {
    Real length = 0;
    for (const Shape& s : shapes) length += (s.chainSegment().segment.point2 - s.chainSegment().segment.point1).norm();
    return "chain of " + std::to_string(shapes.size()) + " segments, " + formatNumber(length, 3) + " m";
  }
  // Counted in the order the types first appear.
  std::vector<std::pair<ShapeType, std::size_t>> counts;
  for (const Shape& s : shapes) {
    const auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == s.type(); });
    if (it == counts.end()) {
      counts.push_back({s.type(), 1});
    } else {
      ++it->second;
    }
  }
  std::string text = std::to_string(shapes.size()) + " shapes: ";
  for (std::size_t i = 0; i < counts.size(); ++i) text += (i > 0 ? ", " : "") + typeName(counts[i].first, counts[i].second);
  return text;
}

}  // namespace impulse::viewer
