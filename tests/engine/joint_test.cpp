// Joints through the World API: validation (nothing changes on a refusal),
// lifetime with bodies, islands, the contacts a joint suppresses,
// determinism, and updates.

#include <gtest/gtest.h>

#include <cmath>

#include "joint_test_support.h"

namespace impulse::test {
namespace {

struct TwoBoxes {
  World world;
  BodyId ground;
  BodyId a;
  BodyId b;
  TwoBoxes() {
    ground = addGround(world);
    a = addBox(world, {.center = Vec2(0, 2)});
    b = addBox(world, {.center = Vec2(2, 2)});
  }
  JointResult create(JointDef def) { return world.createJoint(def); }
  JointDef def(JointSettings settings = DistanceJointSettings{}) {
    return {a, b, Vec2(0, 2), Vec2(2, 2), false, settings};
  }
};

void expectRefused(TwoBoxes& scene, const JointDef& def, const std::string& field) {
  std::uint64_t before = scene.world.stateHash();
  JointResult result = scene.create(def);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find(field), std::string::npos) << result.error;
  EXPECT_EQ(scene.world.jointCount(), 0);
  EXPECT_EQ(scene.world.stateHash(), before);
}

TEST(JointValidation, UnknownRemovedSameAndStaticBodies_AreRefusedWithTheReason) {
  TwoBoxes scene;
  JointDef def = scene.def();
  def.bodyA = BodyId{12345};
  expectRefused(scene, def, "bodyA");
  BodyId gone = addBox(scene.world, {.center = Vec2(5, 5)});
  scene.world.destroyBody(gone);
  def = scene.def();
  def.bodyB = gone;
  expectRefused(scene, def, "bodyB");
  def = scene.def();
  def.bodyB = def.bodyA;
  expectRefused(scene, def, "same body");
  def = scene.def();
  def.bodyA = scene.ground;
  def.bodyB = BodyId{};
  expectRefused(scene, def, "dynamic");
}

TEST(JointValidation, NonFiniteOrOutOfRangeNumbers_NameTheField) {
  TwoBoxes scene;
  const Real nan = std::nanf("");
  JointDef def = scene.def();
  def.anchorA = Vec2(nan, 0);
  expectRefused(scene, def, "anchorA");
  expectRefused(scene, scene.def(DistanceJointSettings{.length = -1}), "length");
  expectRefused(scene, scene.def(DistanceJointSettings{.stiffness = nan}), "stiffness");
  expectRefused(scene, scene.def(RopeJointSettings{.maxLength = INFINITY}), "maxLength");
  expectRefused(
      scene,
      scene.def(RevoluteJointSettings{.enableLimit = true, .lowerAngle = 1, .upperAngle = -1}),
      "lowerAngle");
  expectRefused(scene, scene.def(RevoluteJointSettings{.maxMotorTorque = -5}), "maxMotorTorque");
  expectRefused(scene, scene.def(PrismaticJointSettings{.axis = Vec2::Zero()}), "axis");
  expectRefused(scene, scene.def(WheelJointSettings{.damping = -1}), "damping");
  expectRefused(scene, scene.def(WeldJointSettings{.angularStiffness = nan}), "angularStiffness");
  expectRefused(scene, scene.def(MouseJointSettings{.maxForce = nan}), "maxForce");
}

TEST(JointLifetime, CreateDescribeListAndDestroy) {
  TwoBoxes scene;
  JointResult made = scene.create(scene.def(RopeJointSettings{}));
  ASSERT_TRUE(made.ok()) << made.error;
  EXPECT_EQ(scene.world.jointCount(), 1);
  EXPECT_EQ(scene.world.jointIds(), std::vector<JointId>{made.id});
  std::optional<JointDescription> d = scene.world.jointDescription(made.id);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->bodyA, scene.a);
  EXPECT_EQ(d->bodyB, scene.b);
  // A zero max length means the anchors' distance at creation.
  EXPECT_FLOAT_EQ(std::get<RopeJointSettings>(d->settings).maxLength, 2);
  EXPECT_TRUE(scene.world.destroyJoint(made.id));
  EXPECT_FALSE(scene.world.destroyJoint(made.id));
  EXPECT_EQ(scene.world.jointCount(), 0);
  EXPECT_FALSE(scene.world.jointDescription(made.id));
  // A reused slot gets a new generation: the old id stays dead.
  JointResult again = scene.create(scene.def());
  ASSERT_TRUE(again.ok());
  EXPECT_NE(again.id, made.id);
  EXPECT_FALSE(scene.world.jointState(made.id));
}

