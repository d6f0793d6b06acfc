// Scenes within the loading world's limits (issue 30): slot counts bounded
// by the body limit before anything is built, id counters that cannot wrap,
// and a world that always reloads its own save.
#include <gtest/gtest.h>

#include "impulse/client/commands.h"
#include "impulse/server/commands.h"
#include "impulse/server/simulation.h"
#include "impulse/wire/scene_convert.h"

namespace impulse::server {
namespace {

Simulation sandbox() { return Simulation(SimulationSettings{.maxBodies = 1000, .preset = 0}); }

v1::Scene savedScene(const Simulation& simulation) {
  v1::Scene scene;
  EXPECT_TRUE(scene.ParseFromString(wire::saveScene(simulation.world())));
  return scene;
}

// The load's error, "" when it loaded.
std::string loadError(Simulation& simulation, const v1::Scene& scene) {
  return simulation.loadScene(scene.SerializeAsString()).error;
}

TEST(SceneLimits, SlotCountsPastTheBodyLimitAreRefusedBeforeAnythingIsBuilt) {
  Simulation simulation = sandbox();
  const v1::Scene saved = savedScene(simulation);
  const auto limits = wire::sceneSlotLimits(1000);
  EXPECT_EQ(limits.bodies, 1000u);
  EXPECT_EQ(limits.shapes, 4000u);
  EXPECT_EQ(limits.contacts, 64000u);
  EXPECT_EQ(limits.joints, 4000u);

  v1::Scene freeBodies = saved;
  while (freeBodies.bodies_size() < 1001) freeBodies.add_bodies();
  EXPECT_EQ(loadError(simulation, freeBodies),
            "scene refused: 1001 body slots (live or free), over the 1000 this world allows for "
            "its body limit");
  v1::Scene freeContacts = saved;
  while (freeContacts.contacts_size() < 64001) freeContacts.add_contacts();
  EXPECT_NE(loadError(simulation, freeContacts).find("64001 contact slots"), std::string::npos);
  v1::Scene freeShapes = saved;
  while (freeShapes.shapes_size() < 4001) freeShapes.add_shapes();
  EXPECT_NE(loadError(simulation, freeShapes).find("4001 shape slots"), std::string::npos);
  v1::Scene freeJoints = saved;
  while (freeJoints.joints_size() < 4001) freeJoints.add_joints();
  EXPECT_NE(loadError(simulation, freeJoints).find("4001 joint slots"), std::string::npos);
  v1::Scene treeNodes = saved;
  while (treeNodes.movable_tree().nodes_size() < 16017)
    treeNodes.mutable_movable_tree()->add_nodes();
  EXPECT_NE(loadError(simulation, treeNodes).find("16017 broad-phase tree nodes"),
            std::string::npos);
  // The world is untouched by every refusal.
  EXPECT_EQ(savedScene(simulation).SerializeAsString(), saved.SerializeAsString());
}

TEST(SceneLimits, CountersThatWouldWrapOrReuseAnIdAreRefused) {
  Simulation simulation = sandbox();
  ASSERT_TRUE(simulation.addField(GravitationDef{0.1}).ok());
  const v1::Scene saved = savedScene(simulation);

  v1::Scene fieldIds = saved;
  fieldIds.set_next_field_id(0xFFFFFFFFu);
  EXPECT_EQ(loadError(simulation, fieldIds),
            "scene refused: next_field_id 4294967295 is past 2147483648 (field ids would wrap)");
  v1::Scene creation = saved;
  creation.set_next_creation_order(~std::uint64_t(0));
  EXPECT_NE(
      loadError(simulation, creation).find("next_creation_order 18446744073709551615 is past"),
      std::string::npos);
  v1::Scene behind = saved;
  behind.set_next_field_id(1);
  EXPECT_EQ(loadError(simulation, behind),
            "scene refused: field 0: id 1 must be 1 to next_field_id - 1 (1 - 1)");
  v1::Scene reused = saved;
  reused.set_next_creation_order(2);
  EXPECT_NE(loadError(simulation, reused).find("is not below next_creation_order 2"),
            std::string::npos);
}

// Fields added and removed, joints, bodies removed (free slots): the save
// loads back into the world that made it, and into a fresh one.
TEST(SceneLimits, AWorldReloadsItsOwnSave) {
  Simulation simulation = sandbox();
  for (int i = 0; i < 20; ++i) {
    const auto field = simulation.addField(GravitationDef{0.1});
    ASSERT_TRUE(field.ok()) << field.error;
    if (i % 2 == 0) {
      ASSERT_TRUE(simulation.removeField(field.id));
    }
  }
  std::vector<BodyId> bodies;
  for (int i = 0; i < 30; ++i) {
    const auto body = simulation.createCircle(Vec2(2 + 0.6 * i, 5), Real(0.25), {});
    ASSERT_TRUE(body.ok()) << body.error;
    bodies.push_back(body.id);
  }
  for (int i = 0; i + 1 < 30; i += 3) {
    JointDef def;
    def.bodyA = bodies[std::size_t(i)];
    def.bodyB = bodies[std::size_t(i + 1)];
    def.anchorA = Vec2(2 + 0.6 * i, 5);
    def.anchorB = Vec2(2 + 0.6 * (i + 1), 5);
    ASSERT_TRUE(simulation.createJoint(def).ok());
  }
  for (int i = 0; i < 30; i += 4) ASSERT_TRUE(simulation.removeBody(bodies[std::size_t(i)]));
  for (int i = 0; i < 30; ++i) simulation.step();

  const std::string scene = wire::saveScene(simulation.world());
  const InputResult again = simulation.loadScene(scene);
  EXPECT_TRUE(again.ok()) << again.error;
  EXPECT_EQ(wire::saveScene(simulation.world()), scene);
  Simulation fresh = sandbox();
  const InputResult elsewhere = fresh.loadScene(scene);
  EXPECT_TRUE(elsewhere.ok()) << elsewhere.error;
}

}  // namespace
}  // namespace impulse::server
