// A long Step (issue 12) runs in pieces across ticks: while it runs, the tick
// clock keeps its rate, a newcomer is welcomed and another client's Ping is
// answered, and the Step still ends exactly N ticks on with its reply and
// snapshot; the stepping client's later commands wait for it.
#include <cstdio>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

TEST(LongStep, RunsInPiecesWhileTheServerServesEveryoneElse) {
  ServerProcess server({"--paused"});
  Client heavy(localClient(server.port(), "heavy", false));
  std::vector<v1::ClientMessage> rising = circleGrid(true);
  rising.resize(kSanitized ? 200 : 2000);
  requestAll(heavy, rising);
  const auto skippedBefore = heavy.ping().stats().ticks_skipped();

  const auto start = Clock::now();
  const auto stepId = heavy.send(client::step(600));
  const auto queryId = heavy.send(client::queryBody(1));
  std::this_thread::sleep_for(milliseconds(50));
  const auto joinStart = Clock::now();
  Client light(localClient(server.port(), "light", false));
  const auto pong = light.ping(milliseconds(30000));
  const double joinAndPingMs = millisecondsSince(joinStart);

  const auto stepped = heavy.awaitReply(stepId, milliseconds(120000));
  const double stepMs = millisecondsSince(start);
  ASSERT_TRUE(stepped.has_value());
  EXPECT_TRUE(result(*stepped).ok()) << result(*stepped).error();
  EXPECT_EQ(result(*stepped).tick(), 600u);
  // The query was queued behind the Step and sees the world after it.
  ASSERT_TRUE(heavy.awaitReply(queryId, milliseconds(10000)).has_value());

  std::printf("[ measure ] step 600 ticks: %.0f ms; join + ping meanwhile: %.0f ms at tick %llu\n",
              stepMs, joinAndPingMs, static_cast<unsigned long long>(pong.server_tick()));
  EXPECT_LT(pong.server_tick(), 600u) << "the ping waited for the whole Step";
  EXPECT_LT(joinAndPingMs * 2, stepMs);
  // The clock ran on time meanwhile: no burst of skipped ticks.
  EXPECT_LE(light.ping().stats().ticks_skipped() - skippedBefore, 4u);
}

}  // namespace
}  // namespace impulse::net_test
