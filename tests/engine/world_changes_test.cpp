// The world's change record (World::changes): every call that changes the
// world, and every step, lists what it changed once; a refused call lists
// nothing; clearing forgets the lists but not the revision; a clear, a load
// or an assignment says the world was replaced.

#include <gtest/gtest.h>

#include <memory>
#include <span>
#include <vector>

#include "impulse/fan.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

template <class Id>
std::vector<Id> listed(std::span<const Id> ids) {
  return {ids.begin(), ids.end()};
}

// Every list of the record, empty or not, for comparing whole records.
bool nothingListed(const ChangeView& changes) {
  return changes.createdBodies.empty() && changes.redescribedBodies.empty() &&
         changes.movedBodies.empty() && changes.destroyedBodies.empty() &&
         changes.escapedBodies.empty() && changes.createdJoints.empty() &&
         changes.updatedJoints.empty() && changes.destroyedJoints.empty() &&
         changes.addedFields.empty() && changes.removedFields.empty() && !changes.replaced &&
         !changes.settingsChanged && !changes.originShifted;
}

ShapeDef smallCircle(Vec2 center) {
  ShapeDef def;
  def.shape = translated(Shape::makeCircle(Real(0.2)), center);
  return def;
}

JointDef rodBetween(BodyId a, Vec2 anchorA, BodyId b, Vec2 anchorB) {
  return {a, b, anchorA, anchorB, false, DistanceJointSettings{}};
}

// A world that lists its changes (World::recordChanges).
World recordingWorld(const WorldSettings& settings = {}) {
  World world(settings);
  world.recordChanges(true);
  return world;
}

// Two boxes side by side in a world with nothing else, changes cleared.
struct TwoBoxes {
  World world = recordingWorld();
  BodyId left = addBox(world, {.center = Vec2(0, 5)});
  BodyId right = addBox(world, {.center = Vec2(3, 5)});
  TwoBoxes() { world.clearChanges(); }
};

TEST(WorldChanges, ANewWorld_ListsNothing) {
  World world = recordingWorld();
  EXPECT_TRUE(nothingListed(world.changes()));
  EXPECT_EQ(world.changes().revision, 0u);
}

TEST(WorldChanges, AWorldNotRecording_ListsNothing_ButItsRevisionMoves) {
  World world;
  const BodyId ball = addCircle(world, {.center = Vec2(0, 5)});
  for (int i = 0; i < 10; ++i) world.step(Real(1) / 60);
  ASSERT_TRUE(world.destroyBody(ball));
  EXPECT_TRUE(nothingListed(world.changes()));
  EXPECT_GE(world.changes().revision, 12u);
}

TEST(WorldChanges, EachBodyEdit_ListsTheBodyOnceUnderItsKind) {
  TwoBoxes scene;
  World& world = scene.world;
  const BodyId ball = addCircle(world, {.center = Vec2(6, 5)});
  EXPECT_EQ(listed(world.changes().createdBodies), std::vector{ball});

  ASSERT_TRUE(world.setTransform(scene.left, Vec2(0, 6), 0));
  ASSERT_TRUE(world.setVelocity(scene.left, Vec2(1, 0), 0));
  ASSERT_TRUE(world.applyImpulse(scene.right, Vec2(1, 0)));
  ASSERT_TRUE(world.applyForce(scene.right, Vec2(1, 0)));
  ASSERT_TRUE(world.setTargetTransform(ball, Vec2(6, 6), 0, kDt));
  EXPECT_EQ(listed(world.changes().movedBodies), (std::vector{scene.left, scene.right, ball}));

  const ShapeResult extra = world.createShape(scene.left, smallCircle(Vec2(0, 1)));
  ASSERT_TRUE(extra.ok()) << extra.error;
  ASSERT_TRUE(world.destroyShape(extra.id));
  ASSERT_TRUE(world.setMaterial(scene.left, Material::Rubber));
  ASSERT_TRUE(world.setBodyType(scene.right, BodyType::Kinematic));
  ShapeInteraction sensor;
  sensor.isSensor = true;
  ASSERT_TRUE(world.setShapeInteraction(world.bodyDescription(ball)->shapes.front().id, sensor));
  EXPECT_EQ(listed(world.changes().redescribedBodies),
            (std::vector{scene.left, scene.right, ball}));

  ASSERT_TRUE(world.destroyBody(ball));
  EXPECT_EQ(listed(world.changes().destroyedBodies), std::vector{ball});
  EXPECT_EQ(listed(world.changes().createdBodies), std::vector{ball})
      << "created, then destroyed: in both";
  EXPECT_TRUE(world.changes().escapedBodies.empty());
}

