#pragma once
// Support rows side by side for the SIMD support pass (support_pass.h), as
// many as the lane type F holds. Each lane is laid out with its upper body
// as B (a row whose upper body was A is swapped and its normal negated), so
// a bundle only ever moves its B bodies, and all of them are distinct.

#include <cstdint>

namespace impulse {

/// One row's numbers, upper body as B, as its contact is prepared: written
/// whole into one record, then read with the other lanes of its bundle and
/// turned into the bundle's columns (finishSupportBundles). Written lane by
/// lane into the bundle itself, each field had cost a scattered store.
/// Laid out as whole rows of eight words (the columns' transpose).
struct SupportLaneRecord {
  std::int32_t stateA = 0;  ///< the lower body
  std::int32_t stateB = 0;  ///< the upper body
  float normalX = 0, normalY = 0;
  float invMass = 0, invInertia = 0;
  float slipFriction = 0;
  struct Point {
    float anchorAX = 0, anchorAY = 0, anchorBX = 0, anchorBY = 0;
    float baseSeparation = 0;
    std::uint32_t present = 0;  ///< all bits set where the point exists
  } points[2];
  std::int32_t unused[5] = {};
};
static_assert(sizeof(SupportLaneRecord) == 24 * sizeof(float));

template <class F>
struct WideSupportPoint {
  F anchorAX, anchorAY, anchorBX, anchorBY;
  F baseSeparation;
  /// The upper body's lever arm about the normal.
  F arm;
  /// All-ones where the point exists (a one-point manifold's second does not).
  F present;
  /// The pass's impulse in the last sub-step.
  F impulse;
  /// 1 / K_jj: this point lifting alone.
  F singleMass;
  /// The upper body's lever arm about the tangent (the normal's right
  /// perpendicular).
  F tangentArm;
};

template <class F>
struct WideSupportRow {
  std::int32_t stateA[F::kLanes];  ///< the lower body (read only)
  std::int32_t stateB[F::kLanes];  ///< the upper body
  F normalX, normalY;  ///< from the lower body towards the upper one
  F invMass, invInertia;  ///< the upper body's
  /// The upper body's response K at both points, inverted (zero when singular).
  F pairInverse11, pairInverse12, pairInverse22;
  F k12;
  /// The friction with which a row on the static world holds its lift from
  /// making the points slip: the contact's where friction holds it
  /// sideways, else zero (support_pass_wide_impl.h, holdSlip).
  F slipFriction;
  /// All-ones where the row leans (SupportRow::leans).
  F leans;
  WideSupportPoint<F> points[2];
};

}  // namespace impulse
