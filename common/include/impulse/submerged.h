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
/// Exact for circles and polygons; capsules and rounded polygons are clipped
/// with their arcs in steps of pi/16. Segments have no area.
SubmergedPart submergedPart(const Shape& shape, const Transform& transform, std::span<const Vec2> region);
/// The union of a body's shapes (they do not overlap, or the overlap counts
/// twice, as it does in the body's mass).
SubmergedPart submergedPart(std::span<const Shape* const> shapes, const Transform& transform,
                            std::span<const Vec2> region);

}  // namespace impulse