TEST(WorldChanges, JointEdits_ListTheJointAndTheBodiesTheyWake) {
  TwoBoxes scene;
  World& world = scene.world;
  const JointResult rod =
      world.createJoint(rodBetween(scene.left, Vec2(0, 5), scene.right, Vec2(3, 5)));
  ASSERT_TRUE(rod.ok()) << rod.error;
  EXPECT_EQ(listed(world.changes().createdJoints), std::vector{rod.id});
  EXPECT_EQ(listed(world.changes().movedBodies), (std::vector{scene.left, scene.right}));
  world.clearChanges();

  JointUpdate update;
  update.target = Vec2(1, 1);
  EXPECT_FALSE(world.updateJoint(rod.id, update)) << "a distance joint has no target";
  EXPECT_TRUE(world.changes().updatedJoints.empty());
  const JointResult pull = world.createJoint(
      {scene.left, BodyId{}, Vec2(0, 5), Vec2(0, 5), false, MouseJointSettings{}});
  ASSERT_TRUE(pull.ok()) << pull.error;
  ASSERT_TRUE(world.updateJoint(pull.id, update));
  update.target = Vec2(2, 2);
  ASSERT_TRUE(world.updateJoint(pull.id, update));
  EXPECT_EQ(listed(world.changes().updatedJoints), std::vector{pull.id});
  EXPECT_EQ(listed(world.changes().movedBodies), std::vector{scene.left})
      << "a world-held side names no body";
  world.clearChanges();

  ASSERT_TRUE(world.destroyJoint(rod.id));
  EXPECT_FALSE(world.destroyJoint(rod.id));
  EXPECT_EQ(listed(world.changes().destroyedJoints), std::vector{rod.id});
  EXPECT_EQ(listed(world.changes().movedBodies), (std::vector{scene.left, scene.right}));
  world.clearChanges();

  // A joint that goes with its body is listed; the body is not also moved.
  ASSERT_TRUE(world.destroyBody(scene.left));
  EXPECT_EQ(listed(world.changes().destroyedJoints), std::vector{pull.id});
  EXPECT_TRUE(world.changes().movedBodies.empty());
}

TEST(WorldChanges, FieldsAndGravity_AreListed) {
  World world = recordingWorld();
  const FieldId fan =
      world.addField(makeFan({.position = Vec2(0, 0), .direction = Vec2(1, 0)}).field);
  ASSERT_FALSE(fan.isNull());
  EXPECT_EQ(listed(world.changes().addedFields), std::vector{fan});
  EXPECT_FALSE(world.removeField(FieldId{fan.value + 1}));
  ASSERT_TRUE(world.removeField(fan));
  EXPECT_EQ(listed(world.changes().removedFields), std::vector{fan});
  EXPECT_FALSE(world.changes().settingsChanged);
  ASSERT_TRUE(world.setGravity(Vec2(0, -1)));
  EXPECT_TRUE(world.changes().settingsChanged);
}

TEST(WorldChanges, RefusedCalls_ListNothingAndKeepTheRevision) {
  TwoBoxes scene;
  World& world = scene.world;
  const std::uint64_t revision = world.changes().revision;
  EXPECT_FALSE(world.createCircle(Vec2(5, 5), -1).ok());
  EXPECT_FALSE(world.setTransform(BodyId{9999}, Vec2(0, 0), 0));
  EXPECT_FALSE(world.setVelocity(scene.left, Vec2(1e9f, 0), 0));
  EXPECT_FALSE(world.setGravity(Vec2(0, -1e9f)));
  EXPECT_FALSE(world.createJoint(rodBetween(scene.left, Vec2(0, 5), scene.left, Vec2(0, 5))).ok());
  EXPECT_FALSE(world.destroyBody(BodyId{9999}));
  WorldState negativeTime = world.exportState();
  negativeTime.time = -1;
  EXPECT_FALSE(world.importState(negativeTime));
  EXPECT_TRUE(nothingListed(world.changes()));
  EXPECT_EQ(world.changes().revision, revision);
}

TEST(WorldChanges, Clearing_ForgetsTheListsButNotTheRevision) {
  TwoBoxes scene;
  World& world = scene.world;
  ASSERT_TRUE(world.applyImpulse(scene.left, Vec2(1, 0)));
  const std::uint64_t revision = world.changes().revision;
  EXPECT_GT(revision, 0u);
  world.clearChanges();
  EXPECT_TRUE(nothingListed(world.changes()));
  EXPECT_EQ(world.changes().revision, revision);
  ASSERT_TRUE(world.applyImpulse(scene.left, Vec2(1, 0)));
  EXPECT_EQ(listed(world.changes().movedBodies), std::vector{scene.left})
      << "listed again after the clear";
  EXPECT_GT(world.changes().revision, revision);
}

TEST(WorldChanges, EveryChange_MovesTheRevision_EvenOfABodyListedAlready) {
  TwoBoxes scene;
  World& world = scene.world;
  ASSERT_TRUE(world.applyImpulse(scene.left, Vec2(1, 0)));
  const std::uint64_t revision = world.changes().revision;
  ASSERT_TRUE(world.applyImpulse(scene.left, Vec2(1, 0)));
  EXPECT_GT(world.changes().revision, revision) << "the state changed again";
  EXPECT_EQ(world.changes().movedBodies.size(), 1u);
}

