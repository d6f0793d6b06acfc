// How far the viewer's picture lags the server under a bandwidth budget.
// A grid of circles drifts at one constant velocity (no gravity, no
// contacts), so a drawn body's distance from where the server has it,
// divided by the speed, is the age of what the viewer shows of it. The
// truth is an observer's mirror with no budget and the whole room; each
// viewer frame compares every drawn body with it. Prints the figures
// (docs/networked-play.md, "The viewer's picture under a budget").
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

constexpr int kColumns = 20;
constexpr int kBodies = 400;
constexpr double kSpacing = 0.8;
constexpr double kSpeed = 0.5;  // m/s, along x
constexpr double kBudget = 32000;
constexpr auto kWarmUp = std::chrono::seconds(1);
constexpr auto kMeasured = std::chrono::seconds(5);

struct Lag {
  std::vector<double> metres;  ///< one per drawn body per frame
  double quantile(double q) const {
    std::vector<double> sorted = metres;
    std::sort(sorted.begin(), sorted.end());
    return sorted[std::min(sorted.size() - 1, std::size_t(q * double(sorted.size())))];
  }
  double maximum() const { return *std::max_element(metres.begin(), metres.end()); }
};

// The drifting grid, in the preset scene so the viewer's view (its area of
// interest) holds every body for the whole run.
void spawnDriftingGrid(client::Client& maker) {
  std::vector<std::uint64_t> requests;
  for (int i = 0; i < kBodies; ++i) {
    const client::Point at{2 + kSpacing * (i % kColumns), 1 + kSpacing * (i / kColumns)};
    requests.push_back(maker.send(client::spawnCircle(
        at, 0.1, {.ignoreGravity = true, .velocityX = kSpeed, .velocityY = 0})));
  }
  for (const std::uint64_t id : requests) {
    const auto reply = maker.awaitReply(id, std::chrono::seconds(20));
    ASSERT_TRUE(reply && reply->command_result().ok());
  }
}

// Every drawn body's distance from the observer's newest state of it, each
// frame of kMeasured after kWarmUp.
Lag measureLag(std::uint16_t port, client::Client& observer, std::optional<double> budget) {
  ViewerHarness viewer(port, [&](viewer::ViewerOptions& options) { options.budget = budget; });
  EXPECT_TRUE(observeUntil(viewer, observer, [&] {
    return viewer.app().world().bodies().size() == std::size_t(kBodies);
  }));
  const auto start = std::chrono::steady_clock::now();
  Lag lag;
  observeUntil(
      viewer, observer,
      [&] {
        const auto since = std::chrono::steady_clock::now() - start;
        if (since < kWarmUp) return false;
        for (const viewer::DrawnBody& drawn : viewer.app().world().bodies()) {
          const client::MirrorBody* truth = observer.mirror().find(BodyId{drawn.state.id});
          if (truth != nullptr)
            lag.metres.push_back((truth->state.position - drawn.state.position).norm());
        }
        return since > kWarmUp + kMeasured;
      },
      kWarmUp + kMeasured + std::chrono::seconds(5));
  return lag;
}

void report(const char* stream, const Lag& lag) {
  const auto ms = [](double metres) { return metres / kSpeed * 1000; };
  std::printf(
      "%-22s %8zu samples  lag median %.3f m (%.0f ms)  p99 %.3f m (%.0f ms)  max %.3f m (%.0f "
      "ms)\n",
      stream, lag.metres.size(), lag.quantile(0.5), ms(lag.quantile(0.5)), lag.quantile(0.99),
      ms(lag.quantile(0.99)), lag.maximum(), ms(lag.maximum()));
}

TEST(ViewerUnderBudget, ThePictureLagsByThePlayoutDelayWithout_AndWithinTheStatedWaitWithABudget) {
  net_test::ServerProcess server;
  client::Client observer(observerOptions(server.port()));
  ASSERT_TRUE(observer.request(client::clearWorld()).command_result().ok());
  ASSERT_NO_FATAL_FAILURE(spawnDriftingGrid(observer));

  const Lag free = measureLag(server.port(), observer, std::nullopt);
  const Lag budgeted = measureLag(server.port(), observer, kBudget);
  std::printf(
      "%d bodies drifting at %.1f m/s; lag = distance from the server's state (unbudgeted "
      "observer)\n",
      kBodies, kSpeed);
  report("no budget", free);
  report("budget 32000 B/s", budgeted);
  ASSERT_FALSE(free.metres.empty());
  ASSERT_FALSE(budgeted.metres.empty());

  // Without a budget: about the playout delay (100 ms), never a second.
  EXPECT_LT(free.quantile(0.99) / kSpeed, 0.3);
  EXPECT_LT(free.maximum() / kSpeed, 1.0);
  // With one: behind, but no state waits past the stated bound (4 x 45 bytes
  // x bodies / budget) by more than the playout delay and a snapshot.
  const double statedWait = 4 * 45.0 * kBodies / kBudget;
  EXPECT_GT(budgeted.quantile(0.5), free.quantile(0.5));
  EXPECT_LT(budgeted.maximum() / kSpeed, statedWait + 0.5);
}

}  // namespace
}  // namespace impulse::viewer_test