// The joint tree pass groups joints each step; a step after the last joint
// went must not solve last step's groups (found by world_sequence_fuzzer:
// a use after free once the joint list grew again).
TEST(JointLifetime, ABodyFreedFromItsLastPin_FallsFreely) {
  World world;
  const BodyId bob = addCircle(world, {.center = Vec2(1, 10), .radius = Real(0.2)});
  const JointId pin =
      addJoint(world, bob, BodyId{}, Vec2(1, 10), Vec2(0, 10), RevoluteJointSettings{});
  simulate(world, 0.5);
  ASSERT_TRUE(world.destroyJoint(pin));
  const BodyState released = stateOf(world, bob);
  const Real seconds = Real(0.5);
  simulate(world, seconds);
  const BodyState later = stateOf(world, bob);
  // Free flight: the velocity gains g t downwards, nothing else acts.
  EXPECT_NEAR(later.linearVelocity.x(), released.linearVelocity.x(), 1e-4);
  EXPECT_NEAR(later.linearVelocity.y() - released.linearVelocity.y(), -kG * seconds, 1e-3);
}

TEST(JointLifetime, RemovingABody_RemovesAndListsItsJoints) {
  TwoBoxes scene;
  JointId first =
      addJoint(scene.world, scene.a, scene.b, Vec2(0, 2), Vec2(2, 2), DistanceJointSettings{});
  JointId second =
      addJoint(scene.world, scene.a, BodyId{}, Vec2(0, 2), Vec2(0, 4), RopeJointSettings{});
  BodyId c = addBox(scene.world, {.center = Vec2(4, 2)});
  JointId third =
      addJoint(scene.world, scene.b, c, Vec2(2, 2), Vec2(4, 2), DistanceJointSettings{});
  scene.world.recordChanges(true);
  ASSERT_TRUE(scene.world.destroyBody(scene.a));
  const std::span<const JointId> destroyed = scene.world.changes().destroyedJoints;
  std::vector<JointId> removed(destroyed.begin(), destroyed.end());
  std::sort(removed.begin(), removed.end());
  EXPECT_EQ(removed, (std::vector<JointId>{first, second}));
  EXPECT_EQ(scene.world.jointIds(), std::vector<JointId>{third});
  simulate(scene.world, 1);
  EXPECT_TRUE(allStatesFinite(scene.world));
}

TEST(JointIslands, JointedBodiesSleepTogetherAndWakeOnChange) {
  World world;
  addGround(world);
  BodyId a = addBox(world, {.center = Vec2(0, Real(0.5))});
  BodyId b = addBox(world, {.center = Vec2(3, Real(0.5))});
  JointId joint =
      addJoint(world, a, b, Vec2(0, Real(0.5)), Vec2(3, Real(0.5)), DistanceJointSettings{});
  ASSERT_GT(simulateUntilAsleep(world, 5), 0);
  // Pushing one wakes the other through the joint.
  ASSERT_TRUE(world.applyImpulse(a, Vec2(0, 1)).ok());
  EXPECT_TRUE(stateOf(world, b).awake);
  ASSERT_GT(simulateUntilAsleep(world, 5), 0);
  ASSERT_TRUE(world.destroyJoint(joint));
  EXPECT_TRUE(stateOf(world, a).awake);
  EXPECT_TRUE(stateOf(world, b).awake);
}

