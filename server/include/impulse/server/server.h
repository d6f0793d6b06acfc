#pragma once
/// impulse-server: accepts clients, admits them, and hands each one after
/// Hello to the room it names (room.h), made on first join, which runs its
/// world's tick and broadcasts its snapshots. Sockets, sessions and the
/// rooms' members live on the io_context's thread (every socket operation
/// asynchronous); each room's world is stepped on a strand of the stepping
/// pool, so rooms tick in parallel and never wait on a socket or on each
/// other (docs/server.md, "Rooms").

#include <asio.hpp>
#include <asio/thread_pool.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "impulse/server/access.h"
#include "impulse/server/health_endpoint.h"
#include "impulse/server/options.h"
#include "impulse/server/pool_tasks.h"
#include "impulse/server/room.h"
#include "impulse/server/session.h"
#include "impulse/server/tick_schedule.h"

namespace impulse::server {

class Server final : public SessionHost, public RoomHost {
 public:
  /// Binds the listening socket (throws asio::system_error on failure).
  /// Rooms are stepped on `steppers`, which must outlive the io_context's
  /// pending work (join it after io_context::run() returns).
  Server(asio::io_context& io, asio::thread_pool& steppers, const ServerOptions& options);

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
  void listRooms(v1::RoomList& list) const override;
  std::shared_ptr<ServerBodies> serverBodies() override { return serverBodies_; }

 private:
  void accept();
  /// Why a new connection may not be served ("" when it may); makes room
  /// by evicting an idle connection when it can.
  std::string admissionRefusal(const Session& newcomer);
  /// The room a Hello names, made if new (with the Hello's bounds, which
  /// only an admin may give); or why the client may not join.
  std::variant<std::shared_ptr<Room>, std::string> roomFor(const v1::Hello& hello,
                                                           const std::string& address, bool admin);
  /// The room a client joined; null before Hello.
  std::shared_ptr<Room> roomOf(const Session& session) const;
  void scheduleHousekeeping();
  void housekeeping();
  /// Gives freed heap back to the system after connections closed (a flood
  /// of them would otherwise leave the process large).
  void releaseMemory(Clock::time_point now);
  /// Not ok once a room finished no tick for --room-stall-seconds.
  ProbeStatus liveness() const;
  /// Not ok when no new room fits (--max-rooms) or the overrunning rooms
  /// take every stepping thread (each takes up to half of one).
  ProbeStatus readiness() const;

  asio::io_context& io_;
  ServerOptions options_;
  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer housekeepingTimer_;
  SessionLimits sessionLimits_;
  AccessTokens tokens_;
  /// The probes' endpoint, with --health-port.
  std::unique_ptr<HealthEndpoint> health_;
  asio::thread_pool& steppers_;
  /// Every room's engine workers: threads of steppers_ (--room-workers).
  PoolTasks engineWorkers_;
  std::shared_ptr<ServerBodies> serverBodies_;
  /// By name. The default room lives as long as the server; any other is
  /// dropped when its last member leaves.
  std::map<std::string, std::shared_ptr<Room>> rooms_;
  std::map<std::uint32_t, std::shared_ptr<Room>> roomOfClient_;
  /// The address that made each room it holds (the default room has none).
  std::map<std::string, std::string> roomMaker_;

  std::map<std::uint32_t, std::shared_ptr<Session>> sessions_;
  std::uint32_t nextClientId_ = 1;
  std::uint64_t closedSinceTrim_ = 0;
  Clock::time_point lastTrim_;
  bool stopped_ = false;
};

}  // namespace impulse::server
