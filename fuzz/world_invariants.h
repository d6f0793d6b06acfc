#pragma once
// What must hold for every body of a world at any time (docs/engine.md):
// finite numbers and speeds within the input limits.
#include <cmath>

#include "fuzz_check.h"
#include "impulse/world.h"

inline void checkWorldSane(const impulse::World& world) {
  const impulse::InputLimits& limits = world.settings().inputLimits;
  for (const impulse::BodyId id : world.bodyIds()) {
    const auto state = world.bodyState(id);
    FUZZ_CHECK(state.has_value());
    FUZZ_CHECK(impulse::isFinite(state->position) && impulse::isFinite(state->angle));
    FUZZ_CHECK(impulse::isFinite(state->linearVelocity));
    FUZZ_CHECK(impulse::isFinite(state->angularVelocity));
    // Clamped to the limit in float: allow its rounding.
    FUZZ_CHECK(state->linearVelocity.norm() <= limits.maxSpeed * 1.0001f);
    FUZZ_CHECK(std::abs(state->angularVelocity) <= limits.maxAngularSpeed);
  }
}