TEST(JointContacts, CollideConnectedFalse_SuppressesContactsBetweenThePair) {
  World world;
  world.setGravity(Vec2::Zero());
  BodyId a = addBox(world, {.center = Vec2(0, 0)});
  BodyId b = addBox(world, {.center = Vec2(Real(0.9), 0)});
  world.step(kDt);
  ASSERT_EQ(world.contactCount(), 1);
  JointId joint = addJoint(world, a, b, Vec2(0, 0), Vec2(Real(0.9), 0), WeldJointSettings{});
  EXPECT_EQ(world.contactCount(), 0);
  simulate(world, 0.5);
  EXPECT_EQ(world.contactCount(), 0);
  // Without the joint the broad phase finds the pair again.
  world.destroyJoint(joint);
  world.step(kDt);
  EXPECT_EQ(world.contactCount(), 1);
  addJoint(world, a, b, Vec2(0, 0), Vec2(Real(0.9), 0), WeldJointSettings{}, true);
  simulate(world, 0.1);
  EXPECT_EQ(world.contactCount(), 1);
}

TEST(JointUpdate, RefusesFieldsTheKindLacksAndWakes) {
  TwoBoxes scene;
  JointId rope =
      addJoint(scene.world, scene.a, scene.b, Vec2(0, 2), Vec2(2, 2), RopeJointSettings{});
  EXPECT_FALSE(scene.world.updateJoint(rope, {.target = Vec2(1, 1)}).ok());
  EXPECT_FALSE(scene.world.updateJoint(rope, {.motorSpeed = 1}).ok());
  EXPECT_FALSE(scene.world.updateJoint(JointId{999}, {}).ok());
  JointId hinge =
      addJoint(scene.world, scene.a, BodyId{}, Vec2(0, 2), Vec2(0, 2), RevoluteJointSettings{});
  InputResult bad = scene.world.updateJoint(hinge, {.motorSpeed = std::nanf("")});
  EXPECT_NE(bad.error.find("motorSpeed"), std::string::npos) << bad.error;
  EXPECT_TRUE(scene.world.updateJoint(hinge, {.motorSpeed = 2, .maxMotorForce = 10}).ok());
  auto settings = std::get<RevoluteJointSettings>(scene.world.jointDescription(hinge)->settings);
  EXPECT_EQ(settings.motorSpeed, 2);
  EXPECT_EQ(settings.maxMotorTorque, 10);
}

// A chain of every kind of joint, run twice: the same hashes every step.
std::vector<std::uint64_t> runEveryKind() {
  World world;
  addGround(world);
  std::vector<BodyId> boxes;
  for (int i = 0; i < 8; ++i)
    boxes.push_back(addBox(world, {.center = Vec2(Real(i), Real(4 + 0.3 * i))}));
  const JointSettings kinds[] = {
      DistanceJointSettings{},
      RopeJointSettings{},
      RevoluteJointSettings{.enableMotor = true, .motorSpeed = 1, .maxMotorTorque = 50},
      PrismaticJointSettings{.enableLimit = true, .lower = -1, .upper = 1},
      WeldJointSettings{.linearStiffness = 500},
      WheelJointSettings{.stiffness = 200, .damping = 5},
      DistanceJointSettings{.stiffness = 100, .damping = 1}};
  for (int i = 0; i < 7; ++i) {
    Vec2 pa = stateOf(world, boxes[i]).position;
    Vec2 pb = stateOf(world, boxes[i + 1]).position;
    addJoint(world, boxes[i], boxes[i + 1], pa, pb, kinds[i]);
  }
  addJoint(world, boxes[0], BodyId{}, Vec2(0, 4), Vec2(0, 6),
           MouseJointSettings{.maxForce = 500, .stiffness = 200});
  std::vector<std::uint64_t> hashes;
  for (int i = 0; i < 300; ++i) {
    world.step(kDt);
    hashes.push_back(world.stateHash());
  }
  EXPECT_TRUE(allStatesFinite(world));
  return hashes;
}

