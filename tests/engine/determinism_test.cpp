// Determinism: the same scene and commands give bit-identical states.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "impulse/scenes/stress.h"
#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

struct RunRecord {
  std::vector<std::uint64_t> hashes;  // after every step
  int asleepAtStep = -1;              // first step after which nothing is awake
};

// A 10-row pyramid hit from the side by a fast heavy ball, with a seeded
// random pile of circles and boxes dropped on the far side, between two
// walls that keep the debris on the ground: chaotic enough that any
// difference in operation order shows up in the bits.
RunRecord runChaoticScene(int maxSteps, SimdWidth width = SimdWidth::Best) {
  WorldSettings settings;
  settings.simdWidth = width;
  World world(settings);
  buildPyramid(world, 10);
  for (Real x : {Real(-19), Real(19)}) {
    addBox(world,
           {.center = Vec2(x, 9), .halfWidth = Real(0.5), .halfHeight = 9, .isStatic = true});
  }
  addCircle(world, {.center = Vec2(-14, Real(1.5)),
                    .radius = Real(0.6),
                    .material = Material::Metal,
                    .velocity = Vec2(25, 2)});
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> x(6, 12);
  std::uniform_real_distribution<Real> y(2, 10);
  std::uniform_real_distribution<Real> size(Real(0.2), Real(0.5));
  for (int i = 0; i < 40; ++i) {
    Vec2 centre(x(random), y(random));
    if (i % 2 == 0) {
      addCircle(world, {.center = centre, .radius = size(random), .material = Material::Rubber});
    } else {
      addBox(world, {.center = centre,
                     .halfWidth = size(random),
                     .halfHeight = size(random),
                     .material = Material::Wood});
    }
  }
  RunRecord record;
  for (int i = 1; i <= maxSteps; ++i) {
    world.step(kDt);
    record.hashes.push_back(world.stateHash());
    if (record.asleepAtStep < 0 && world.awakeBodyCount() == 0) record.asleepAtStep = i;
  }
  return record;
}

// The first step after which two runs' hashes differ (a run that ends
// first differs there), or 0 when they agree at every step.
int firstDivergingStep(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b) {
  const auto [atA, atB] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return atA == a.end() && atB == b.end() ? 0 : int(atA - a.begin()) + 1;
}

TEST(Determinism, ChaoticSceneRunTwice_GivesIdenticalHashesAndSleepStep) {
  // 20 s of simulated time: long enough for the scene to come to rest.
  const int steps = stepsFor(20);
  RunRecord first = runChaoticScene(steps);
  RunRecord second = runChaoticScene(steps);
  ASSERT_EQ(firstDivergingStep(first.hashes, second.hashes), 0) << "states diverge after that step";
  EXPECT_GT(first.asleepAtStep, 0) << "the scene comes to rest within 20 s";
  EXPECT_EQ(first.asleepAtStep, second.asleepAtStep);
  // The hit really disturbed the scene: states changed after the first step.
  EXPECT_NE(first.hashes.front(), first.hashes.back());
}

// The contact solver runs four lanes on SSE2 or eight on AVX2 (when the CPU
// has it); the bits must not depend on which.
TEST(Determinism, Sse2AndWidestSimd_GiveIdenticalHashes) {
  const int steps = stepsFor(10);
  RunRecord sse2 = runChaoticScene(steps, SimdWidth::Sse2);
  RunRecord widest = runChaoticScene(steps, SimdWidth::Best);
  EXPECT_EQ(firstDivergingStep(sse2.hashes, widest.hashes), 0) << "widths diverge after that step";
}

// A step whose colours hold four contacts or fewer runs the four-lane
// kernels whatever the width asked for; a column grown box by box from one
// to twelve (two colours, of up to six contacts) crosses that line mid-run.
std::vector<std::uint64_t> growingColumnHashes(SimdWidth width) {
  WorldSettings settings = sleepless();
  settings.simdWidth = width;
  World world(settings);
  addGround(world);
  std::vector<std::uint64_t> hashes;
  for (int box = 0; box < 12; ++box) {
    addBox(world, {.center = Vec2(Real(0.02) * Real(box % 3), Real(0.5) + Real(box) * Real(1.05))});
    for (int i = 0; i < 20; ++i) {
      world.step(kDt);
      hashes.push_back(world.stateHash());
    }
  }
  return hashes;
}

TEST(Determinism, ColumnGrowingPastFourContactsAColour_GivesEveryWidthsBits) {
  const std::vector<std::uint64_t> sse2 = growingColumnHashes(SimdWidth::Sse2);
  const std::vector<std::uint64_t> widest = growingColumnHashes(SimdWidth::Best);
  EXPECT_EQ(firstDivergingStep(sse2, widest), 0) << "widths diverge after that step";
}

TEST(Determinism, SameCommandsAtSameTicks_GiveIdenticalStates) {
  auto run = [] {
    World world;
    std::vector<BodyId> tower = buildTower(world, 6, Real(0.05));
    for (int i = 1; i <= stepsFor(4); ++i) {
      // Commands at fixed ticks, as the server applies them.
      if (i == 30) world.applyImpulse(tower[4], Vec2(400, 0), Vec2(0, Real(4.8)));
      if (i == 90) world.destroyBody(tower[1]);
      if (i == 120) addCircle(world, {.center = Vec2(2, 8), .radius = Real(0.4)});
      world.step(kDt);
    }
    return world.stateHash();
  };
  EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace impulse
