#pragma once
/// The part of a shape inside a convex region, exactly: area and centroid
/// of a polygon clipped by the region's edges, or of a circle cut by them
/// (triangles and circular sectors, no sampling). Liquids use it for
/// buoyancy.

#include <span>

#include "impulse/math.h"
#include "impulse/shape.h"

namespace impulse {

struct SubmergedPart {
  double area = 0;
  Vec2 centroid = Vec2::Zero();  ///< world; meaningless when area is 0
};

/// `region`: a convex polygon in world coordinates, anticlockwise.
SubmergedPart submergedPart(const Shape& shape, const Transform& transform, std::span<const Vec2> region);

}  // namespace impulse
