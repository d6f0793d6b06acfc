#pragma once
/// impulse-server: accepts clients, admits them, and hands each one after
/// Hello to a room (room.h), which runs the world's tick and broadcasts its
/// snapshots. Everything runs on the io_context's thread: every piece of
/// work is bounded and every socket operation is asynchronous, so the
/// simulation never waits on a socket.

#include <asio.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "impulse/server/access.h"
#include "impulse/server/options.h"
#include "impulse/server/room.h"
#include "impulse/server/session.h"
#include "impulse/server/tick_schedule.h"

namespace impulse::server {

class Server final : public SessionHost, public RoomHost {
 public:
  /// Binds the listening socket (throws asio::system_error on failure).
  Server(asio::io_context& io, const ServerOptions& options);

  asio::ip::tcp::endpoint endpoint() const { return acceptor_.local_endpoint(); }
  /// Starts accepting and ticking.
  void start();
  /// Closes the listener and every session; io_context::run() then returns.
  void stop();

  void onHello(const std::shared_ptr<Session>& session, const v1::Hello& hello) override;
  void onCommand(const std::shared_ptr<Session>& session, v1::ClientMessage&& message,
                 std::size_t bytes) override;
  void onClosed(Session& session) override;
  std::size_t connectionCount() const override { return sessions_.size(); }

 private:
  void accept();
  /// Why a new connection may not be served ("" when it may); makes room
  /// by evicting an idle connection when it can.
  std::string admissionRefusal(const Session& newcomer);
  /// The room a client plays in: the default room, until clients can choose.
  Room& roomOf(const Session& session);
  void scheduleHousekeeping();
  void housekeeping();
  /// Gives freed heap back to the system after connections closed (a flood
  /// of them would otherwise leave the process large).
  void releaseMemory(Clock::time_point now);

  asio::io_context& io_;
  ServerOptions options_;
  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer housekeepingTimer_;
  SessionLimits sessionLimits_;
  AccessTokens tokens_;
  /// The first is the default room, the only one today.
  std::vector<std::unique_ptr<Room>> rooms_;

  std::map<std::uint32_t, std::shared_ptr<Session>> sessions_;
  std::uint32_t nextClientId_ = 1;
  std::uint64_t closedSinceTrim_ = 0;
  Clock::time_point lastTrim_;
  bool stopped_ = false;
};

}  // namespace impulse::server
