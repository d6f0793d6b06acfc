// Shape casts by conservative advancement: a shape moving in a straight line
// cannot close a gap faster than it travels, so stepping it forward by the
// gap (the exact distance between the shapes) never steps through the
// target. Head on, one step closes the gap; at an angle each step closes a
// share of it, and a near-tangent graze that has not closed within the
// step budget counts as passing by.

#include "shape_cast.h"

#include "impulse/query.h"
#include "shape_pair.h"

namespace impulse {
namespace {

constexpr int kMaxAdvances = 100;

// The touch at a pose within tolerance of the target, read from their
// manifold (normal from the moving shape to the target, points midway
// between the surfaces). A chain segment met from behind, or through a join
// that belongs to its neighbour, has no manifold and so no touch.
std::optional<ShapeCastTouch> touchAt(ShapeRef moving, const Transform& pose, ShapeRef target,
                                      const Transform& targetTransform, Real fraction) {
  const Manifold manifold = collide(moving, pose, target, targetTransform);
  if (manifold.pointCount == 0) return std::nullopt;
  Vec2 point = Vec2::Zero();
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ManifoldPoint& contact = manifold.points[i];
    point += contact.point + Real(0.5) * contact.separation * manifold.normal;
  }
  return ShapeCastTouch{fraction, point / Real(manifold.pointCount), -manifold.normal};
}

}  // namespace

std::optional<ShapeCastTouch> castShapeAgainst(ShapeRef moving, const Transform& start,
                                               const Vec2& translation, ShapeRef target,
                                               const Transform& targetTransform) {
  const Real length = translation.norm();
  Real fraction = 0;
  for (int advance = 0; advance < kMaxAdvances; ++advance) {
    const Transform pose{start.p + fraction * translation, start.q};
    const Real gap = computeSeparation(moving, pose, target, targetTransform);
    if (gap < kShapeCastTolerance) return touchAt(moving, pose, target, targetTransform, fraction);
    fraction += gap / length;
    if (fraction > 1) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace impulse
