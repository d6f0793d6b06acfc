// The large-world origin (World::shiftOrigin): a world far from (0, 0) with
// its origin there is the near world, bit for bit; moving the origin moves
// every stored position and nothing in the world itself; saved states carry
// it; bad origins are refused with nothing changed.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <variant>

#include "impulse/field_kinds.h"
#include "impulse/scenes/stress.h"
#include "impulse/world.h"
#include "joint_test_support.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

const Vec2d kFar(100000, -80000);

// A settling pyramid, a pendulum pinned to the world and a box a rigid mouse
// joint pulls along the ground: every kind of stored world point.
struct Playground {
  std::vector<BodyId> bodies;
  FieldId fan;
};

Playground buildPlayground(World& world) {
  Playground built;
  built.bodies = buildPyramid(world, 4).boxes;
  const BodyId bob = addCircle(world, {.center = Vec2(10, 6), .radius = Real(0.3)});
  addJoint(world, bob, {}, Vec2(10, 6), Vec2(12, 9), DistanceJointSettings{});
  const BodyId dragged = addBox(world, {.center = Vec2(-12, Real(0.5))});
  addJoint(world, dragged, {}, Vec2(-12, Real(0.5)), Vec2(-7, Real(0.5)),
           MouseJointSettings{.maxForce = 1e5f, .stiffness = 2000, .damping = 1000});
  built.bodies.push_back(bob);
  built.bodies.push_back(dragged);
  FanDef fan;
  fan.position = Vec2(-20, 5);
  built.fan = world.addField(makeField(fan).field);
  return built;
}

Vec2d globalPosition(const World& world, BodyId id) {
  return world.toGlobal(stateOf(world, id).position);
}

// The bits of every position the world keeps, its origin included: equal
// before and after a refused shift.
std::uint64_t positionBits(const World& world) {
  const WorldState state = world.exportState();
  std::uint64_t hash = 14695981039346656037ull;
  auto add = [&](const auto& value) {
    unsigned char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    for (unsigned char byte : bytes) hash = (hash ^ byte) * 1099511628211ull;
  };
  add(state.origin.x());
  add(state.origin.y());
  for (const BodySlotState& body : state.bodies) {
    add(body.transform.p.x());
    add(body.transform.p.y());
  }
  for (const JointSlotState& joint : state.joints) {
    add(joint.localAnchorB.x());
    add(joint.target.x());
  }
  for (const DynamicTree::State& tree : state.broadPhase.trees) {
    for (const DynamicTree::Node& node : tree.nodes) {
      add(node.box.lower.x());
      add(node.box.upper.y());
    }
  }
  for (const FieldSlotState& field : state.fields) add(std::get<FanDef>(field.def).position.x());
  return hash;
}

TEST(WorldOrigin, FarWorldWithItsOriginThere_StepsAsTheNearOne_BitForBit) {
  World near;
  World far;
  ASSERT_TRUE(far.shiftOrigin(kFar).ok());
  const Playground nearBodies = buildPlayground(near);
  const Playground farBodies = buildPlayground(far);
  for (int i = 0; i < stepsFor(2); ++i) {
    near.step(kDt);
    far.step(kDt);
    ASSERT_EQ(far.stateHash(), near.stateHash()) << "step " << i;
  }
  const Vec2 local = stateOf(far, farBodies.bodies.back()).position;
  EXPECT_EQ(globalPosition(far, farBodies.bodies.back()), Vec2d(kFar + local.cast<double>()));
  EXPECT_EQ(far.toLocal(globalPosition(far, farBodies.bodies.back())), local);
}

TEST(WorldOrigin, ShiftOrigin_MovesNothingInTheWorld) {
  World still;
  World shifted;
  const Playground stillBodies = buildPlayground(still);
  const Playground shiftedBodies = buildPlayground(shifted);
  simulate(still, 0.5);
  simulate(shifted, 0.5);
  const int contacts = shifted.contactCount();
  const Vec2d origin(7.3, -4.1);
  ASSERT_TRUE(shifted.shiftOrigin(origin).ok());
  EXPECT_EQ(shifted.origin(), origin);
  for (BodyId id : shiftedBodies.bodies) {
    EXPECT_LT((globalPosition(shifted, id) - globalPosition(still, id)).norm(), 1e-5);
  }
  const FanDef fan = std::get<FanDef>(*describeField(*shifted.field(shiftedBodies.fan)));
  EXPECT_LT((shifted.toGlobal(fan.position) - Vec2d(-20, 5)).norm(), 1e-5);
  // The broad phase moved with the bodies: a box around the pyramid's top
  // finds the same shapes, and the step keeps every contact.
  const Vec2d top = globalPosition(still, stillBodies.bodies[9]);
  const AABB probe{shifted.toLocal(top) - Vec2(1, 1), shifted.toLocal(top) + Vec2(1, 1)};
  const AABB stillProbe{still.toLocal(top) - Vec2(1, 1), still.toLocal(top) + Vec2(1, 1)};
  EXPECT_EQ(shifted.overlapAABB(probe).results, still.overlapAABB(stillProbe).results);
  shifted.step(kDt);
  still.step(kDt);
  EXPECT_EQ(shifted.contactCount(), contacts);

  // Stepping on, both worlds tell the same story: the pile stays, the
  // pendulum swings about its world pin, the mouse drags its box to the
  // same target.
  simulate(still, 2);
  simulate(shifted, 2);
  for (std::size_t i = 0; i < stillBodies.bodies.size(); ++i) {
    EXPECT_LT((globalPosition(shifted, shiftedBodies.bodies[i]) -
               globalPosition(still, stillBodies.bodies[i]))
                  .norm(),
              0.01)
        << "body " << i;
  }
  EXPECT_NEAR(globalPosition(shifted, shiftedBodies.bodies.back()).x(), -7, 0.05);
}

