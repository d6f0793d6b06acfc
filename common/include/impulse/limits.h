#pragma once
/// Physical limits on every input the engine accepts, and the checks that
/// enforce them.
///
/// With every accepted input inside these ranges (and shapes inside
/// ShapeLimits) no product the engine forms can overflow float: positions
/// stay within about 1100 m of the origin (bodies further out are removed),
/// speeds within maxSpeed, masses below 1e9 kg, so momenta stay below 1e12
/// and angular momenta and energies below 1e18. The step guard (World::step)
/// enforces the speed limits after every step as well, so they hold for the
/// world's whole life.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "impulse/body.h"
#include "impulse/math.h"

namespace impulse {

/// Ranges of every physical input. docs/server.md has them as a table.
struct InputLimits {
  /// Linear speed of any body, m/s (spawn velocity, after an impulse, after a step).
  Real maxSpeed = 500;
  /// Angular speed of any body, rad/s.
  Real maxAngularSpeed = 1000;
  /// Each gravity component, m/s^2.
  Real maxGravity = 1000;
  /// Acceleration a force may give a body (|F| / m), m/s^2.
  Real maxForceAcceleration = 1e5f;
  /// Angular acceleration a force's torque may give a body (|T| / I), rad/s^2.
  Real maxTorqueAcceleration = 1e6f;
  /// Bodies whose centre ends a step further than this outside the world
  /// bounds are removed (World::escapedBodies()). Points of application must
  /// lie within the bounds grown by this margin too.
  Real escapeMargin = 1000;
};

/// Outcome of a change requested through the World API: empty error when it
/// was applied, otherwise what was wrong (field and range) and nothing changed.
struct InputResult {
  std::string error;
  bool ok() const { return error.empty(); }
  explicit operator bool() const { return ok(); }
};

/// What the last-line guard at the end of each step did.
struct StepGuardReport {
  /// Bodies removed in the last step for leaving the world bounds far behind.
  std::vector<BodyId> escaped;
  /// Since the world was created: bodies whose state turned non-finite in a
  /// step and were put back where the step started them, at rest.
  std::uint64_t repairedBodies = 0;
  /// Since the world was created: bodies slowed to the speed limits after a step.
  std::uint64_t clampedBodies = 0;
};

/// Errors (empty when accepted) for the motion of a new body.
std::string checkBodyMotion(const InputLimits& limits, const Vec2& linearVelocity,
                            Real angularVelocity);
/// Error (empty when accepted) for a gravity vector.
std::string checkGravity(const InputLimits& limits, const Vec2& gravity);
/// Error (empty when accepted) for a point of application: finite and within
/// the world bounds grown by the escape margin. The point and the bounds are
/// relative to `origin` (World::origin()); the error quotes them from (0, 0).
std::string checkApplicationPoint(const InputLimits& limits, const AABB& bounds,
                                  const Vec2d& origin, const std::optional<Vec2>& point,
                                  const char* field);

/// A body's motion in double precision, so checks on huge requests cannot
/// overflow while they are computed.
struct MotionCheck {
  double linearSpeed = 0;
  double angularSpeed = 0;
};

/// Error (empty when accepted) for the speeds a body would have after a push.
std::string checkResultingMotion(const InputLimits& limits, const MotionCheck& motion,
                                 const char* field);

}  // namespace impulse
