#pragma once
/// impulse-server: accepts clients, runs the fixed tick and broadcasts
/// snapshots. Everything runs on the io_context's thread: the world step is
/// bounded and every socket operation is asynchronous, so the simulation
/// never waits on a socket.

#include <asio.hpp>
#include <cstdint>
#include <map>
#include <memory>

#include "impulse/server/access.h"
#include "impulse/server/commands.h"
#include "impulse/server/fair_queue.h"
#include "impulse/server/options.h"
#include "impulse/server/session.h"
#include "impulse/server/simulation.h"
#include "impulse/server/tick_schedule.h"

namespace impulse::server {

class Server final : public SessionHost {
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
  std::pair<SharedFrame, std::uint64_t> currentFullSnapshot() override;

 private:
  void accept();
  /// Why a new connection may not be served ("" when it may); makes room
  /// by evicting an idle connection when it can.
  std::string admissionRefusal(const Session& newcomer);
  /// Applies one queued command for its client, roles checked, and replies.
  void applyQueued(QueuedCommand& queued, Session& session);
  void scheduleTick();
  void onTimer();
  void runTick();
  void applyCommands();
  void broadcastSnapshot();
  /// Snapshots are due when floor(tick * snapshot_hz / tick_hz) changes.
  std::int64_t snapshotSlot() const;
  bool snapshotDue() const;
  v1::ServerStats stats(bool withStateHash);
  /// Gives freed heap back to the system after connections closed (a flood
  /// of them would otherwise leave the process large).
  void releaseMemory(Clock::time_point now);
  void housekeeping(Clock::time_point now);

  asio::io_context& io_;
  ServerOptions options_;
  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer timer_;
  Simulation simulation_;
  CommandLimits limits_;
  SessionLimits sessionLimits_;
  TickSchedule schedule_;
  TickTimes tickTimes_;

  std::map<std::uint32_t, std::shared_ptr<Session>> sessions_;
  std::uint32_t nextClientId_ = 1;
  FairQueue commands_;
  AccessTokens tokens_;
  Ownership ownership_;
  std::uint64_t commandsRateLimited_ = 0;
  std::uint64_t closedSinceTrim_ = 0;
  Clock::time_point lastTrim_;

  std::uint64_t snapshotSequence_ = 0;
  std::int64_t lastSnapshotSlot_ = 0;
  std::uint64_t lastSnapshotBytes_ = 0;
  std::uint64_t snapshotsSkipped_ = 0;
  std::uint64_t ticksRun_ = 0;
  Clock::time_point lastHousekeeping_;
  Clock::time_point lastStatsLog_;
  bool stopped_ = false;
};

}  // namespace impulse::server