TEST(WorldOrigin, SavedStateCarriesTheOrigin_AndStepsOnBitIdentically) {
  World original;
  ASSERT_TRUE(original.shiftOrigin(kFar).ok());
  buildPlayground(original);
  simulate(original, 0.5);
  ASSERT_TRUE(original.shiftOrigin(kFar + Vec2d(0.75, -0.5)).ok());
  const WorldState saved = original.exportState();
  EXPECT_EQ(saved.origin, original.origin());

  World loaded(original.settings());
  ASSERT_TRUE(loaded.importState(saved).ok());
  EXPECT_EQ(loaded.origin(), original.origin());
  for (int i = 0; i < stepsFor(3); ++i) {
    original.step(kDt);
    loaded.step(kDt);
    ASSERT_EQ(loaded.stateHash(), original.stateHash()) << "step " << i << " after load";
  }
}

TEST(WorldOrigin, StateWithoutAnOrigin_LoadsAtZero) {
  World source;
  buildPyramid(source, 3);
  WorldState state = source.exportState();
  state.origin = Vec2d::Zero();  // what a state saved before origins holds
  World loaded;
  ASSERT_TRUE(loaded.shiftOrigin(kFar).ok());
  ASSERT_TRUE(loaded.importState(state).ok());
  EXPECT_EQ(loaded.origin(), Vec2d::Zero());
  EXPECT_EQ(loaded.stateHash(), source.stateHash());
}

// Two runs that move the origin along with a falling rain at the same steps,
// one of them on two workers: the same bits at every step.
TEST(WorldOrigin, ShiftsMidRun_AreDeterministic) {
  auto run = [](int workers) {
    WorldSettings settings;
    settings.tasks.workerCount = workers;
    World world(settings);
    EXPECT_TRUE(world.shiftOrigin(kFar).ok());
    buildRain(world, 300);
    std::vector<std::uint64_t> hashes;
    for (int i = 1; i <= stepsFor(3); ++i) {
      world.step(kDt);
      if (i % 30 == 0) {
        EXPECT_TRUE(world.shiftOrigin(world.origin() + Vec2d(0.37, -0.11)).ok());
      }
      hashes.push_back(world.stateHash());
    }
    return hashes;
  };
  EXPECT_EQ(run(2), run(1));
}

// Each refusal names the problem and leaves every position as it was.
void expectShiftRefused(World& world, const Vec2d& origin, const std::string& expected) {
  const std::uint64_t before = positionBits(world);
  const Vec2d originBefore = world.origin();
  const InputResult result = world.shiftOrigin(origin);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find(expected), std::string::npos) << result.error;
  EXPECT_EQ(world.origin(), originBefore);
  EXPECT_EQ(positionBits(world), before);
}

TEST(WorldOrigin, RefusesNonFiniteOrHugeOrigin_NothingChanged) {
  World world;
  buildPlayground(world);
  simulate(world, 0.2);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectShiftRefused(world, Vec2d(nan, 0), "origin x (m) must be a finite number");
  expectShiftRefused(world, Vec2d(0, std::numeric_limits<double>::infinity()),
                     "origin y (m) must be a finite number");
  expectShiftRefused(world, Vec2d(2e9, 0), "in [-1e+09, 1e+09]");
}

TEST(WorldOrigin, RefusesShiftThatLeavesBodiesOutOfRange_NothingChanged) {
  World world;
  buildPlayground(world);
  simulate(world, 0.2);
  expectShiftRefused(world, Vec2d(5000, 0), "outside the bounds");
}

TEST(WorldOrigin, RefusesShiftThatPutsAFieldOutOfRange_NothingChanged) {
  World world;
  FanDef fan;
  world.addField(makeField(fan).field);
  expectShiftRefused(world, Vec2d(20000, 0), "field 1 at the new origin");
}

TEST(WorldOrigin, ImportRefusesNonFiniteOrigin) {
  World source;
  buildPyramid(source, 3);
  WorldState state = source.exportState();
  state.origin.x() = std::numeric_limits<double>::quiet_NaN();
  World target;
  const InputResult result = target.importState(state);
  EXPECT_NE(result.error.find("origin x (m)"), std::string::npos) << result.error;
  EXPECT_EQ(target.bodyCount(), 0);
}

}  // namespace
}  // namespace impulse
