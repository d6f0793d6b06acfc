// Slow subscribers cost the server nothing it cannot bound: the tick rate
// holds, memory stays flat, a lagging reader skips to a full snapshot and a
// client that reads nothing is dropped after the stall timeout.
#include <algorithm>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
using Clock = std::chrono::steady_clock;

void spawnRisingGrid(Client& driver) {
  std::vector<v1::ClientMessage> commands = {client::setPaused(true)};
  const auto grid = circleGrid(true);
  commands.insert(commands.end(), grid.begin(), grid.end());
  commands.push_back(client::setPaused(false));
  for (const auto& reply : requestAll(driver, commands)) ASSERT_TRUE(result(reply).ok());
}

TEST(SlowClients, NeverReadingSubscriberDoesNotSlowTheTickAndIsDropped) {
  auto args = timedRates();
  args.insert(args.end(), {"--stall-timeout", "3"});
  ServerProcess server(args);
  Client driver(localClient(server.port(), "driver", false));
  spawnRisingGrid(driver);
  ASSERT_EQ(driver.ping().stats().awake_bodies(), 2000u);

  // Subscribes, then never reads a byte.
  RawConnection silent(server.port(), 4096);
  silent.sendHello(1, true);

  const auto start = Clock::now();
  const auto first = driver.ping();
  long baselineKb = 0, peakKb = 0;
  std::uint32_t clientsEarly = 0;
  v1::Pong last = first;
  while (Clock::now() - start < milliseconds(4500)) {
    std::this_thread::sleep_for(milliseconds(200));
    last = driver.ping();
    const auto elapsed = Clock::now() - start;
    const long rss = server.residentKb();
    // The first second fills the kernel's socket buffers; after that the
    // server's own memory must stay flat.
    if (elapsed < milliseconds(1000)) {
      baselineKb = std::max(baselineKb, rss);
    } else {
      peakKb = std::max(peakKb, rss);
    }
    if (elapsed < milliseconds(2500)) clientsEarly = last.stats().clients();
  }
  ASSERT_GT(baselineKb, 0);

  // The tick rate held: ticks advanced with the wall clock (within 3 %) and
  // none was skipped; the mean tick stayed well inside its period.
  const double seconds = double(last.stats().uptime_us() - first.stats().uptime_us()) / 1e6;
  const double ticks = double(last.server_tick() - first.server_tick());
  EXPECT_NEAR(ticks / seconds, kTestTickHz, kTestTickHz * 0.03);
  EXPECT_EQ(last.stats().ticks_skipped(), 0u);
  EXPECT_LT(last.stats().mean_tick_ms(), 0.75 * 1000 / kTestTickHz);
  EXPECT_EQ(last.stats().awake_bodies(), 2000u);

  // Snapshots for the silent client were skipped, not queued: memory flat.
  EXPECT_GT(last.stats().snapshots_skipped(), 10u);
  EXPECT_LT(peakKb - baselineKb, 16 * 1024) << "baseline " << baselineKb << " KiB";

  // Subscribed at first, dropped once it had accepted nothing for 3 s.
  EXPECT_EQ(clientsEarly, 2u);
  EXPECT_EQ(last.stats().clients(), 1u);
  EXPECT_NE(server.log().find("stalled"), std::string::npos);
  std::cout << "[ measure ] tick " << last.stats().mean_tick_ms() << " ms mean, "
            << last.stats().max_tick_ms() << " ms max; rss " << baselineKb << " -> " << peakKb
            << " KiB\n";
}

TEST(SlowClients, LaggingReaderSkipsToAFullSnapshotAndStaysExact) {
  ServerProcess server({"--stall-timeout", "5"});
  Client driver(localClient(server.port(), "driver", false));
  spawnRisingGrid(driver);

  auto slowOptions = localClient(server.port(), "slow");
  slowOptions.receiveBufferBytes = 8192;
  Client slow(slowOptions);
  Client fast(localClient(server.port(), "fast"));
  int slowFull = 0;
  slow.onSnapshot([&](const v1::Snapshot& s, std::size_t) { slowFull += s.full() ? 1 : 0; });

  // The slow client stops reading for 1.5 s (under the stall timeout) while
  // the fast one keeps up.
  const auto start = Clock::now();
  while (Clock::now() - start < milliseconds(1500)) fast.poll(milliseconds(20));
  EXPECT_GT(driver.ping().stats().snapshots_skipped(), 0u);
  // Catching up: the skipped snapshots are replaced by a full one.
  slow.poll(milliseconds(500));
  EXPECT_GE(slowFull, 1);

  // Freeze the world; after a round trip both mirrors hold the same exact
  // state (a broken delta chain would have thrown on an unknown body or
  // left a stale state here).
  ASSERT_TRUE(result(driver.request(client::setPaused(true))).ok());
  slow.ping();
  fast.ping();
  ASSERT_EQ(slow.mirror().bodies().size(), 2003u);
  ASSERT_EQ(fast.mirror().bodies().size(), 2003u);
  EXPECT_EQ(slow.mirror().tick(), fast.mirror().tick());
  for (const auto& [id, body] : fast.mirror().bodies()) {
    const auto* other = slow.mirror().find(BodyId{id});
    ASSERT_NE(other, nullptr);
    ASSERT_EQ(other->state.position, body.state.position) << id;
    ASSERT_EQ(other->state.linearVelocity, body.state.linearVelocity) << id;
  }
}

// How much the flooded server may grow. AddressSanitizer keeps freed blocks
// in quarantine (and pads every block), so its builds get four times the
// room; a leak or an unbounded queue still shows against either bound.
#if defined(__SANITIZE_ADDRESS__)
constexpr long kFloodGrowthKb = 64 * 1024;
#else
constexpr long kFloodGrowthKb = 16 * 1024;
#endif

TEST(SlowClients, ClientThatFloodsCommandsWithoutReadingIsBounded) {
  // No rate limit to speak of: the rate would slow the flooder down to a
  // trickle (HostileClients), and this is about the reply cap.
  ServerProcess server({"--stall-timeout", "3", "--max-commands-per-second", "1000000"});
  Client observer(localClient(server.port(), "observer", false));
  const long before = server.residentKb();
  RawConnection flooder(server.port(), 4096);
  flooder.sendHello();
  // 200k pings (~2 MB): the server reads at most its command cap ahead and
  // drops the client once its unread replies pass their cap.
  std::string burst;
  for (int i = 0; i < 2000; ++i) burst += wire::encodeFrame(client::ping(i));
  const auto start = Clock::now();
  while (Clock::now() - start < milliseconds(3000)) {
    flooder.send(burst);
    if (observer.ping().stats().clients() == 1) break;
  }
  EXPECT_EQ(observer.ping().stats().clients(), 1u);
  EXPECT_LT(server.residentKb() - before, kFloodGrowthKb);
  const auto pong = observer.ping();
  EXPECT_EQ(pong.stats().ticks_skipped(), 0u);
}

}  // namespace
}  // namespace impulse::net_test
