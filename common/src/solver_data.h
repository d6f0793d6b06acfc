#pragma once
// What the solver keeps per awake body during a step, shared by every kind
// of constraint (constraint_kind.h).

#include <cstdint>

#include "edge_list.h"
#include "impulse/math.h"

namespace impulse {

/// Velocity and accumulated motion of an awake body during a step: the hot
/// data the constraint passes stream through every sub-step (32 bytes).
struct SolverState {
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  Vec2 deltaPosition = Vec2::Zero();
  Rot deltaRotation;
  Real padding = 0;
};

/// A body's real velocity, set aside while the push pass borrows the state's
/// velocity slots for pseudo velocities.
struct ParkedVelocity {
  Vec2 linear = Vec2::Zero();
  Real angular = 0;
};

/// Per-body integration inputs, read once per sub-step.
struct SolverIntegration {
  Vec2 linearAcceleration = Vec2::Zero();  ///< gravity plus force / mass
  Real angularAcceleration = 0;
  Real linearDamping = 1;   ///< velocity factor per sub-step
  Real angularDamping = 1;
  std::int32_t body = kNullIndex;
  /// The body's extent, so that the push pass's end need not read the body
  /// to tell whether it was pushed (keepAwakeWhilePushed).
  Real extent = 0;
};

/// A soft constraint's spring-damper terms for one sub-step length.
struct Softness {
  Real biasRate = 0;
  Real massScale = 1;
  Real impulseScale = 0;
};

/// Spring-damper softness for a constraint of stiffness `hertz` and
/// `dampingRatio`, solved with sub-step h (hertz 0: rigid).
Softness makeSoftness(Real hertz, Real dampingRatio, Real h);

}  // namespace impulse
