#pragma once
// Shared helpers of the integration tests.

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "impulse/client/client.h"
#include "impulse/client/commands.h"
#include "server_process.h"

namespace impulse::net_test {

/// Sanitizer builds run the engine several times slower: timing-bound tests
/// run the server at half the tick rate there and check that rate instead.
#ifdef IMPULSE_TESTS_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
inline constexpr double kTestTickHz = kSanitized ? 30 : 60;

/// --tick-hz and --snapshot-hz for timing-bound tests.
inline std::vector<std::string> timedRates() {
  return {"--tick-hz", std::to_string(int(kTestTickHz)), "--snapshot-hz",
          std::to_string(int(kTestTickHz / 2))};
}

inline client::ConnectOptions localClient(std::uint16_t port, std::string name = "test",
                                          bool wantSnapshots = true) {
  client::ConnectOptions options;
  options.port = port;
  options.name = std::move(name);
  options.wantSnapshots = wantSnapshots;
  options.timeout = milliseconds(10000);
  return options;
}

/// A client without snapshots presenting `token` (Access).
inline client::ConnectOptions withToken(std::uint16_t port, std::string name, std::string token) {
  auto options = localClient(port, std::move(name), false);
  options.token = std::move(token);
  return options;
}

inline bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// Sends every command first, then awaits every reply (one tick in all).
inline std::vector<v1::ServerMessage> requestAll(client::Client& client,
                                                 const std::vector<v1::ClientMessage>& commands) {
  std::vector<std::uint64_t> ids;
  for (const auto& command : commands) ids.push_back(client.send(command));
  std::vector<v1::ServerMessage> replies;
  for (const auto id : ids) {
    auto reply = client.awaitReply(id, milliseconds(20000));
    if (!reply) throw client::ConnectionError("no reply to " + std::to_string(id));
    replies.push_back(std::move(*reply));
  }
  return replies;
}

/// A 50 x 40 grid of small circles (2000 bodies) inside the sandbox. With
/// `rising`, they ignore gravity and drift upwards together at 1 m/s: awake,
/// never touching, for as long as a test runs.
inline std::vector<v1::ClientMessage> circleGrid(bool rising) {
  std::vector<v1::ClientMessage> commands;
  client::SpawnOptions options;
  options.ignoreGravity = rising;
  options.velocityY = rising ? 1.0 : 0.0;
  for (int row = 0; row < 40; ++row) {
    for (int column = 0; column < 50; ++column) {
      commands.push_back(
          client::spawnCircle({1.2 + 0.45 * column, 1.5 + 0.42 * row}, 0.18, options));
    }
  }
  return commands;
}

/// The server's client count once it equals `expected` (connections closed
/// for an error linger a moment), or the last count after three seconds.
inline std::uint32_t clientsOnceSettled(client::Client& observer, std::uint32_t expected) {
  const auto deadline = std::chrono::steady_clock::now() + milliseconds(3000);
  std::uint32_t clients = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    clients = observer.ping().stats().clients();
    if (clients == expected) break;
    std::this_thread::sleep_for(milliseconds(20));
  }
  return clients;
}

inline const v1::CommandResult& result(const v1::ServerMessage& reply) {
  EXPECT_TRUE(reply.has_command_result()) << reply.message_case();
  return reply.command_result();
}

/// A refused command's reason (the reply must be a CommandResult).
inline std::string errorOf(const v1::ServerMessage& reply) { return result(reply).error(); }

}  // namespace impulse::net_test
