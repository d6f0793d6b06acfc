// The tick clock of the running server follows the wall clock: the tick
// count never drifts by more than one tick from elapsed time / period.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

TEST(TickClock, TickCountFollowsTheWallClockWithinOneTick) {
  ServerProcess server(timedRates());
  Client client(localClient(server.port(), "clock", false));
  for (int sample = 0; sample < 6; ++sample) {
    std::this_thread::sleep_for(milliseconds(500));
    const auto pong = client.ping();
    const auto& stats = pong.stats();
    // Slots whose deadline has passed, against the wall time since start
    // (the Pong is answered inside a tick, so at most one slot behind).
    const double expected = double(stats.uptime_us()) / 1e6 * kTestTickHz;
    EXPECT_NEAR(double(stats.clock_ticks()), expected, 1.0) << "sample " << sample;
    EXPECT_EQ(stats.ticks_skipped(), 0u);
    // Running since start with nothing skipped: one world step per slot,
    // and the Ping was applied at the start of the current slot's tick,
    // before its step.
    EXPECT_EQ(pong.server_tick() + 1, stats.clock_ticks());
  }
}

}  // namespace
}  // namespace impulse::net_test
