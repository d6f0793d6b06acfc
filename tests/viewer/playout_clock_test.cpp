#include "playout_clock.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>

namespace impulse::viewer {
namespace {

constexpr double kInterval = 1.0 / 30.0;

// Feeds snapshots produced every interval, each arriving 2 ms plus a delay
// from `jitter` later, in order as TCP delivers, and renders at 120 Hz in
// between, recording the smallest and largest step of the rendered time.
struct PlayoutRun {
  double minStep = 1e9;
  double maxStep = 0;
  double lastRender = 0;
  double lastServer = 0;
};

template <class Jitter>
PlayoutRun simulate(PlayoutClock& clock, double seconds, Jitter jitter, double start = 0) {
  PlayoutRun run;
  double nextSnapshot = start;
  std::optional<double> previous;
  std::vector<std::pair<double, double>> inFlight;  // arrival, server time
  for (double now = start; now < start + seconds; now += 1.0 / 120) {
    while (nextSnapshot <= now) {
      inFlight.emplace_back(nextSnapshot + 0.002 + jitter(), nextSnapshot);
      nextSnapshot += kInterval;
    }
    // TCP delivers in order: a late one holds back those behind it.
    double release = 0;
    std::erase_if(inFlight, [&](const std::pair<double, double>& p) {
      release = std::max(release, p.first);
      if (release > now) return false;
      clock.onSnapshot(p.second, now);
      run.lastServer = p.second;
      return true;
    });
    const double rendered = clock.renderTime(now);
    if (!clock.started()) continue;
    if (previous) {
      const double step = rendered - *previous;
      run.minStep = std::min(run.minStep, step);
      run.maxStep = std::max(run.maxStep, step);
    }
    previous = rendered;
    run.lastRender = rendered;
  }
  return run;
}

TEST(PlayoutClock, SteadyStream_DelayIsThreeIntervals_AndTimeAdvancesSmoothly) {
  PlayoutClock clock({kInterval});
  const PlayoutRun run = simulate(clock, 5, [] { return 0.0; });
  EXPECT_NEAR(clock.delay(), 3 * kInterval, 1e-9);
  EXPECT_NEAR(run.minStep, 1.0 / 120, 1e-3);
  EXPECT_NEAR(run.maxStep, 1.0 / 120, 1e-3);
  // Rendered time trails the newest snapshot by about the delay minus latency.
  EXPECT_GT(run.lastServer - run.lastRender, kInterval);
  EXPECT_LT(run.lastServer - run.lastRender, 3 * kInterval + 0.01);
}

TEST(PlayoutClock, Jitter_GrowsTheDelay_AndRenderedTimeStaysMonotonic) {
  PlayoutClock clock({kInterval});
  std::mt19937 random(7);
  std::uniform_real_distribution<double> late(0, 0.120);
  const PlayoutRun run = simulate(clock, 6, [&] { return late(random); });
  EXPECT_GT(clock.delay(), 0.120);
  EXPECT_LE(clock.delay(), 12 * kInterval);
  EXPECT_GT(run.minStep, 0.0);
  // Rendered time never runs ahead of what has arrived by more than one
  // interval (the buffer's extrapolation limit) once settled.
  EXPECT_LT(run.lastRender, run.lastServer + kInterval);
}

TEST(PlayoutClock, Stall_DoesNotFreezeOrJumpTheClock) {
  PlayoutClock clock({kInterval});
  simulate(clock, 3, [] { return 0.0; });
  // A 250 ms stall every two seconds: the clock keeps running at about real
  // speed (steering is bounded), it never stops or runs backwards.
  int count = 0;
  const PlayoutRun run = simulate(
      clock, 4, [&] { return (count++ % 60) == 0 ? 0.25 : 0.0; }, 3);
  EXPECT_GT(run.minStep, (1.0 / 120) * 0.9);
  EXPECT_LT(run.maxStep, (1.0 / 120) * 1.1);
  EXPECT_GT(clock.delay(), 0.25);
}

TEST(PlayoutClock, Paused_ShowsTheLatestSnapshotAtOnce) {
  PlayoutClock clock({kInterval});
  simulate(clock, 2, [] { return 0.0; });
  clock.onSnapshot(2.5, 2.6, true);
  EXPECT_DOUBLE_EQ(clock.renderTime(2.7), 2.5);
  clock.onSnapshot(2.5 + 1.0 / 60, 9.0, true);  // a Step much later
  EXPECT_DOUBLE_EQ(clock.renderTime(9.0), 2.5 + 1.0 / 60);
  // Running again: timing restarts from the new arrivals, no huge delay.
  clock.onSnapshot(2.6, 10.0);
  EXPECT_NEAR(clock.renderTime(10.0), 2.6 - 3 * kInterval, 1e-9);
  EXPECT_NEAR(clock.delay(), 3 * kInterval, 1e-9);
}

TEST(PlayoutClock, Reset_ForgetsTiming) {
  PlayoutClock clock({kInterval});
  simulate(clock, 1, [] { return 0.05; });
  clock.reset();
  EXPECT_FALSE(clock.started());
  EXPECT_DOUBLE_EQ(clock.renderTime(5), 0);
  clock.onSnapshot(100, 5);
  EXPECT_NEAR(clock.renderTime(5), 100 - 3 * kInterval, 1e-9);
}

TEST(PlayoutClock, LargeError_Jumps) {
  PlayoutClock clock({kInterval});
  clock.onSnapshot(0, 0);
  clock.renderTime(0);
  // The server's time jumps ahead by seconds (it was stopped, then resumed
  // without a paused snapshot reaching us): the clock follows at once.
  for (int i = 0; i < 60; ++i) clock.onSnapshot(10 + i * kInterval, 1 + i * kInterval);
  const double rendered = clock.renderTime(1 + 59 * kInterval);
  EXPECT_GT(rendered, 10);
}

}  // namespace
}  // namespace impulse::viewer