TEST(JointDeterminism, EveryKindRunTwice_GivesIdenticalHashes) {
  EXPECT_EQ(runEveryKind(), runEveryKind());
}

}  // namespace
}  // namespace impulse::test

namespace impulse::test {
namespace {

// A body hanging at rest from the world: the joint carries its weight, so
// the reaction is m*g (on B, the world: downward), within 1 %.
TEST(JointState, HangingBody_ReactionIsItsWeight_LengthAndAngleReported) {
  World world;
  BodyId bob = addCircle(world, {.center = Vec2(0, -2), .radius = Real(0.2)});
  JointId rod = addJoint(world, bob, BodyId{}, Vec2(0, -2), Vec2::Zero(), DistanceJointSettings{});
  JointId pin =
      addJoint(world, bob, BodyId{}, Vec2(0, -2), Vec2(0, -2), RevoluteJointSettings{}, true);
  simulate(world, 1);
  double weight = massOf(world, bob) * kG;
  JointState rodState = *world.jointState(rod);
  JointState pinState = *world.jointState(pin);
  Vec2 total = rodState.reactionForce + pinState.reactionForce;
  std::printf("measured: hanging reaction / weight = %.6f\n", -total.y() / weight);
  EXPECT_NEAR(-total.y() / weight, 1, 0.01);
  EXPECT_NEAR(total.x(), 0, weight * 0.01);
  EXPECT_NEAR(rodState.length, 2, 0.001);
  EXPECT_NEAR(pinState.angle, 0, 0.001);
}

}  // namespace
}  // namespace impulse::test

namespace impulse::test {
namespace {

// The largest numbers createJoint accepts, on small light bodies far apart:
// every state stays finite without the step guard's repairs.
TEST(JointLimits, LargestAcceptedNumbers_KeepEveryStateFinite) {
  World world;
  const Real big = 1e9f;
  const Real force = 1e10f;
  const JointSettings kinds[] = {
      DistanceJointSettings{.length = 10, .stiffness = big, .damping = big},
      RopeJointSettings{.maxLength = Real(0.1)},
      RevoluteJointSettings{.enableLimit = true,
                            .lowerAngle = -3,
                            .upperAngle = 3,
                            .enableMotor = true,
                            .motorSpeed = 1000,
                            .maxMotorTorque = force,
                            .stiffness = big,
                            .damping = big},
      PrismaticJointSettings{.axis = Vec2(1, 1),
                             .enableLimit = true,
                             .lower = -10000,
                             .upper = 10000,
                             .enableMotor = true,
                             .motorSpeed = -1000,
                             .maxMotorForce = force,
                             .stiffness = big,
                             .damping = big},
      WeldJointSettings{.linearStiffness = big, .angularStiffness = big},
      WheelJointSettings{.axis = Vec2(0, -3),
                         .stiffness = big,
                         .damping = big,
                         .enableMotor = true,
                         .motorSpeed = 1000,
                         .maxMotorTorque = force},
      MouseJointSettings{.maxForce = force, .stiffness = big, .damping = big}};
  Real x = -20;
  for (const JointSettings& settings : kinds) {
    BodyId a = addCircle(world, {.center = Vec2(x, 5), .radius = Real(0.05)});
    BodyId b = addCircle(world, {.center = Vec2(x + 3, 7), .radius = Real(0.05)});
    addJoint(world, a, b, Vec2(x, 5), Vec2(x + 3, 7), settings);
    x += 9;
  }
  for (int i = 0; i < 240; ++i) {
    world.step(kDt);
    ASSERT_TRUE(allStatesFinite(world)) << "step " << i;
  }
  EXPECT_EQ(world.guardReport().repairedBodies, 0u);
}

}  // namespace
}  // namespace impulse::test
