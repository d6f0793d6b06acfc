// Fair service and access without sockets: the round-robin queue, the rate
// limiter's arithmetic, token admission and player ownership.
#include <gtest/gtest.h>

#include "impulse/client/commands.h"
#include "impulse/server/access.h"
#include "impulse/server/commands.h"
#include "impulse/server/fair_queue.h"
#include "impulse/server/rate_limiter.h"
#include "impulse/wire/scene_convert.h"

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

constexpr std::uint32_t kPlayer = 7;
constexpr std::uint32_t kAdmin = 1;

// Why the player may not run `message` (its command's row resolved as the room does).
std::string refusalFor(const Ownership& ownership, const v1::ClientMessage& message, std::uint32_t client) {
  const CommandRow* row = findCommand(message);
  EXPECT_NE(row, nullptr) << "a message with a command";
  return row == nullptr ? "no command" : ownership.playerRefusal(*row, message, client);
}

// Applies `message` for `client` as the room does: refused when the player
// may not, else applied and its outcome recorded. The reply.
v1::ServerMessage applyAs(Simulation& simulation, Ownership& ownership,
                          const v1::ClientMessage& message, std::uint32_t client) {
  const CommandRow& row = *findCommand(message);
  if (client == kPlayer) {
    if (std::string refusal = ownership.playerRefusal(row, message, client); !refusal.empty()) {
      v1::ServerMessage reply;
      reply.mutable_command_result()->set_error(refusal);
      return reply;
    }
  }
  auto outcome = applyCommand(simulation, row, message, CommandLimits{});
  ownership.recordOutcome(row, message, outcome.reply, client, simulation);
  return outcome.reply;
}

std::string errorOf(const v1::ServerMessage& reply) { return reply.command_result().error(); }

TEST(Ownership, PlayersMayPushAndRemoveWhatTheySpawned) {
  Simulation simulation(SimulationSettings{.preset = 0});
  Ownership ownership;
  const auto spawned = applyAs(simulation, ownership, client::spawnCircle({5, 5}, 0.5), kPlayer);
  const std::uint32_t body = spawned.command_result().body_id();
  ASSERT_TRUE(spawned.command_result().ok()) << errorOf(spawned);

  EXPECT_TRUE(refusalFor(ownership, client::applyImpulse(body, {1, 0}), kPlayer).empty());
  EXPECT_NE(refusalFor(ownership, client::applyImpulse(body, {1, 0}), 8)
                .find("body " + std::to_string(body) + " was not created by this client"),
            std::string::npos);
  // Body 1 is the preset's floor: the admin's, not the player's.
  EXPECT_FALSE(refusalFor(ownership, client::removeBody(1), kPlayer).empty());
  EXPECT_NE(
      refusalFor(ownership, client::clearWorld(), kPlayer).find("refused for the player role"),
      std::string::npos);
  EXPECT_TRUE(refusalFor(ownership, client::queryBody(body), 8).empty());
  // Removed: no longer the player's to push.
  ASSERT_TRUE(
      applyAs(simulation, ownership, client::removeBody(body), kPlayer).command_result().ok());
  EXPECT_FALSE(refusalFor(ownership, client::applyImpulse(body, {1, 0}), kPlayer).empty());
}

// Ids start over with each world, so a player who created body (or joint)
// N must not act on whatever body N the next world has: clear, preset and
// scene loads all forget owners.
TEST(Ownership, EveryWorldReplacementForgetsOwners) {
  const std::string scene = wire::saveScene(Simulation(SimulationSettings{.preset = 0}).world());
  const std::vector<v1::ClientMessage> replacements = {client::clearWorld(), client::loadPreset(0),
                                                       client::loadScene(scene)};
  for (const auto& replacement : replacements) {
    SCOPED_TRACE(std::string(commandName(replacement)));
    Simulation simulation(SimulationSettings{.preset = 0});
    Ownership ownership;
    const auto spawned = applyAs(simulation, ownership, client::spawnCircle({5, 5}, 0.5), kPlayer);
    const std::uint32_t body = spawned.command_result().body_id();
    const auto pinned = applyAs(simulation, ownership,
                                client::distanceJoint({body, 0, {5, 5}, {5, 6}}, {}), kPlayer);
    const std::uint32_t joint = pinned.command_result().joint_id();
    ASSERT_TRUE(pinned.command_result().ok()) << errorOf(pinned);
    ASSERT_TRUE(refusalFor(ownership, client::applyImpulse(body, {1, 0}), kPlayer).empty());
    ASSERT_TRUE(refusalFor(ownership, client::removeJoint(joint), kPlayer).empty());

    ASSERT_TRUE(applyAs(simulation, ownership, replacement, kAdmin).command_result().ok());
    // The admin's new bodies and joint take the ids the player had.
    for (int i = 0; i < 6; ++i)
      applyAs(simulation, ownership, client::spawnCircle({3.0 + i, 3}, 0.4), kAdmin);
    ASSERT_TRUE(simulation.world().isValid(BodyId{body}));
    const auto adminJoint = applyAs(simulation, ownership,
                                    client::distanceJoint({body, 0, {5, 3}, {5, 4}}, {}), kAdmin);
    ASSERT_EQ(adminJoint.command_result().joint_id(), joint);

    EXPECT_NE(errorOf(applyAs(simulation, ownership, client::applyImpulse(body, {1, 0}), kPlayer))
                  .find("body " + std::to_string(body) + " was not created by this client"),
              std::string::npos);
    EXPECT_NE(errorOf(applyAs(simulation, ownership, client::removeJoint(joint), kPlayer))
                  .find("joint " + std::to_string(joint) + " was not created by this client"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace impulse::server
