// One-sided chains keep what is in front of them: a body squeezed into a
// chain while it slides fast along it must not get its centre behind the
// chain, where nothing would ever hold it again (how bodies leaked out of
// Box2D v3's spinner scene).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using test::kDt;
using test::stateOf;

MaterialOverride frictionless() {
  MaterialOverride none;
  none.staticFriction = 0;
  none.dynamicFriction = 0;
  return none;
}

TEST(ChainCrossing, AFastBodySqueezedIntoAChainStaysInFront) {
  WorldSettings settings;
  settings.gravity = Vec2::Zero();
  settings.bounds = AABB{Vec2(-60, -25), Vec2(60, 45)};
  World world(settings);
  // Terrain runs right to left: bodies collide above it.
  const std::array<Vec2, 4> floor{Vec2(50, 0), Vec2(20, 0), Vec2(-20, 0), Vec2(-50, 0)};
  BodyOptions floorOptions;
  floorOptions.materialOverride = frictionless();
  ASSERT_TRUE(world.createChain(floor, false, floorOptions).ok());

  BodyOptions ballOptions;
  ballOptions.materialOverride = frictionless();
  ballOptions.linearVelocity = Vec2(30, 0);
  const CreateResult ball = world.createCircle(Vec2(-15, Real(0.35)), Real(0.35), ballOptions);
  ASSERT_TRUE(ball.ok());

  // A kinematic plate comes down on the ball and stops with its bottom
  // 0.5 m below the floor's line, crushing it: the plate cannot give way, and
  // only the floor's one-sided contact holds the ball up.
  BodyDef plate;
  plate.shape = Shape::makePolygon(makeBox(20, Real(0.5)));
  plate.position = Vec2(0, Real(1.2));
  plate.properties.isKinematic = true;
  plate.linearVelocity = Vec2(0, -6);
  plate.materialOverride = frictionless();
  const CreateResult press = world.createBody(plate);
  ASSERT_TRUE(press.ok());

  Real lowest = stateOf(world, ball.id).position.y();
  for (int i = 0; i < 48; ++i) {
    if (i == 12) {
      ASSERT_TRUE(world.setVelocity(press.id, Vec2::Zero(), 0).ok());
    }
    world.step(kDt);
    ASSERT_TRUE(world.isValid(ball.id)) << "the ball left the world at step " << i;
    lowest = std::min(lowest, stateOf(world, ball.id).position.y());
  }
  EXPECT_GE(lowest, 0) << "the ball's centre never gets behind the floor";
  EXPECT_GT(stateOf(world, ball.id).position.x(), 0) << "and it slides on instead of pausing";
}

}  // namespace
}  // namespace impulse
