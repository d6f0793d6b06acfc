#pragma once
// One shape swept against another: the narrow phase of World::castShape.

#include <optional>

#include "impulse/shape.h"
#include "shape_ref.h"

namespace impulse {

/// Where a swept shape first touches a fixed one: at start.p + fraction *
/// translation, the point on the fixed shape's surface and its unit normal
/// there, facing the swept shape (world).
struct ShapeCastTouch {
  Real fraction = 0;
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();
};

/// The first touch of `moving`, placed at `start` and translated (without
/// turning) by `translation`, with `target` placed at targetTransform,
/// within kShapeCastTolerance; fraction 0 when they start overlapping.
/// Nothing when it passes by, or meets a chain segment from behind. The
/// translation must not be zero.
std::optional<ShapeCastTouch> castShapeAgainst(ShapeRef moving, const Transform& start,
                                               const Vec2& translation, ShapeRef target,
                                               const Transform& targetTransform);

}  // namespace impulse
