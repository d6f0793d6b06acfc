// Bandwidth budgets (SetBandwidthBudget): a subscriber under a budget gets
// at most that many snapshot bytes a second, the most important states
// first, and every changed body reaches it in time; bad budgets are refused.
#include <cmath>
#include <map>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

TEST(BandwidthBudget, BytesStayUnderTheBudgetAndEveryBodyComes) {
  ServerProcess server(timedRates());
  Client driver(localClient(server.port(), "driver", false));
  ASSERT_TRUE(result(driver.request(client::clearWorld())).ok());
  requestAll(driver, circleGrid(true));  // 2000 bodies rising together
  Client watcher(localClient(server.port(), "watcher"));
  constexpr double kBudget = 40000;
  ASSERT_TRUE(result(watcher.request(client::setBandwidthBudget(kBudget))).ok());

  // The full snapshot that starts the budgeted stream is paid for first (up
  // to a second's bytes), then deltas flow at the budget.
  std::size_t bytes = 0;
  std::uint64_t oldestWithheld = 0;
  std::uint32_t withheld = 0;
  bool counting = false;
  watcher.onSnapshot([&](const v1::Snapshot& snapshot, std::size_t frameBytes) {
    if (!counting) return;
    bytes += frameBytes;
    oldestWithheld = std::max(oldestWithheld, snapshot.oldest_withheld_ticks());
    withheld = std::max(withheld, snapshot.states_withheld());
  });
  const auto pollFor = [&](milliseconds span) {
    const auto end = std::chrono::steady_clock::now() + span;
    while (std::chrono::steady_clock::now() < end) watcher.poll(milliseconds(10));
  };
  pollFor(milliseconds(3000));
  std::map<std::uint32_t, double> heightAtStart;
  for (const auto& [id, body] : watcher.mirror().bodies()) heightAtStart[id] = body.state.position.y();
  counting = true;
  const auto start = std::chrono::steady_clock::now();
  pollFor(milliseconds(3000));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  EXPECT_LE(double(bytes) / seconds, kBudget * 1.1) << bytes << " bytes in " << seconds << " s";
  EXPECT_GT(double(bytes) / seconds, kBudget * 0.5) << "the budget is used";
  EXPECT_GT(withheld, 0u) << "2000 moving bodies need more than the budget";
  // 2000 states of about 45 bytes at 40 kB/s: a turn every ~2.3 s, up to
  // twice that for the least important; the longest wait stays near it.
  EXPECT_LT(double(oldestWithheld) / kTestTickHz, 6.0);
  int moved = 0;
  for (const auto& [id, body] : watcher.mirror().bodies()) moved += body.state.position.y() > heightAtStart[id] + 0.5;
  EXPECT_EQ(moved, 2000) << "every body's state came within the three seconds";
}

TEST(BandwidthBudget, ZeroAndOutOfRangeBudgetsAreRefused) {
  ServerProcess server({"--paused"});
  Client watcher(localClient(server.port(), "watcher"));
  for (const double rate : {0.0, -5.0, 999.0, 1e12, std::nan("")}) {
    const v1::CommandResult refused = result(watcher.request(client::setBandwidthBudget(rate)));
    EXPECT_FALSE(refused.ok()) << rate;
    EXPECT_TRUE(mentions(refused.error(), "budget BYTES_PER_SECOND")) << refused.error();
    EXPECT_TRUE(mentions(refused.error(), "must be in [1000, 125000000]")) << refused.error();
  }
  EXPECT_TRUE(result(watcher.request(client::setBandwidthBudget(std::nullopt))).ok()) << "no budget";
}

}  // namespace
}  // namespace impulse::net_test
