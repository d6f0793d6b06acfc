// Presets 18-21, each held to the outcome its text promises.

#include <gtest/gtest.h>

#include <cmath>

#include "impulse/scenes/presets.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using test::kDt;
using test::stateOf;

// A preset loaded into a world and stepped as the server steps it: its
// script, if it has one, runs before every step.
class PresetRun {
 public:
  PresetRun(World& world, int id) : world_(world), info_(*loadPreset(world, id)) {}

  // Steps for `seconds`; `observe` sees the world after every step.
  void run(double seconds, const std::function<void()>& observe = [] {}) {
    for (int i = 0; i < test::stepsFor(seconds); ++i) {
      if (info_.drive) info_.drive(world_, world_.simulatedTime(), kDt);
      world_.step(kDt);
      observe();
    }
  }

 private:
  World& world_;
  PresetInfo info_;
};

std::vector<BodyId> dynamicBodies(const World& world) {
  std::vector<BodyId> ids;
  for (BodyId id : world.bodyIds()) {
    const BodyDescription body = *world.bodyDescription(id);
    if (body.properties.isDynamic()) ids.push_back(id);
  }
  return ids;
}

// The heaviest dynamic body (the car's chassis, the tumbler's drum).
BodyId heaviest(const World& world) {
  BodyId best;
  Real mass = 0;
  for (BodyId id : dynamicBodies(world)) {
    if (world.bodyDescription(id)->mass.mass > mass) {
      mass = world.bodyDescription(id)->mass.mass;
      best = id;
    }
  }
  return best;
}

TEST(ShapePresets, TheCarDrivesOverTheChainHillsWithoutCatching) {
  World world;
  PresetRun preset(world, 18);
  const BodyId chassis = heaviest(world);
  const double startX = stateOf(world, chassis).position.x();
  double lowest = 1e9;
  preset.run(5, [&] { lowest = std::min(lowest, double(stateOf(world, chassis).position.y())); });
  // 3 m/s on the flat; the hills slow it somewhat.
  EXPECT_GT(stateOf(world, chassis).position.x() - startX, 8) << "the car drove on over the joins";
  EXPECT_GT(lowest, 1.3) << "the chassis never sank into the terrain";
  EXPECT_EQ(world.escapedBodies().size(), 0u);
}

TEST(ShapePresets, TheElevatorCarriesItsCratesUpAndDownAgain) {
  World world;
  PresetRun preset(world, 19);
  preset.run(4);
  const std::vector<BodyId> crates = dynamicBodies(world);
  ASSERT_EQ(crates.size(), 3u);
  for (BodyId crate : crates) {
    const BodyState top = stateOf(world, crate);
    EXPECT_GT(top.position.y(), 11.5) << "at the top after half a period";
    EXPECT_NEAR(top.position.x(), kSceneSize.x() / 2, 2.5) << "still on the platform";
  }
  // Four more seconds: back at the bottom (the platform's top at 1.75 m).
  preset.run(4);
  for (BodyId crate : crates) EXPECT_NEAR(stateOf(world, crate).position.y(), 2.25, 0.1);
}

TEST(ShapePresets, TheTumblerTurnsAndKeepsEveryPieceInside) {
  World world;
  PresetRun preset(world, 20);
  const BodyId drum = heaviest(world);
  const Vec2 centre = stateOf(world, drum).position;
  std::vector<BodyId> pieces = dynamicBodies(world);
  std::erase(pieces, drum);
  ASSERT_EQ(pieces.size(), 40u);
  preset.run(1);  // spin-up
  double turned = 0;
  Real previous = stateOf(world, drum).angle;
  preset.run(7, [&] {
    const Real angle = stateOf(world, drum).angle;
    turned += std::remainder(double(angle - previous), 2 * std::numbers::pi);
    previous = angle;
  });
  EXPECT_NEAR(turned, 0.6 * 7, 0.6 * 7 * 0.03) << "the motor holds 0.6 rad/s under the load, within 3 %";
  EXPECT_NEAR((stateOf(world, drum).position - centre).norm(), 0, 0.01) << "pinned at its centre";
  const Rot drumTurn = Rot::fromAngle(stateOf(world, drum).angle);
  for (BodyId piece : pieces) {
    const Vec2 local = drumTurn.applyInverse(stateOf(world, piece).position - centre);
    EXPECT_LT(std::max(std::abs(local.x()), std::abs(local.y())), 4.75) << "piece " << piece.value;
  }
}

TEST(ShapePresets, RagdollsTumbleDownTheStairsWithTheirJointsHeld) {
  World world;
  PresetRun preset(world, 21);
  double startHeight = 0;
  for (BodyId id : dynamicBodies(world)) startHeight = std::max(startHeight, double(stateOf(world, id).position.y()));
  double worstGap = 0;
  preset.run(8, [&] {
    // A revolute joint's anchors coincide: their distance is its gap.
    for (JointId id : world.jointIds()) worstGap = std::max(worstGap, double(world.jointState(id)->length));
  });
  double restingGap = 0;
  for (JointId id : world.jointIds()) restingGap = std::max(restingGap, double(world.jointState(id)->length));
  EXPECT_LT(worstGap, 0.15) << "no joint opened by more than 15 cm, hard landings included";
  EXPECT_LT(restingGap, 0.01) << "at the bottom, every joint closed again to within 1 cm";
  int descended = 0;
  const std::vector<BodyId> limbs = dynamicBodies(world);
  for (BodyId id : limbs) {
    const BodyState state = stateOf(world, id);
    ASSERT_TRUE(std::isfinite(state.position.x()) && std::isfinite(state.position.y()));
    if (state.position.y() < startHeight - 4) ++descended;
  }
  EXPECT_GT(descended, int(limbs.size()) / 2) << "most limbs went 4 m or more down the stairs";
  std::printf("ragdolls: worst joint gap %.4f m (at the end %.4f m), %d of %zu limbs 4 m down\n", worstGap,
              restingGap, descended, limbs.size());
}

}  // namespace
}  // namespace impulse
