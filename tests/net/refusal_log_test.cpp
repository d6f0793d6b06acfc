// A refused command over the protocol: answered in the user's words (the
// CLI's command and argument names, no protocol field path), and logged by
// the server on a line naming the room and the client, at a bounded rate.
#include <chrono>
#include <cmath>
#include <thread>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

std::size_t countOf(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

client::ConnectOptions builderInArena(std::uint16_t port) {
  auto options = localClient(port, "builder", false);
  options.room = "arena";
  return options;
}

TEST(RefusalLog, ABadCommandIsAnsweredAndLoggedInTheUsersWords_WithRoomAndClient) {
  ServerProcess server({"--paused"});
  Client client(builderInArena(server.port()));
  const double nan = std::nan("");
  const std::string error = result(client.request(client::spawnCircle({nan, 2}, 0.5))).error();
  EXPECT_EQ(error, "circle X is not a finite number");
  const std::string scale = result(client.request(client::setTimeScale(100))).error();
  EXPECT_TRUE(scale.starts_with("time-scale: time scale 100 must be in")) << scale;
  const std::string rope =
      result(client.request(client::ropeJoint({1, 2, {nan, 0}, {1, 0}, false}, {}))).error();
  EXPECT_EQ(rope, "rope anchor a x is not a finite number");

  const std::string label = "room arena, client " + std::to_string(client.welcome().client_id()) +
                            " 'builder' (127.0.0.1:";
  const std::string log = server.log();
  EXPECT_TRUE(mentions(log, label)) << log;
  EXPECT_TRUE(mentions(log, ") said hello")) << log;
  EXPECT_TRUE(mentions(log, ") refused: circle X is not a finite number")) << log;
  EXPECT_TRUE(mentions(log, ") refused: " + scale)) << log;
  EXPECT_TRUE(mentions(log, ") refused: " + rope)) << log;
  for (const char* wireName : {"spawn_circle", "set_time_scale", "create_joint"}) {
    EXPECT_FALSE(mentions(log, wireName)) << wireName << " in\n" << log;
  }
}

TEST(RefusalLog, AFloodOfBadCommandsLogsABurstThenSaysHowManyWereLeftOut) {
  ServerProcess server({"--paused"});
  Client client(builderInArena(server.port()));
  std::vector<v1::ClientMessage> bad(200, client::removeBody(4242));
  for (const auto& reply : requestAll(client, bad)) EXPECT_EQ(result(reply).error(), "remove: unknown body id 4242");
  const std::size_t logged = countOf(server.log(), "refused: remove: unknown body id 4242");
  // A burst of ten, and one a second while the flood lasts.
  EXPECT_GE(logged, 10u);
  EXPECT_LE(logged, 15u);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  EXPECT_FALSE(result(client.request(client::removeBody(4243))).ok());
  EXPECT_TRUE(mentions(server.log(), "refused: remove: unknown body id 4243 (and " +
                                         std::to_string(200 - logged) + " refusals before it not logged)"))
      << server.log();
}

}  // namespace
}  // namespace impulse::net_test
