#include "body_metrics.h"

#include <algorithm>

#include "impulse/client/number_format.h"
#include "impulse/material.h"

namespace impulse::viewer {

MassProperties massOf(const BodyLook& look) {
  if (look.isStatic) return {computeMassProperties(look.shape, 1).area, 0, 0};
  return computeMassProperties(look.shape, materialProperties(look.material).density);
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
  if (shape.type() == ShapeType::Circle) {
    return "circle, radius " + formatNumber(shape.circle().radius, 3) + " m";
  }
  const Polygon& polygon = shape.polygon;
  Vec2 lower = polygon.vertices[0];
  Vec2 upper = polygon.vertices[0];
  for (int i = 1; i < polygon.count; ++i) {
    lower = lower.cwiseMin(polygon.vertices[i]);
    upper = upper.cwiseMax(polygon.vertices[i]);
  }
  const Vec2 size = upper - lower;
  return "polygon, " + std::to_string(polygon.count) + " vertices, " +
         formatNumber(size.x(), 3) + " x " + formatNumber(size.y(), 3) + " m";
}

}  // namespace impulse::viewer
