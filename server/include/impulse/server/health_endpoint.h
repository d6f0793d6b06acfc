#pragma once
/// The orchestrator's probes (docs/server.md, "Health probes"): a tiny HTTP
/// endpoint on its own port (--health-port), on the I/O thread.
///   GET /healthz  200 "ok" while the I/O thread serves and every room
///                 ticks; 503 naming a stalled room (a wedged server cannot
///                 answer at all: either way the liveness probe restarts it).
///   GET /readyz   200 when a new room can be made and served, else 503 (a
///                 server full of rooms, or whose stepping threads are taken
///                 by overrunning rooms, takes no new match but keeps its
///                 players).
/// One request per connection: the request line is read (at most 1 KiB,
/// within 2 s), answered, and the connection closed.

#include <asio.hpp>
#include <cstdint>
#include <functional>
#include <string>

namespace impulse::server {

/// A probe's answer: 200 or 503, and the response body (one line).
struct ProbeStatus {
  bool ok = false;
  std::string text;
};

class HealthEndpoint {
 public:
  /// Binds `endpoint` (throws asio::system_error on failure).
  HealthEndpoint(asio::io_context& io, const asio::ip::tcp::endpoint& endpoint,
                 std::function<ProbeStatus()> liveness, std::function<ProbeStatus()> readiness);

  asio::ip::tcp::endpoint endpoint() const { return acceptor_.local_endpoint(); }
  void start();
  void stop();

 private:
  void accept();
  /// The status line and body for `requestLine` ("GET /healthz HTTP/1.1").
  std::string respond(const std::string& requestLine) const;

  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer retry_;
  std::function<ProbeStatus()> liveness_;
  std::function<ProbeStatus()> readiness_;
  bool stopped_ = false;
};

}  // namespace impulse::server
