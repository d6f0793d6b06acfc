// Commands stamped with the tick they are meant for (ClientMessage.for_tick):
// applied at that tick when it is still to come, at once (and said so) when
// it is past, refused beyond the server's --max-input-delay.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

v1::ClientMessage circleAt(double x) { return client::spawnCircle({x, 5}, 0.3, {}); }

// The server's tick once it has passed `ticks`, however slowly the server
// starts (a loaded machine, a sanitizer build): a fixed sleep had found it at
// tick 10 under AddressSanitizer.
std::uint64_t tickPast(Client& client, std::uint64_t ticks) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  std::uint64_t now = client.ping().server_tick();
  while (now <= ticks && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(milliseconds(50));
    now = client.ping().server_tick();
  }
  return now;
}

TEST(StampedCommands, TwoClientsStampingOneTickMeetAtThatTick) {
  ServerProcess server(timedRates());
  Client first(localClient(server.port(), "first", false));
  Client second(localClient(server.port(), "second"));
  EXPECT_EQ(first.welcome().max_input_delay_ticks(), 30u) << "the default bound";
  const std::uint64_t target = first.ping().server_tick() + 20;
  const auto firstId = first.send(client::forTick(circleAt(2), target));
  const auto secondId = second.send(client::forTick(circleAt(6), target));
  const auto firstReply = first.awaitReply(firstId, milliseconds(5000));
  const auto secondReply = second.awaitReply(secondId, milliseconds(5000));
  ASSERT_TRUE(firstReply && secondReply);
  for (const auto* reply : {&*firstReply, &*secondReply}) {
    EXPECT_TRUE(result(*reply).ok()) << result(*reply).error();
    EXPECT_EQ(result(*reply).tick(), target) << "applied before the step from the stamped tick";
    EXPECT_FALSE(result(*reply).late());
  }
  // The snapshot that brings them is the first past the stamped tick, and
  // brings both.
  const std::uint32_t firstBody = result(*firstReply).body_id();
  const std::uint32_t secondBody = result(*secondReply).body_id();
  for (int i = 0; i < 60 && !second.mirror().find(BodyId{firstBody}); ++i) {
    ASSERT_TRUE(second.awaitSnapshot(milliseconds(2000)));
  }
  EXPECT_TRUE(second.mirror().find(BodyId{secondBody}));
  EXPECT_GT(second.mirror().tick(), target);
  EXPECT_LE(second.mirror().tick(), target + 2) << "snapshots come every second tick";
}

TEST(StampedCommands, LateStampIsAppliedAtOnceAndTheReplySaysSo) {
  ServerProcess server(timedRates());
  Client client(localClient(server.port(), "late", false));
  const std::uint64_t now = tickPast(client, 10);
  ASSERT_GT(now, 10u);
  const std::uint32_t bodiesBefore = client.ping().stats().bodies();
  const v1::CommandResult applied = result(client.request(client::forTick(circleAt(3), now - 10)));
  EXPECT_TRUE(applied.ok()) << applied.error();
  EXPECT_TRUE(applied.late());
  EXPECT_GE(applied.tick(), now);
  EXPECT_EQ(client.ping().stats().bodies(), bodiesBefore + 1);
  const v1::CommandResult unstamped = result(client.request(circleAt(5)));
  EXPECT_FALSE(unstamped.late()) << "an unstamped command is never late";
}

TEST(StampedCommands, StampsBeyondTheBoundAreRefusedAndChangeNothing) {
  ServerProcess server([] {
    auto args = timedRates();
    args.insert(args.end(), {"--max-input-delay", "5"});
    return args;
  }());
  Client client(localClient(server.port(), "bad", false));
  EXPECT_EQ(client.welcome().max_input_delay_ticks(), 5u);
  const std::uint64_t now = tickPast(client, 10);
  ASSERT_GT(now, 10u);
  const std::uint32_t bodiesBefore = client.ping().stats().bodies();
  for (const std::uint64_t stamp : {now + 1000, std::uint64_t(0), ~std::uint64_t(0)}) {
    SCOPED_TRACE(stamp);
    const v1::CommandResult refused = result(client.request(client::forTick(circleAt(3), stamp)));
    EXPECT_FALSE(refused.ok());
    EXPECT_TRUE(mentions(refused.error(), "for_tick " + std::to_string(stamp))) << refused.error();
    EXPECT_TRUE(mentions(refused.error(), "at most 5")) << refused.error();
    EXPECT_TRUE(mentions(refused.error(), "--max-input-delay")) << refused.error();
  }
  EXPECT_EQ(client.ping().stats().bodies(), bodiesBefore);
  EXPECT_EQ(client.ping().stats().commands_queued(), 0u) << "nothing left waiting";
}

}  // namespace
}  // namespace impulse::net_test
