// SetTimeScale on the running server: world steps per wall tick follow the
// scale (N clock ticks at scale s advance the world s N ticks of dt), the
// scale is carried by Welcome and snapshots, and a bad one is refused.
#include <cmath>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

// World ticks (of the unchanged dt) and clock ticks over about a second.
struct Advance {
  double worldTicks = 0;
  double clockTicks = 0;
};

Advance advanceOverASecond(Client& client) {
  const auto before = client.ping();
  std::this_thread::sleep_for(milliseconds(1000));
  const auto after = client.ping();
  return {double(after.server_tick() - before.server_tick()),
          double(after.stats().clock_ticks() - before.stats().clock_ticks())};
}

TEST(TimeScaleServer, WorldTicksPerClockTickFollowTheScale) {
  ServerProcess server(timedRates());
  Client client(localClient(server.port(), "time", false));
  for (double scale : {4.0, 0.25}) {
    SCOPED_TRACE(scale);
    ASSERT_TRUE(result(client.request(client::setTimeScale(scale))).ok());
    const Advance advance = advanceOverASecond(client);
    ASSERT_GT(advance.clockTicks, kTestTickHz / 2);
    // Both Pings are answered at the start of a tick, before its steps: the
    // world advanced s per clock tick, up to one tick's share at each end.
    EXPECT_NEAR(advance.worldTicks, scale * advance.clockTicks, std::max(1.0, scale));
  }
  EXPECT_EQ(client.ping().stats().scaled_steps_dropped(), 0u) << "a small world fits 4x";
}

TEST(TimeScaleServer, WelcomeAndSnapshotsCarryTheScale) {
  ServerProcess server(timedRates());
  Client admin(localClient(server.port(), "admin"));
  EXPECT_EQ(admin.welcome().time_scale(), 1);
  ASSERT_TRUE(result(admin.request(client::setTimeScale(0.5))).ok());
  const auto snapshot = admin.awaitSnapshot(milliseconds(2000));
  ASSERT_TRUE(snapshot);
  EXPECT_EQ(snapshot->time_scale(), 0.5);
  Client late(localClient(server.port(), "late"));
  EXPECT_EQ(late.welcome().time_scale(), 0.5);
  EXPECT_EQ(late.lastSnapshot()->time_scale(), 0.5) << "the full snapshot too";
}

TEST(TimeScaleServer, OutOfRangeScaleIsRefusedAndChangesNothing) {
  ServerProcess server(timedRates());
  Client client(localClient(server.port(), "bad", false));
  for (double scale : {0.001, 17.0, std::nan("")}) {
    const v1::CommandResult refused = result(client.request(client::setTimeScale(scale)));
    EXPECT_FALSE(refused.ok());
    EXPECT_TRUE(mentions(refused.error(), "time-scale: time scale")) << refused.error();
    EXPECT_TRUE(mentions(refused.error(), "[0.01, 16]")) << refused.error();
  }
  const Advance advance = advanceOverASecond(client);
  EXPECT_NEAR(advance.worldTicks, advance.clockTicks, 1) << "still 1x";
}

}  // namespace
}  // namespace impulse::net_test
