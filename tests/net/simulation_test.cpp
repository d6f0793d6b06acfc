// The Simulation is the only way to change a served world: every change it
// accepts is recorded for the next snapshot and moves the version that names
// the world's state; a refused change records nothing.
#include "impulse/server/simulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "impulse/wire/scene_convert.h"

namespace impulse::server {
namespace {

Simulation pausedSandbox() {
  SimulationSettings settings;
  settings.paused = true;
  return Simulation(settings);
}

bool contains(const std::vector<BodyId>& ids, BodyId id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

TEST(Simulation, EveryAcceptedChangeIsRecordedAndMovesTheVersion) {
  Simulation sim = pausedSandbox();
  sim.takeChanges();
  auto version = sim.version();
  auto changedOnce = [&] {
    const bool moved = sim.version() > version;
    version = sim.version();
    return moved;
  };

  const auto ball = sim.createCircle(Vec2(5, 5), 0.5f, {});
  ASSERT_TRUE(ball.ok()) << ball.error;
  EXPECT_TRUE(changedOnce());
  EXPECT_TRUE(sim.applyImpulse(ball.id, Vec2(1, 0), std::nullopt));
  EXPECT_TRUE(changedOnce());
  EXPECT_TRUE(sim.setGravity(Vec2(0, -1)));
  EXPECT_TRUE(changedOnce());
  sim.setPaused(false);
  EXPECT_TRUE(changedOnce());
  sim.step();
  EXPECT_TRUE(changedOnce());
  auto changes = sim.takeChanges();
  changes.normalise();
  EXPECT_TRUE(contains(changes.addedIds(), ball.id));
  EXPECT_TRUE(contains(changes.changedIds(), ball.id));

  EXPECT_TRUE(sim.removeBody(ball.id));
  EXPECT_TRUE(changedOnce());
  EXPECT_TRUE(contains(sim.takeChanges().removedIds(), ball.id));
  sim.clear();
  EXPECT_TRUE(changedOnce());
  EXPECT_TRUE(sim.takeChanges().wasReplaced());
  EXPECT_TRUE(sim.loadPreset(2, Material::Solid));
  EXPECT_TRUE(changedOnce());
  EXPECT_EQ(sim.preset().id, 2);
  EXPECT_TRUE(sim.takeChanges().wasReplaced());
}

TEST(Simulation, RefusedChangesRecordNothing) {
  Simulation sim = pausedSandbox();
  sim.takeChanges();
  const auto version = sim.version();
  EXPECT_FALSE(sim.createCircle(Vec2(5, 5), -1.0f, {}).ok());
  EXPECT_FALSE(sim.removeBody(BodyId{9999}));
  EXPECT_FALSE(sim.applyImpulse(BodyId{9999}, Vec2(1, 0), std::nullopt));
  EXPECT_FALSE(sim.setGravity(Vec2(0, -1e6f)));
  EXPECT_FALSE(sim.loadPreset(kPresetCount, Material::Solid));
  EXPECT_EQ(sim.version(), version);
  auto changes = sim.takeChanges();
  changes.normalise();
  EXPECT_FALSE(changes.wasReplaced());
  EXPECT_TRUE(changes.addedIds().empty());
  EXPECT_TRUE(changes.removedIds().empty());
  EXPECT_TRUE(changes.changedIds().empty());
}

bool hasJoint(const std::vector<JointId>& ids, JointId id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

TEST(Simulation, JointsAreRecordedWhenAddedRemovedOrTakenWithTheirBodies) {
  Simulation sim = pausedSandbox();
  const auto a = sim.createCircle(Vec2(5, 5), 0.5f, {});
  const auto b = sim.createCircle(Vec2(7, 5), 0.5f, {});
  ASSERT_TRUE(a.ok() && b.ok());
  sim.takeChanges();

  JointDef def;
  def.bodyA = a.id;
  def.bodyB = b.id;
  def.anchorA = Vec2(5, 5);
  def.anchorB = Vec2(7, 5);
  const auto rod = sim.createJoint(def);
  ASSERT_TRUE(rod.ok()) << rod.error;
  const auto spring = sim.createJoint(def);
  ASSERT_TRUE(spring.ok()) << spring.error;
  EXPECT_TRUE(hasJoint(sim.takeChanges().addedJointIds(), rod.id));

  const auto version = sim.version();
  EXPECT_TRUE(sim.removeJoint(rod.id));
  EXPECT_GT(sim.version(), version);
  EXPECT_FALSE(sim.removeJoint(rod.id));
  EXPECT_TRUE(hasJoint(sim.takeChanges().removedJointIds(), rod.id));

  // Refused: nothing recorded.
  def.bodyB = a.id;
  EXPECT_FALSE(sim.createJoint(def).ok());
  EXPECT_TRUE(sim.takeChanges().addedJointIds().empty());

  ASSERT_TRUE(sim.removeBody(b.id));
  EXPECT_TRUE(hasJoint(sim.takeChanges().removedJointIds(), spring.id));
}

// The world records its edits; the Simulation's changes read them in
// snapshot terms: a new descriptor is `added`, a new joint descriptor
// `joints_added`.
TEST(Simulation, RedescribedBodiesAndUpdatedJointsGoOutAsAdded) {
  Simulation sim = pausedSandbox();
  const auto ball = sim.createCircle(Vec2(5, 5), 0.5f, {});
  ASSERT_TRUE(ball.ok()) << ball.error;
  JointDef def;
  def.bodyA = ball.id;
  def.anchorA = Vec2(5, 5);
  def.anchorB = Vec2(5, 5);
  def.settings = MouseJointSettings{};
  const auto pull = sim.createJoint(def);
  ASSERT_TRUE(pull.ok()) << pull.error;
  sim.takeChanges();

  ASSERT_TRUE(sim.setMaterial(ball.id, Material::Rubber));
  JointUpdate update;
  update.target = Vec2(6, 6);
  ASSERT_TRUE(sim.updateJoint(pull.id, update));
  auto changes = sim.takeChanges();
  changes.normalise();
  EXPECT_EQ(changes.addedIds(), std::vector{ball.id});
  EXPECT_EQ(changes.changedIds(), std::vector{ball.id}) << "a new descriptor comes with the state";
  EXPECT_EQ(changes.addedJointIds(), std::vector{pull.id});
  EXPECT_TRUE(sim.takeChanges().addedIds().empty()) << "taken once";
}

// A scene replaces the world object whole: the version still only moves
// forward, so nothing cached for an earlier version is taken for it.
TEST(Simulation, ALoadedSceneIsReplacedAndTheVersionMovesOn) {
  Simulation sim = pausedSandbox();
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(sim.createCircle(Vec2(float(i) - 10, 5), 0.2f, {}).ok());
  const std::string scene = wire::saveScene(World());
  const auto version = sim.version();
  const auto hash = sim.stateHash();
  ASSERT_TRUE(sim.loadScene(scene));
  EXPECT_GT(sim.version(), version);
  EXPECT_TRUE(sim.takeChanges().wasReplaced());
  EXPECT_NE(sim.stateHash(), hash);
  EXPECT_EQ(sim.stateHash(), sim.world().stateHash());
}

}  // namespace
}  // namespace impulse::server
