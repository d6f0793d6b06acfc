// SetTimeScale (docs/protocol.md, "Time") at the Simulation: N wall ticks at
// scale s run floor(s N) world steps of the unchanged tick dt, so simulated
// time advances by s N dt within one step, whatever s.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "impulse/server/simulation.h"

namespace impulse::server {
namespace {

Simulation runningSandbox() { return Simulation(SimulationSettings{}); }

// Simulated seconds after `ticks` wall ticks at `scale`, stepping as the
// room does.
double simulatedAfter(Simulation& sim, double scale, int ticks) {
  EXPECT_TRUE(sim.setTimeScale(scale));
  const double start = sim.simTime();
  for (int i = 0; i < ticks; ++i) {
    for (int due = sim.stepsDueThisTick(); due > 0; --due) sim.step();
  }
  return sim.simTime() - start;
}

TEST(TimeScale, NTicksAtScaleSAdvanceSimulatedTimeBySNDt) {
  for (double scale : {0.01, 0.1, 0.25, 1.0, 2.5, 4.0, 16.0}) {
    SCOPED_TRACE(scale);
    Simulation sim = runningSandbox();
    const int ticks = 600;
    const double dt = 1 / sim.tickHz();
    const double expected = scale * ticks * dt;
    // Every scale here times 600 is a whole number of steps: exact, up to
    // the sum of 600 * 16 doubles (1e-9 s).
    EXPECT_NEAR(simulatedAfter(sim, scale, ticks), expected, 1e-9);
  }
}

TEST(TimeScale, FractionalStepsAreOwedNotLost) {
  // At 0.3x, 10 ticks owe 3 steps; 7 more ticks (2.1 steps) owe 2 more,
  // with the 0.1 kept for later: never more than one step behind s N dt.
  Simulation sim = runningSandbox();
  const double dt = 1 / sim.tickHz();
  ASSERT_TRUE(sim.setTimeScale(0.3));
  int ticks = 0;
  for (int round = 0; round < 50; ++round) {
    for (int i = 0; i < 7; ++i, ++ticks) {
      for (int due = sim.stepsDueThisTick(); due > 0; --due) sim.step();
    }
    const double ideal = 0.3 * ticks * dt;
    EXPECT_LE(sim.simTime(), ideal + 1e-9);
    EXPECT_GT(sim.simTime(), ideal - dt);
  }
}

TEST(TimeScale, TheStepSizeStaysTheTicks) {
  // Accuracy does not change with speed: a ball dropped for 1 s of
  // simulated time lands in the same state at 0.25x, 1x and 4x, bit for bit.
  auto dropped = [](double scale) {
    Simulation sim = runningSandbox();
    const auto ball = sim.createCircle(Vec2(10, 15), 0.5f, {});
    EXPECT_TRUE(ball.ok()) << ball.error;
    simulatedAfter(sim, scale, int(std::lround(sim.tickHz() / scale)));
    return *sim.world().bodyState(ball.id);
  };
  const BodyState normal = dropped(1);
  for (double scale : {0.25, 4.0}) {
    const BodyState scaled = dropped(scale);
    EXPECT_EQ(scaled.position, normal.position) << scale;
    EXPECT_EQ(scaled.linearVelocity, normal.linearVelocity) << scale;
  }
}

TEST(TimeScale, OutOfRangeScalesAreRefusedNamingTheRange) {
  Simulation sim = runningSandbox();
  ASSERT_TRUE(sim.setTimeScale(2));
  const auto version = sim.version();
  for (double scale : {0.0, 0.005, 16.5, -1.0, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
    const InputResult result = sim.setTimeScale(scale);
    EXPECT_FALSE(result);
    EXPECT_NE(result.error.find("[0.01, 16]"), std::string::npos) << result.error;
  }
  EXPECT_EQ(sim.timeScale(), 2) << "unchanged";
  EXPECT_EQ(sim.version(), version);
  EXPECT_EQ(sim.meta().timeScale, 2);
}

}  // namespace
}  // namespace impulse::server
