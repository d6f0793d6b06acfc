// Cost of serving 2000 bodies: tick time and snapshot bytes per body while
// they fall and pile up (awake), then once they all sleep. Prints the
// measurements (quoted in docs/measurements.md) and checks their bounds.
#include <cstdio>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
using Clock = std::chrono::steady_clock;

struct Sample {
  double bytesPerBody = 0;
  double snapshotBytes = 0;
  double meanTickMs = 0;
  double maxTickMs = 0;
  double stepMs = 0;
  int snapshots = 0;
};

TEST(SnapshotCost, TwoThousandBodiesAwakeThenAsleep) {
  ServerProcess server(timedRates());
  Client driver(localClient(server.port(), "driver", false));
  std::vector<v1::ClientMessage> commands = {client::setPaused(true)};
  const auto grid = circleGrid(false);
  commands.insert(commands.end(), grid.begin(), grid.end());
  requestAll(driver, commands);

  Client viewer(localClient(server.port(), "viewer"));
  ASSERT_EQ(viewer.mirror().bodies().size(), 2003u);
  Sample awake, asleep;
  Sample* current = &awake;
  bool counting = false;
  viewer.onSnapshot([&](const v1::Snapshot& s, std::size_t bytes) {
    if (!counting || s.full()) return;
    current->snapshotBytes += double(bytes);
    ++current->snapshots;
  });
  ASSERT_TRUE(result(driver.request(client::setPaused(false))).ok());

  // Awake: the first second of the fall (every body moves).
  counting = true;
  viewer.poll(milliseconds(1000));
  auto pong = driver.ping();
  EXPECT_EQ(pong.stats().awake_bodies(), 2000u);
  awake.meanTickMs = pong.stats().mean_tick_ms();
  awake.maxTickMs = pong.stats().max_tick_ms();
  awake.stepMs = pong.stats().mean_step_ms();
  counting = false;

  // Asleep: wait for the pile to settle (the engine's sleep), then measure.
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (driver.ping().stats().awake_bodies() > 0 && Clock::now() < deadline) {
    viewer.poll(milliseconds(200));
  }
  ASSERT_EQ(driver.ping().stats().awake_bodies(), 0u) << "the pile never fell asleep";
  viewer.poll(milliseconds(1100));  // a full second of tick times asleep
  current = &asleep;
  counting = true;
  viewer.poll(milliseconds(1000));
  pong = driver.ping();
  asleep.meanTickMs = pong.stats().mean_tick_ms();
  asleep.maxTickMs = pong.stats().max_tick_ms();
  asleep.stepMs = pong.stats().mean_step_ms();

  for (Sample* s : {&awake, &asleep}) {
    ASSERT_GT(s->snapshots, 5);
    s->snapshotBytes /= s->snapshots;
    s->bytesPerBody = s->snapshotBytes / 2000;
  }
  std::printf(
      "[ measure ] 2000 bodies awake:  tick %.3f ms mean (%.3f max), step %.3f ms, "
      "%.0f bytes/snapshot = %.2f bytes/body\n"
      "[ measure ] 2000 bodies asleep: tick %.3f ms mean (%.3f max), step %.3f ms, "
      "%.0f bytes/snapshot = %.4f bytes/body\n",
      awake.meanTickMs, awake.maxTickMs, awake.stepMs, awake.snapshotBytes, awake.bytesPerBody,
      asleep.meanTickMs, asleep.maxTickMs, asleep.stepMs, asleep.snapshotBytes,
      asleep.bytesPerBody);

  // Awake: every body's state in each delta, a few dozen bytes each.
  EXPECT_GT(awake.bytesPerBody, 15);
  EXPECT_LT(awake.bytesPerBody, 80);
  // Asleep: deltas carry no body at all, and the tick is nearly free.
  EXPECT_LT(asleep.snapshotBytes, 64);
  if (!kSanitized) {
    EXPECT_LT(awake.meanTickMs, 1000 / kTestTickHz);
    EXPECT_LT(asleep.meanTickMs, awake.meanTickMs / 5);
  }
}

}  // namespace
}  // namespace impulse::net_test
