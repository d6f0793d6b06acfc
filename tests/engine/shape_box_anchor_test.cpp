// A resting body's shape boxes are not recomputed while the body has moved
// too little since for them to leave their fat boxes (ShapeBoxAnchor): a
// body creeping on the ground, too slowly for its boxes to be stretched
// along its motion, or turning slowly, must still take its fat boxes along
// and meet what lies ahead.

#include <cmath>

#include "world_test_support.h"

namespace impulse::test {
namespace {

// Drives `mover` at `speed` along +x for `seconds`, setting its velocity
// each step as a kinematic push would; returns how far its right face went
// past the left face of `target` at worst (positive: overlap).
Real worstOverlapWhileCreeping(World& world, BodyId mover, Real moverHalfWidth, BodyId target,
                               Real targetHalfWidth, Real speed, double seconds) {
  Real worst = -1;
  for (int i = 0; i < stepsFor(seconds); ++i) {
    EXPECT_TRUE(world.setVelocity(mover, Vec2(speed, 0), 0));
    world.step(kDt);
    const Real moverRight = stateOf(world, mover).position.x() + moverHalfWidth;
    const Real targetLeft = stateOf(world, target).position.x() - targetHalfWidth;
    worst = std::max(worst, moverRight - targetLeft);
  }
  return worst;
}

TEST(ShapeBoxAnchor, ABoxCreepingOnTheGround_MeetsTheBoxAhead) {
  World world(sleepless());
  addGround(world);
  const BodyId mover = addBox(world, {.center = Vec2(0, Real(0.5))});
  const BodyId target = addBox(world, {.center = Vec2(3, Real(0.5))});
  simulate(world, 1);
  // 5 mm a step for 2 m: the fat box's margin (about 0.2 m) is left many
  // times over, never in one step.
  const Real overlap = worstOverlapWhileCreeping(world, mover, Real(0.5), target, Real(0.5), Real(0.3), 10);
  EXPECT_LT(overlap, Real(0.02));
  EXPECT_GT(stateOf(world, target).position.x(), Real(3.5)) << "the mover pushes the box ahead along";
}

TEST(ShapeBoxAnchor, APlankTurningSlowly_MeetsTheBoxInItsSweep) {
  WorldSettings settings = sleepless();
  settings.gravity = Vec2::Zero();
  World world(settings);
  const BodyId plank = addBox(world, {.halfWidth = 2, .halfHeight = Real(0.05)});
  // In the plank's sweep, 1.5 m out at 0.8 rad: reached after 8 s.
  const Vec2 boxStart(Real(1.5 * std::cos(0.8)), Real(1.5 * std::sin(0.8)));
  const BodyId box = addBox(world, {.center = boxStart, .halfWidth = Real(0.1), .halfHeight = Real(0.1)});
  // 0.1 rad/s: its ends move 3.3 mm a step, too little for its box to be
  // stretched along the motion, so only the turn tells its box to follow.
  for (int i = 0; i < stepsFor(10); ++i) {
    ASSERT_TRUE(world.setVelocity(plank, Vec2::Zero(), Real(0.1)));
    world.step(kDt);
  }
  EXPECT_GT((stateOf(world, box).position - boxStart).norm(), Real(0.1)) << "the plank sweeps the box along";
}

}  // namespace
}  // namespace impulse::test
