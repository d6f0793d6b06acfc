#include "impulse/server/health_endpoint.h"

#include <memory>

namespace impulse::server {

namespace {

constexpr std::size_t kMaxRequestLine = 1024;
constexpr auto kProbeTimeout = std::chrono::seconds(2);
constexpr auto kAcceptRetryDelay = std::chrono::milliseconds(100);

std::string httpResponse(const std::string& status, const std::string& body) {
  return "HTTP/1.1 " + status + "\r\nContent-Type: text/plain\r\nContent-Length: " +
         std::to_string(body.size()) + "\r\nConnection: close\r\n\r\n" + body;
}

// One probe connection: its socket, what it sent, its deadline.
struct Probe {
  explicit Probe(asio::ip::tcp::socket s) : socket(std::move(s)), deadline(socket.get_executor()) {}
  asio::ip::tcp::socket socket;
  asio::steady_timer deadline;
  std::string request;
  std::string response;
};

}  // namespace

HealthEndpoint::HealthEndpoint(asio::io_context& io, const asio::ip::tcp::endpoint& endpoint,
                               std::function<ProbeStatus()> liveness,
                               std::function<ProbeStatus()> readiness)
    : acceptor_(io),
      retry_(io),
      liveness_(std::move(liveness)),
      readiness_(std::move(readiness)) {
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(asio::ip::tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
}

void HealthEndpoint::start() { accept(); }

void HealthEndpoint::stop() {
  stopped_ = true;
  asio::error_code ignored;
  acceptor_.close(ignored);
  retry_.cancel();
}

void HealthEndpoint::accept() {
  acceptor_.async_accept([this](const asio::error_code& ec, asio::ip::tcp::socket socket) {
    if (stopped_) return;
    if (ec) {
      // Out of descriptors and the like: retry soon instead of spinning.
      retry_.expires_after(kAcceptRetryDelay);
      retry_.async_wait([this](const asio::error_code& timer) {
        if (!timer && !stopped_) accept();
      });
      return;
    }
    {
      auto probe = std::make_shared<Probe>(std::move(socket));
      // A silent or slow peer is cut off: probes answer at once or not at all.
      probe->deadline.expires_after(kProbeTimeout);
      probe->deadline.async_wait([probe](const asio::error_code& timer) {
        asio::error_code ignored;
        if (!timer) probe->socket.close(ignored);
      });
      asio::async_read_until(
          probe->socket, asio::dynamic_buffer(probe->request, kMaxRequestLine), "\r\n",
          [this, probe](const asio::error_code& read, std::size_t length) {
            if (read) {
              probe->deadline.cancel();
              return;
            }
            probe->response = respond(probe->request.substr(0, length));
            asio::async_write(probe->socket, asio::buffer(probe->response),
                              [probe](const asio::error_code&, std::size_t) {
                                asio::error_code ignored;
                                probe->socket.shutdown(asio::ip::tcp::socket::shutdown_both,
                                                       ignored);
                                probe->socket.close(ignored);
                                probe->deadline.cancel();
                              });
          });
    }
    accept();
  });
}

std::string HealthEndpoint::respond(const std::string& requestLine) const {
  auto answer = [](const ProbeStatus& status) {
    return httpResponse(status.ok ? "200 OK" : "503 Service Unavailable", status.text + "\n");
  };
  if (requestLine.starts_with("GET /healthz ")) return answer(liveness_());
  if (requestLine.starts_with("GET /readyz ")) return answer(readiness_());
  return httpResponse("404 Not Found", "GET /healthz or GET /readyz\n");
}

}  // namespace impulse::server
