#pragma once
// Helpers shared by the world-level behaviour tests: body creation in one
// line, stepping for a simulated duration, and whole-world checks.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "impulse/body.h"
#include "impulse/material.h"
#include "impulse/shape.h"
#include "impulse/world.h"

namespace impulse::test {

/// The fixed tick every behaviour test uses (the server's 60 Hz).
inline constexpr Real kDt = Real(1) / Real(60);
inline constexpr double kPi = std::numbers::pi;
/// Magnitude of the default gravity.
inline constexpr double kG = 9.81;

/// Number of fixed ticks in `seconds` of simulated time.
inline int stepsFor(double seconds) { return static_cast<int>(std::lround(seconds / kDt)); }

/// Steps the world for `seconds` of simulated time.
inline void simulate(World& world, double seconds) {
  for (int i = 0, n = stepsFor(seconds); i < n; ++i) world.step(kDt);
}

/// Steps for at most `seconds`, calling `observe` after every step; stops
/// early when it returns true. Returns the number of steps taken.
inline int simulateUntil(World& world, double seconds, const std::function<bool()>& observe) {
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
    world.step(kDt);
    if (observe()) return i;
  }
  return stepsFor(seconds);
}

/// Steps until every body sleeps; returns the step count, or -1 if some body
/// is still awake after `seconds`.
inline int simulateUntilAsleep(World& world, double seconds) {
  int taken = simulateUntil(world, seconds, [&] { return world.awakeBodyCount() == 0; });
  return world.awakeBodyCount() == 0 ? taken : -1;
}

/// The state of a body that must exist (a missing body fails the test and
/// yields a default state).
inline BodyState stateOf(const World& world, BodyId id) {
  std::optional<BodyState> state = world.bodyState(id);
  EXPECT_TRUE(state.has_value()) << "body " << id.value << " does not exist";
  return state.value_or(BodyState{});
}

/// Creates a body from the fields box and circle specs share; the body must
/// be accepted (a refusal fails the test).
template <typename Spec>
BodyId addBody(World& world, const Shape& shape, const Spec& spec, Real angle = 0) {
  BodyDef def;
  def.shape = shape;
  def.position = spec.center;
  def.angle = angle;
  def.material = spec.material;
  def.properties.isStatic = spec.isStatic;
  def.properties.ignoreGravity = spec.ignoreGravity;
  def.linearVelocity = spec.velocity;
  def.angularVelocity = spec.angularVelocity;
  CreateResult result = world.createBody(def);
  EXPECT_TRUE(result.ok()) << result.error;
  return result.id;
}

struct BoxSpec {
  Vec2 center = Vec2::Zero();
  Real halfWidth = Real(0.5);
  Real halfHeight = Real(0.5);
  Real angle = 0;
  Material material = Material::Solid;
  bool isStatic = false;
  bool ignoreGravity = false;
  Vec2 velocity = Vec2::Zero();
  Real angularVelocity = 0;
};

inline BodyId addBox(World& world, const BoxSpec& spec) {
  return addBody(world, Shape::makePolygon(makeBox(spec.halfWidth, spec.halfHeight)), spec, spec.angle);
}

struct CircleSpec {
  Vec2 center = Vec2::Zero();
  Real radius = Real(0.5);
  Material material = Material::Solid;
  bool isStatic = false;
  bool ignoreGravity = false;
  Vec2 velocity = Vec2::Zero();
  Real angularVelocity = 0;
};

inline BodyId addCircle(World& world, const CircleSpec& spec) {
  return addBody(world, Shape::makeCircle(spec.radius), spec);
}

/// Default settings with sleeping off: every body stays in the step.
inline WorldSettings sleepless() {
  WorldSettings settings;
  settings.enableSleep = false;
  return settings;
}

/// A static ground slab whose top face is at y = top, spanning |x| <= halfWidth.
inline BodyId addGround(World& world, Real top = 0, Real halfWidth = 20) {
  return addBox(
      world,
      {.center = Vec2(0, top - 1), .halfWidth = halfWidth, .halfHeight = 1, .isStatic = true});
}

/// Pair-mixed coefficients as the engine documents them (mean of the two).
inline double mixedRestitution(Material a, Material b) {
  return mixCoefficient(materialProperties(a).restitution, materialProperties(b).restitution);
}
inline double mixedDynamicFriction(Material a, Material b) {
  return mixCoefficient(materialProperties(a).dynamicFriction,
                        materialProperties(b).dynamicFriction);
}
inline double mixedStaticFriction(Material a, Material b) {
  return mixCoefficient(materialProperties(a).staticFriction, materialProperties(b).staticFriction);
}
inline double mixedRollingResistance(Material a, Material b) {
  return mixCoefficient(materialProperties(a).rollingResistance,
                        materialProperties(b).rollingResistance);
}

/// True when every live body has finite position, angle and velocities.
inline bool allStatesFinite(const World& world) {
  for (BodyId id : world.bodyIds()) {
    std::optional<BodyState> s = world.bodyState(id);
    if (!s || !isFinite(s->position) || !isFinite(s->angle) || !isFinite(s->linearVelocity) ||
        !isFinite(s->angularVelocity)) {
      return false;
    }
  }
  return true;
}

/// Ids of the dynamic bodies, in slot (= creation, for a fresh world) order.
inline std::vector<BodyId> dynamicBodies(const World& world) {
  std::vector<BodyId> ids;
  for (BodyId id : world.bodyIds()) {
    std::optional<BodyDescription> d = world.bodyDescription(id);
    if (d && !d->properties.isStatic) ids.push_back(id);
  }
  return ids;
}

}  // namespace impulse::test
