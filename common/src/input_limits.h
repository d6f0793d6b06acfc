#pragma once
// Checks of pushes on existing bodies against InputLimits (input_limits.cpp).
// They read the body's mass and motion, so they live beside the private
// world state. Each returns an empty string when the push is accepted.

#include <optional>
#include <string>

#include "impulse/limits.h"
#include "world_data.h"

namespace impulse {

/// A number as error messages print it, shortest readable: "500", "3.4e+38".
std::string describeNumber(double value);

/// A coordinate as error messages print it: to the micrometre, without
/// trailing zeros ("80049.845676", "-25"), so one far from (0, 0) keeps its
/// metres' fractions.
std::string describeCoordinate(double value);

/// One number: empty when finite and within [lo, hi], else a sentence that
/// names the field and the range.
std::string checkRange(const std::string& field, double value, double lo, double hi);

/// A world origin: finite and within kMaxOriginCoordinate of (0, 0).
std::string checkOrigin(const Vec2d& origin);

/// A body's centre where it is created or moved to: inside the bounds. The
/// refusal quotes the bounds from (0, 0).
std::string checkInsideBounds(const WorldData& world, const Vec2& position);

/// An impulse (N*s) at `point` (default: the centre of mass).
std::string checkImpulse(const WorldData& world, BodyId id, const Vec2& impulse,
                         const std::optional<Vec2>& point);
/// A force (N) at `point`, added to the forces already pending for the step.
std::string checkForce(const WorldData& world, BodyId id, const Vec2& force,
                       const std::optional<Vec2>& point);
/// New velocities of a body.
std::string checkSetVelocity(const WorldData& world, BodyId id, const Vec2& linear, Real angular);

}  // namespace impulse
