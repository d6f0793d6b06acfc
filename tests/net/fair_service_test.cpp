// Fair service and access without sockets: the round-robin queue, the rate
// limiter's arithmetic, token admission and player ownership.
#include <gtest/gtest.h>

#include "impulse/client/commands.h"
#include "impulse/server/access.h"
#include "impulse/server/fair_queue.h"
#include "impulse/server/rate_limiter.h"

namespace impulse::server {
namespace {

v1::ClientMessage request(std::uint64_t id) {
  auto message = client::ping(0);
  message.set_request_id(id);
  return message;
}

TEST(FairQueue, ServesClientsInTurn_EachInItsOwnOrder) {
  FairQueue queue;
  for (std::uint64_t i = 1; i <= 4; ++i) queue.push(7, request(100 + i), 10);  // a backlog
  queue.push(3, request(1), 10);
  queue.push(9, request(2), 10);
  std::vector<std::pair<std::uint32_t, std::uint64_t>> order;
  while (auto next = queue.pop()) order.emplace_back(next->client, next->message.request_id());
  const std::vector<std::pair<std::uint32_t, std::uint64_t>> expected = {
      {3, 1}, {7, 101}, {9, 2}, {7, 102}, {7, 103}, {7, 104}};
  EXPECT_EQ(order, expected);
  EXPECT_TRUE(queue.empty());
}

TEST(FairQueue, TurnCarriesOverBetweenPops_AndADroppedClientLosesItsQueue) {
  FairQueue queue;
  queue.push(1, request(1), 10);
  queue.push(1, request(2), 10);
  queue.push(2, request(3), 10);
  EXPECT_EQ(queue.pop()->client, 1u);
  queue.push(1, request(4), 10);
  EXPECT_EQ(queue.pop()->client, 2u);  // client 2's turn, though 1 has more
  EXPECT_EQ(queue.dropClient(1), 2u);
  EXPECT_EQ(queue.dropClient(1), 0u);
  EXPECT_TRUE(queue.empty());
  EXPECT_FALSE(queue.pop().has_value());
}

TEST(RateLimiter, AllowsTheBurst_ThenRefillsAtTheRate) {
  const auto start = Clock::now();
  RateLimiter limiter(10, 20, start);
  int allowed = 0;
  for (int i = 0; i < 50; ++i) allowed += limiter.take(start) ? 1 : 0;
  EXPECT_EQ(allowed, 20);
  // Half a second refills five tokens (10 per second), no more.
  const auto later = start + std::chrono::milliseconds(500);
  allowed = 0;
  for (int i = 0; i < 50; ++i) allowed += limiter.take(later) ? 1 : 0;
  EXPECT_EQ(allowed, 5);
  // A long pause refills to the burst only.
  const auto much = later + std::chrono::seconds(60);
  allowed = 0;
  for (int i = 0; i < 50; ++i) allowed += limiter.take(much) ? 1 : 0;
  EXPECT_EQ(allowed, 20);
}

TEST(Access, TokensDecideAdmissionAndRole) {
  EXPECT_TRUE(admit({}, "").admin);                     // no tokens: everyone admin
  EXPECT_TRUE(admit({"t", ""}, "t").admin);             // token only: everyone admin
  EXPECT_FALSE(admit({"t", ""}, "x").error.empty());    // wrong token
  EXPECT_NE(admit({"t", ""}, "").error.find("requires a token"), std::string::npos);
  EXPECT_TRUE(admit({"t", "a"}, "a").admin);            // the admin token
  const Admission player = admit({"t", "a"}, "t");
  EXPECT_TRUE(player.error.empty());
  EXPECT_FALSE(player.admin);
  EXPECT_TRUE(admit({"", "a"}, "anything").error.empty());  // no token: anyone joins, as player
  EXPECT_FALSE(admit({"", "a"}, "anything").admin);
}

TEST(Access, LoopbackAddresses) {
  EXPECT_TRUE(isLoopbackAddress("127.0.0.1"));
  EXPECT_TRUE(isLoopbackAddress("127.1.2.3"));
  EXPECT_TRUE(isLoopbackAddress("::1"));
  EXPECT_TRUE(isLoopbackAddress("localhost"));
  EXPECT_FALSE(isLoopbackAddress("0.0.0.0"));
  EXPECT_FALSE(isLoopbackAddress("::"));
  EXPECT_FALSE(isLoopbackAddress("10.0.0.1"));
}

TEST(Ownership, PlayersMayPushAndRemoveWhatTheySpawned) {
  World world;
  Ownership ownership;
  const auto spawn = client::spawnCircle({5, 5}, 0.5);
  ASSERT_TRUE(ownership.playerRefusal(spawn, 7).empty());
  const CreateResult body = world.createCircle(Vec2(5, 5), 0.5f);
  v1::ServerMessage reply;
  reply.mutable_command_result()->set_ok(true);
  reply.mutable_command_result()->set_body_id(body.id.value);
  ownership.recordOutcome(spawn, reply, 7, world);

  EXPECT_TRUE(ownership.playerRefusal(client::applyImpulse(body.id.value, {1, 0}), 7).empty());
  EXPECT_NE(ownership.playerRefusal(client::applyImpulse(body.id.value, {1, 0}), 8)
                .find("was not created by this client"),
            std::string::npos);
  EXPECT_NE(ownership.playerRefusal(client::clearWorld(), 7).find("refused for the player role"),
            std::string::npos);
  EXPECT_TRUE(ownership.playerRefusal(client::queryBody(body.id.value), 8).empty());
  // Removed: no longer the player's to push.
  const auto remove = client::removeBody(body.id.value);
  ownership.recordOutcome(remove, reply, 7, world);
  EXPECT_FALSE(ownership.playerRefusal(client::applyImpulse(body.id.value, {1, 0}), 7).empty());
}

}  // namespace
}  // namespace impulse::server
