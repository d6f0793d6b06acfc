#pragma once
/// The orchestrator's probes (docs/server.md, "Health probes"): a tiny HTTP
/// endpoint on its own port (--health-port), on the I/O thread.
///   GET /healthz  200 "ok": the I/O thread is serving (a wedged server
///                 cannot answer, so the liveness probe restarts it).
///   GET /readyz   200 when a new room can be made, else 503 (a server full
///                 of rooms takes no new match but keeps its players).
/// One request per connection: the request line is read (at most 1 KiB,
/// within 2 s), answered, and the connection closed.

#include <asio.hpp>
#include <cstdint>
#include <functional>
#include <string>

namespace impulse::server {

struct Readiness {
  bool ready = false;
  std::string text;  // the response body, one line
};

class HealthEndpoint {
 public:
  /// Binds `endpoint` (throws asio::system_error on failure).
  HealthEndpoint(asio::io_context& io, const asio::ip::tcp::endpoint& endpoint,
                 std::function<Readiness()> readiness);

  asio::ip::tcp::endpoint endpoint() const { return acceptor_.local_endpoint(); }
  void start();
  void stop();

 private:
  void accept();
  /// The status line and body for `requestLine` ("GET /healthz HTTP/1.1").
  std::string respond(const std::string& requestLine) const;

  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer retry_;
  std::function<Readiness()> readiness_;
  bool stopped_ = false;
};

}  // namespace impulse::server
