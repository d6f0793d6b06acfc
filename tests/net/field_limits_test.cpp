// Force fields within a room's budget (issue 30: 3 000 AddField were
// accepted and one gravitation field over 9 990 bodies cost ~300 ms a step):
// a count limit and a cost budget in body interactions per step, checked on
// AddField, on every spawn under fields and on LoadScene, refused by name.
#include <gtest/gtest.h>

#include "impulse/server/simulation.h"
#include "impulse/wire/scene_convert.h"

namespace impulse::server {
namespace {

FanDef fan() {
  FanDef def;
  def.position = Vec2(5, 1);
  def.direction = Vec2(0, 1);
  return def;
}

// Circles `first` to `last` - 1 of a grid of small circles in rows of 50,
// 0.4 m apart, none touching.
void spawnGrid(Simulation& simulation, int first, int last) {
  for (int i = first; i < last; ++i) {
    const auto body =
        simulation.createCircle(Vec2(1 + 0.4 * (i % 50), 1 + 0.4 * (i / 50)), Real(0.1), {});
    ASSERT_TRUE(body.ok()) << "body " << i << ": " << body.error;
  }
}

TEST(FieldLimits, AFieldPastTheCountLimitIsRefused) {
  Simulation simulation(SimulationSettings{.preset = 0});
  for (int i = 0; i < 64; ++i) ASSERT_TRUE(simulation.addField(fan()).ok()) << i;
  const FieldResult refused = simulation.addField(fan());
  EXPECT_EQ(refused.error, "65 force fields, over the room's limit of 64 (--max-fields)");
  EXPECT_EQ(simulation.world().fieldCount(), 64);
}

TEST(FieldLimits, GravitationPastTheCostBudgetIsRefused_AndSoAreBodiesPastIt) {
  Simulation simulation(SimulationSettings{.preset = 0});
  simulation.clear();
  spawnGrid(simulation, 0, 1500);
  EXPECT_EQ(simulation.addField(GravitationDef{0.1}).error,
            "a gravitation field over 1500 bodies brings the room's fields to 1124250 body "
            "interactions per step, over the room's budget of 1000000 (--max-field-cost): fewer "
            "bodies or fewer fields");

  simulation.clear();
  spawnGrid(simulation, 0, 1400);
  ASSERT_TRUE(simulation.addField(GravitationDef{0.1}).ok());
  // n (n - 1) / 2 stays within 1 000 000 up to 1414 bodies.
  spawnGrid(simulation, 1400, 1414);
  const CreateResult refused = simulation.createCircle(Vec2(10, 20), Real(0.1), {});
  EXPECT_EQ(refused.error,
            "with 1415 bodies the room's force fields would cost 1000405 body interactions per "
            "step, over the room's budget of 1000000 (--max-field-cost): remove a field first");
  EXPECT_EQ(simulation.world().bodyCount(), 1414);
}

TEST(FieldLimits, ASceneWhoseFieldsBreakTheBudgetIsRefused) {
  Simulation generous(
      SimulationSettings{.preset = 0, .fieldLimits = {.maxFields = 64, .maxCost = 1u << 30}});
  generous.clear();
  spawnGrid(generous, 0, 1500);
  ASSERT_TRUE(generous.addField(GravitationDef{0.1}).ok());
  const std::string scene = wire::saveScene(generous.world());

  Simulation simulation(SimulationSettings{.preset = 0});
  EXPECT_EQ(simulation.loadScene(scene).error,
            "scene refused: its force fields over 1500 bodies cost 1124250 body interactions per "
            "step, over the room's budget of 1000000 (--max-field-cost)");
  EXPECT_EQ(simulation.world().bodyCount(), 3);  // the sandbox, untouched
}

}  // namespace
}  // namespace impulse::server
