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

}  // namespace impulse::viewer
