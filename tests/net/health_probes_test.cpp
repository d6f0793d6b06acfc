// The orchestrator's probes (docs/server.md, "Health probes"): --health-port
// answers GET /healthz and /readyz over plain HTTP.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

/// The port the server logged for its probes ("health probes on port N").
std::uint16_t probePort(const ServerProcess& server) {
  const std::string marker = "health probes on port ";
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string log = server.log();
    if (const auto at = log.find(marker); at != std::string::npos) {
      return std::uint16_t(std::stoi(log.substr(at + marker.size())));
    }
    std::this_thread::sleep_for(milliseconds(20));
  }
  return 0;
}

/// Sends `request` to 127.0.0.1:port and returns everything until the peer closes.
std::string httpExchange(std::uint16_t port, const std::string& request) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::string response;
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
    if (!request.empty()) send(fd, request.data(), request.size(), MSG_NOSIGNAL);
    char buffer[4096];
    for (ssize_t n; (n = recv(fd, buffer, sizeof buffer, 0)) > 0;) response.append(buffer, std::size_t(n));
  }
  close(fd);
  return response;
}

std::string get(std::uint16_t port, const std::string& path) {
  return httpExchange(port, "GET " + path + " HTTP/1.1\r\nHost: probe\r\n\r\n");
}

std::string statusLine(const std::string& response) { return response.substr(0, response.find("\r\n")); }

std::string body(const std::string& response) {
  const auto end = response.find("\r\n\r\n");
  return end == std::string::npos ? "" : response.substr(end + 4);
}

TEST(HealthProbes, LivenessAndReadinessFollowTheRooms) {
  ServerProcess server({"--health-port", "0", "--max-rooms", "2"});
  const auto port = probePort(server);
  ASSERT_NE(port, 0) << server.log();

  const auto alive = get(port, "/healthz");
  EXPECT_EQ(statusLine(alive), "HTTP/1.1 200 OK");
  EXPECT_EQ(body(alive), "ok\n");
  EXPECT_TRUE(mentions(alive, "Content-Length: 3\r\n"));

  const auto ready = get(port, "/readyz");
  EXPECT_EQ(statusLine(ready), "HTTP/1.1 200 OK");
  EXPECT_EQ(body(ready), "ready: 1 of 2 rooms\n");

  // The second room fills the server: no new match fits, but it is alive.
  auto options = localClient(server.port(), "player", false);
  options.room = "match";
  client::Client player(options);
  const auto full = get(port, "/readyz");
  EXPECT_EQ(statusLine(full), "HTTP/1.1 503 Service Unavailable");
  EXPECT_EQ(body(full), "full: 2 of 2 rooms\n");
  EXPECT_EQ(statusLine(get(port, "/healthz")), "HTTP/1.1 200 OK");

  const auto unknown = get(port, "/metrics");
  EXPECT_EQ(statusLine(unknown), "HTTP/1.1 404 Not Found");
  EXPECT_EQ(body(unknown), "GET /healthz or GET /readyz\n");
  // The game port still serves: the player's Ping counts its one connection.
  EXPECT_EQ(player.ping().stats().clients(), 1u);
}

TEST(HealthProbes, SilentProbeIsCutOff) {
  ServerProcess server({"--health-port", "0"});
  const auto port = probePort(server);
  ASSERT_NE(port, 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(httpExchange(port, ""), "");  // sends nothing: closed after 2 s without an answer
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(seconds, 1.5);
  EXPECT_LT(seconds, 5.0);
  EXPECT_EQ(body(get(port, "/healthz")), "ok\n");
}

// The first body `path` answers with that starts with `prefix`, probing
// every 50 ms for at most `seconds`; the last body otherwise.
std::string awaitBody(std::uint16_t port, const std::string& path, const std::string& prefix,
                      double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::string last;
  do {
    last = body(get(port, path));
    if (last.starts_with(prefix)) break;
    std::this_thread::sleep_for(milliseconds(50));
  } while (std::chrono::steady_clock::now() < deadline);
  return last;
}

// Issue 30: /healthz and /readyz answered 200 while heavy rooms stalled
// every room. Readiness now says busy once overrunning rooms take the
// stepping threads (each up to half of one), and liveness names a room that
// finished no tick for --room-stall-seconds.
TEST(HealthProbes, OverrunningRoomsMakeTheServerBusy_AStalledRoomFailsLiveness) {
  // 240 Hz: a falling pile of 9 000 at 64 sub-steps overruns its 4.2 ms
  // period for as long as the test runs, however busy the machine, and each
  // of its ticks (over 10 ms) leaves the other rooms on the one thread
  // longer than the 10 ms stall bound without a tick. (Piles of 3 000 and
  // a 30 ms bound no longer stalled once the engine got faster.)
  ServerProcess server({"--health-port", "0", "--room-threads", "1", "--substeps", "64",
                        "--tick-hz", "240",
                        "--room-stall-seconds", "0.01", "--max-commands-per-second", "1000000"});
  const auto port = probePort(server);
  ASSERT_NE(port, 0) << server.log();
  EXPECT_EQ(awaitBody(port, "/healthz", "ok", 3), "ok\n");
  EXPECT_EQ(awaitBody(port, "/readyz", "ready", 3), "ready: 1 of 16 rooms\n");

  std::vector<std::unique_ptr<client::Client>> heavy;
  for (const char* name : {"heavy-1", "heavy-2"}) {
    auto options = localClient(server.port(), name, false);
    options.room = name;
    heavy.push_back(std::make_unique<client::Client>(options));
    std::vector<v1::ClientMessage> pile;
    for (int i = 0; i < 9000; ++i) {
      pile.push_back(client::spawnCircle({-20 + 0.5 * (i % 60), 2 + 0.5 * (i / 60)}, 0.2));
    }
    requestAll(*heavy.back(), pile);
  }
  const std::string busy = awaitBody(port, "/readyz", "busy", 10);
  std::printf("[ measure ] /readyz: %s", busy.c_str());
  EXPECT_EQ(busy,
            "busy: 2 rooms overrunning their tick budget take the 1 stepping thread(s); 3 of 16 "
            "rooms\n");
  EXPECT_EQ(statusLine(get(port, "/readyz")), "HTTP/1.1 503 Service Unavailable");
  // Generous: on a loaded 2-core machine a heavy room may still finish a
  // tick now and then before the probe catches a 10 ms stall.
  const std::string stalled = awaitBody(port, "/healthz", "stalled", 20);
  std::printf("[ measure ] /healthz: %s", stalled.c_str());
  EXPECT_TRUE(mentions(stalled, "stalled: room ")) << stalled;
  EXPECT_TRUE(mentions(stalled, " s (--room-stall-seconds 0.010000)")) << stalled;
}

}  // namespace
}  // namespace impulse::net_test
