// The narrow phase reuses a contact's manifold while its bodies have not
// moved relative to each other (0.5 mm sideways or 5 mm along the normal).

#include "world_test_support.h"

namespace impulse::test {
namespace {

int manifoldUpdatesOver(World& world, int steps) {
  int updates = 0;
  for (int i = 0; i < steps; ++i) {
    world.step(kDt);
    updates += world.profile().manifoldUpdates;
  }
  return updates;
}

TEST(NarrowPhaseReuse, RestingStackRecomputesNoManifold_OnceSettled) {
  World world(sleepless());
  addGround(world);
  for (int i = 0; i < 5; ++i) addBox(world, {.center = Vec2(0, Real(0.5) + Real(i))});
  simulate(world, 3);
  ASSERT_EQ(world.contactCount(), 5);
  // One second of rest: 300 contact-steps, none of which needs the narrow phase.
  EXPECT_EQ(manifoldUpdatesOver(world, 60), 0);
}

TEST(NarrowPhaseReuse, PushedBodyRecomputesItsManifolds) {
  World world(sleepless());
  addGround(world);
  BodyId lower = addBox(world, {.center = Vec2(0, Real(0.5))});
  BodyId upper = addBox(world, {.center = Vec2(0, Real(1.5))});
  simulate(world, 3);
  ASSERT_EQ(manifoldUpdatesOver(world, 1), 0);
  // A sideways shove moves the top box in the next step; the step after
  // recomputes its contact with the lower box (manifolds follow the poses
  // at the start of a step), and the ground contact if the lower box moved.
  ASSERT_TRUE(world.applyImpulse(upper, Vec2(500, 0)));
  world.step(kDt);
  world.step(kDt);
  EXPECT_GE(world.profile().manifoldUpdates, 1);
  EXPECT_LE(world.profile().manifoldUpdates, 2);
  EXPECT_GT(stateOf(world, upper).position.x(), stateOf(world, lower).position.x());
}

TEST(NarrowPhaseReuse, SlidingBoxRecomputesEveryStep) {
  World world(sleepless());
  addGround(world);
  addBox(world, {.center = Vec2(0, Real(0.5)), .material = Material::Ice, .velocity = Vec2(3, 0)});
  world.step(kDt);
  EXPECT_EQ(manifoldUpdatesOver(world, 30), 30);
}

}  // namespace
}  // namespace impulse::test
