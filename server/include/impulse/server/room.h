#pragma once
/// One world and everything that serves it: the simulation, its tick
/// schedule and timer, the clients' command queues, its members and
/// subscribers, and the snapshot builder. The Server accepts connections
/// and hands each client, after Hello, to a room; today there is one.
///
/// Data flow: session -> enqueue() -> FairQueue -> (tick) applyCommand()
/// through the command table -> Simulation (records its changes) ->
/// SnapshotBuilder -> every subscribed member.

#include <asio.hpp>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>

#include "impulse/server/access.h"
#include "impulse/server/commands.h"
#include "impulse/server/fair_queue.h"
#include "impulse/server/options.h"
#include "impulse/server/session.h"
#include "impulse/server/simulation.h"
#include "impulse/server/snapshot_builder.h"
#include "impulse/server/step_job.h"
#include "impulse/server/tick_schedule.h"

namespace impulse::server {

/// What a room needs from the server that holds it.
class RoomHost {
 public:
  virtual ~RoomHost() = default;
  /// Open connections, members of any room or not (ServerStats.clients).
  virtual std::size_t connectionCount() const = 0;
};

class Room final : public SnapshotSource {
 public:
  Room(asio::io_context& io, const ServerOptions& options, RoomHost& host);

  /// Starts the tick timer.
  void start();
  /// Stops ticking and forgets every queued command.
  void stop();

  /// A client past Hello joins with its role: Welcome, then the snapshot
  /// stream if it asked for it.
  void join(const std::shared_ptr<Session>& session, bool wantSnapshots);
  /// A member closed: its queued commands and its Step in progress are dropped.
  void leave(Session& session);
  /// A member's command, applied at a coming tick; refused at once past the
  /// client's rate.
  void enqueue(Session& session, v1::ClientMessage&& message, std::size_t bytes);

  std::pair<SharedFrame, std::uint64_t> fullSnapshot(bool quantized) override;

 private:
  void scheduleTick();
  void onTimer();
  void runTick();
  /// Runs the oldest Step in progress until `deadline` (at least one tick).
  void advanceStep(Clock::time_point deadline);
  void applyCommands(Clock::time_point deadline);
  /// Applies one queued command for its client, roles checked, and replies.
  void applyQueued(QueuedCommand& queued, Session& session);
  void reply(Session& session, v1::ServerMessage message, std::size_t bytes);
  /// Adds the room's statistics to the handler's Pong: only Ping needs them.
  void answerPing(const v1::Ping& ping, v1::ServerMessage& pong);
  void broadcastSnapshot();
  /// Snapshots are due when floor(tick * snapshot_hz / tick_hz) changes.
  std::int64_t snapshotSlot() const;
  v1::ServerStats stats(bool withStateHash);
  void logStats(Clock::time_point now);
  /// A shared owner, so that a session closed by what is sent to it stays
  /// alive until the caller is done with it; null for a non-member.
  std::shared_ptr<Session> member(std::uint32_t client) const;

  const ServerOptions& options_;
  RoomHost& host_;
  asio::steady_timer timer_;
  Simulation simulation_;
  SnapshotBuilder snapshots_;
  CommandLimits limits_;
  TickSchedule schedule_;
  TickTimes tickTimes_;
  bool stopped_ = false;

  std::map<std::uint32_t, std::shared_ptr<Session>> members_;
  FairQueue commands_;
  std::deque<StepJob> steps_;
  Ownership ownership_;

  std::uint64_t snapshotSequence_ = 0;
  std::int64_t lastSnapshotSlot_ = 0;
  std::uint64_t lastSnapshotBytes_ = 0;
  /// Snapshots skipped by members that left.
  std::uint64_t snapshotsSkippedByLeavers_ = 0;
  std::uint64_t commandsRateLimited_ = 0;
  Clock::time_point lastStatsLog_;
};

}  // namespace impulse::server
