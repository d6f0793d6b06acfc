// One-sided chains keep what is in front of them: a body squeezed into a
// chain while it slides fast along it must not get its centre behind the
// chain, where nothing would ever hold it again (how bodies leaked out of
// Box2D v3's spinner scene).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numbers>
#include <vector>

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

// Box2D v3's spinner in small, at one sub-step: a crowd of circles,
// capsules and boxes made overlapping (half a metre apart, 0.7 m across)
// inside a chain loop, stirred by a kinematic rotor whose tip grazes the
// loop. Pushing themselves apart, the crowd and the rotor press the bodies
// at the edge into the loop; a body moving far less than its own size per
// step (so never swept as a fast one) can sink past a segment's line within
// the step's single solve, and the one-sided loop would let it go.
TEST(ChainCrossing, ACrowdPressedIntoAChainLoopAtOneSubStepStaysInside) {
  WorldSettings settings;
  settings.subSteps = 1;
  World world(settings);
  const Real radius = 15;
  const Vec2 centre(0, radius);
  std::vector<Vec2> loop;  // clockwise: the loop holds what is inside it
  for (int i = 0; i < 90; ++i) {
    const Real angle = -2 * std::numbers::pi_v<Real> * Real(i) / 90;
    loop.push_back(centre + radius * Vec2(std::cos(angle), std::sin(angle)));
  }
  ASSERT_TRUE(world.createChain(loop, true, BodyOptions{}).ok());

  BodyDef rotor;
  Polygon blade = makeBox(Real(0.2), radius / 2);
  blade.radius = Real(0.2);
  rotor.shape = Shape::makePolygon(blade);
  rotor.position = Vec2(0, radius / 2);
  rotor.properties.isKinematic = true;
  rotor.angularVelocity = 3;
  ASSERT_TRUE(world.createBody(rotor).ok());

  std::vector<BodyId> crowd;
  const Real rowHalfWidth = Real(0.55) * radius;
  for (int i = 0; i < 1500; ++i) {
    const Vec2 at(-rowHalfWidth + Real(0.5) * Real(i % 33), Real(0.17) * radius + Real(0.6) + Real(0.5) * Real(i / 33));
    const Vec2 half(Real(0.25), 0);
    const CreateResult body = i % 3 == 0   ? world.createCircle(at, Real(0.35))
                              : i % 3 == 1 ? world.createCapsule(at - half, at + half, Real(0.25))
                                           : world.createBody(makeBodyDef(Shape::makePolygon(makeBox(Real(0.35), Real(0.35))), at, {}));
    ASSERT_TRUE(body.ok()) << body.error;
    crowd.push_back(body.id);
  }

  int escaped = 0;
  for (int step = 0; step < 300; ++step) {
    world.step(kDt);
    for (BodyId& id : crowd) {
      if (id.isNull()) continue;
      if (!world.isValid(id) || (stateOf(world, id).position - centre).norm() > radius) {
        ++escaped;
        id = BodyId{};
      }
    }
  }
  EXPECT_EQ(escaped, 0) << "bodies got out of the loop";
}

}  // namespace
}  // namespace impulse
