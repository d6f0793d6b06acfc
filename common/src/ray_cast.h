#pragma once
// A ray against one shape: the narrow phase of World's ray casts.

#include <optional>

#include "impulse/shape.h"
#include "shape_ref.h"

namespace impulse {

/// Where a ray enters a shape: origin + fraction * translation, and the
/// surface's unit normal there (world), facing the ray.
struct ShapeRayHit {
  Real fraction = 0;
  Vec2 normal = Vec2::Zero();
};

/// The first point where the segment origin -> origin + translation
/// (world) enters the shape placed at transform. Nothing when it misses,
/// when it starts inside a solid shape, or when it meets a chain segment
/// from behind (chains are hit from their collision side only). The
/// translation must not be zero.
std::optional<ShapeRayHit> rayCastShape(ShapeRef shape, const Transform& transform,
                                        const Vec2& origin, const Vec2& translation);

}  // namespace impulse