// A slot freed and handed to a new body: the new id is listed beside the
// old one, although the slot was listed already.
TEST(WorldChanges, ASlotReused_ListsTheOldAndTheNewBody) {
  TwoBoxes scene;
  World& world = scene.world;
  ASSERT_TRUE(world.applyImpulse(scene.right, Vec2(1, 0)));
  ASSERT_TRUE(world.destroyBody(scene.right));
  const BodyId successor = addCircle(world, {.center = Vec2(3, 5)});
  ASSERT_EQ(successor.slot(), scene.right.slot());
  ASSERT_NE(successor, scene.right);
  ASSERT_TRUE(world.applyImpulse(successor, Vec2(1, 0)));
  EXPECT_EQ(listed(world.changes().movedBodies), (std::vector{scene.right, successor}));
  EXPECT_EQ(listed(world.changes().destroyedBodies), std::vector{scene.right});
  EXPECT_EQ(listed(world.changes().createdBodies), std::vector{successor});

  world.clearChanges();
  ASSERT_TRUE(world.applyImpulse(successor, Vec2(1, 0)));
  EXPECT_EQ(listed(world.changes().movedBodies), std::vector{successor});
}

TEST(WorldChanges, Steps_ListTheBodiesTheyMoved_ButNotSleepers) {
  World world = recordingWorld();
  addGround(world);
  const BodyId sleeper = addBox(world, {.center = Vec2(-5, 0.5f)});
  ASSERT_GT(simulateUntilAsleep(world, 5), 0);
  const BodyId faller = addCircle(world, {.center = Vec2(5, 10)});
  world.clearChanges();
  const std::uint64_t revision = world.changes().revision;
  simulate(world, 0.25);
  EXPECT_EQ(listed(world.changes().movedBodies), std::vector{faller})
      << "the sleeping box is not listed";
  EXPECT_EQ(world.changes().revision, revision + std::uint64_t(stepsFor(0.25))) << "one per step";
  EXPECT_TRUE(world.isValid(sleeper));
}

TEST(WorldChanges, ABodyTheStepRemoves_IsEscapedAndDestroyedWithItsJoints) {
  WorldSettings settings;
  settings.inputLimits.escapeMargin = 5;
  World world = recordingWorld(settings);
  const BodyId rocket =
      addCircle(world, {.center = Vec2(5, 40), .ignoreGravity = true, .velocity = Vec2(0, 50)});
  const BodyId anchor = addCircle(world, {.center = Vec2(0, 0), .isStatic = true});
  const JointResult rope = world.createJoint(
      {rocket, anchor, Vec2(5, 40), Vec2(0, 0), false, RopeJointSettings{.maxLength = 1000}});
  ASSERT_TRUE(rope.ok()) << rope.error;
  world.clearChanges();
  simulateUntil(world, 1, [&] { return !world.isValid(rocket); });
  ASSERT_FALSE(world.isValid(rocket));
  EXPECT_EQ(listed(world.changes().escapedBodies), std::vector{rocket});
  EXPECT_EQ(listed(world.changes().destroyedBodies), std::vector{rocket});
  EXPECT_EQ(listed(world.changes().destroyedJoints), std::vector{rope.id});
}

TEST(WorldChanges, ClearAndImport_SayReplaced_AndListWhatCameAfter) {
  TwoBoxes scene;
  World& world = scene.world;
  const WorldState saved = world.exportState();
  ASSERT_TRUE(world.applyImpulse(scene.left, Vec2(1, 0)));
  std::uint64_t revision = world.changes().revision;

  world.clear();
  EXPECT_TRUE(world.changes().replaced);
  EXPECT_TRUE(world.changes().movedBodies.empty()) << "what came before the replacement is dropped";
  EXPECT_GT(world.changes().revision, revision);
  const BodyId ball = addCircle(world, {.center = Vec2(0, 5)});
  EXPECT_EQ(listed(world.changes().createdBodies), std::vector{ball});
  EXPECT_TRUE(world.changes().replaced);

  world.clearChanges();
  revision = world.changes().revision;
  ASSERT_TRUE(world.importState(saved));
  EXPECT_TRUE(world.changes().replaced);
  EXPECT_TRUE(world.changes().createdBodies.empty());
  EXPECT_GT(world.changes().revision, revision);
}

TEST(WorldChanges, AWorldAssigned_SaysReplacedAtALaterRevision) {
  TwoBoxes scene;
  World& world = scene.world;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(world.applyImpulse(scene.left, Vec2(1, 0)));
  const std::uint64_t revision = world.changes().revision;
  World other;
  addCircle(other, {.center = Vec2(0, 5)});
  ASSERT_LT(other.changes().revision, revision) << "the other world's own count is lower";
  world = std::move(other);
  EXPECT_EQ(world.bodyCount(), 1);
  EXPECT_TRUE(world.changes().replaced);
  EXPECT_TRUE(world.changes().createdBodies.empty());
  EXPECT_GT(world.changes().revision, revision) << "never goes back";
}

TEST(WorldChanges, ShiftingTheOrigin_MovesEveryBody) {
  TwoBoxes scene;
  World& world = scene.world;
  ASSERT_TRUE(world.shiftOrigin(Vec2d(100, 0)));
  EXPECT_TRUE(world.changes().originShifted);
  EXPECT_EQ(listed(world.changes().movedBodies), (std::vector{scene.left, scene.right}));
}

}  // namespace
}  // namespace impulse
