#pragma once
// The last line of defence at the end of World::step (step_guard.cpp).

#include "impulse/limits.h"
#include "world_data.h"

namespace impulse {

/// Runs over the bodies the step moved: a body with any non-finite number is
/// put back where the step started it, at rest, with its contacts' impulses
/// forgotten; speeds above the limits are scaled down to them; bodies further
/// than the escape margin outside the bounds are listed in report.escaped
/// (and dropped from the moved list) for the caller to destroy.
void guardStep(WorldData& world, StepGuardReport& report);

}  // namespace impulse
