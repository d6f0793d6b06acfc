#pragma once
/// One world and everything that serves it: the simulation, its tick
/// schedule and timer, the clients' command queues, its members and
/// subscribers, and the snapshot builder. The Server accepts connections
/// and hands each client, after Hello, to the room it names.
///
/// Data flow: session -> enqueue() -> FairQueue -> (tick) applyCommand()
/// through the command table -> Simulation (records its changes) ->
/// SnapshotBuilder -> every subscribed member.
///
/// Positions: the wire's are from (0, 0); the world computes around the
/// room's origin (RoomBounds::origin). The room's edge moves them: commands
/// as they are applied, replies and events as they leave, snapshots as the
/// builder encodes them (wire_positions.h).
///
/// Threads (docs/server.md, "Rooms"): a room lives on two sides.
/// - The I/O thread (the io_context, like every Session) owns the members
///   and calls every public function.
/// - The room's strand on the stepping pool owns the world: the simulation,
///   the command queue, the Steps in progress, the tick timer. Commands,
///   joins and leaves are posted to it; what it has to say (Welcome,
///   replies, snapshot frames) is collected in an outbox and posted back to
///   the I/O thread in one batch (deliver()). So a session is only ever
///   touched by the I/O thread and a world only by one thread at a time.
/// A subscriber's full snapshot (or key frame) is asked of the strand too,
/// and comes back in a batch after the broadcasts it includes: no lock is
/// shared between a tick and the I/O thread.

#include <asio.hpp>
#include <asio/thread_pool.hpp>
#include <atomic>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "impulse/server/access.h"
#include "impulse/server/commands.h"
#include "impulse/server/fair_queue.h"
#include "impulse/server/joint_tags.h"
#include "impulse/server/options.h"
#include "impulse/server/room_bounds.h"
#include "impulse/server/session.h"
#include "impulse/server/simulation.h"
#include "impulse/server/snapshot_builder.h"
#include "impulse/server/stamped_commands.h"
#include "impulse/server/step_job.h"
#include "impulse/server/tick_schedule.h"

namespace impulse::server {

/// What a room needs from the server that holds it (called on the I/O thread).
class RoomHost {
 public:
  virtual ~RoomHost() = default;
  /// Open connections, members of any room or not (ServerStats.clients).
  virtual std::size_t connectionCount() const = 0;
  /// Every room of the server, for a RoomList.
  virtual void listRooms(v1::RoomList& list) const = 0;
  /// The bodies of all rooms, against --max-total-bodies.
  virtual std::shared_ptr<ServerBodies> serverBodies() = 0;
};

class Room final : public SnapshotSource, public std::enable_shared_from_this<Room> {
 public:
  /// `bounds`: the world's (Hello.room_min, room_max; checked by the server),
  /// which also place its origin.
  /// `engineWorkers`: how the world's step gets threads of `steppers`
  /// beside the room's own (pool_tasks.h).
  Room(std::string name, asio::io_context& io, asio::thread_pool& steppers, const TaskSettings& engineWorkers,
       const ServerOptions& options, RoomHost& host, const RoomBounds& bounds);

  const std::string& name() const { return name_; }
  /// The world bounds it was made with.
  const RoomBounds& bounds() const { return bounds_; }

  /// Starts the tick timer.
  void start();
  /// Stops ticking and forgets every queued command.
  void stop();

  /// A client past Hello joins with its role: Welcome, then the snapshot
  /// stream if it asked for it.
  void join(const std::shared_ptr<Session>& session, bool wantSnapshots);
  /// A member closed: its queued commands and its Step in progress are dropped.
  void leave(Session& session);
  bool empty() const { return members_.empty(); }
  /// A member's command, applied at a coming tick (the session reads no
  /// faster than the client's rate).
  void enqueue(Session& session, v1::ClientMessage&& message, std::size_t bytes);
  /// Name, members, and the bodies and tick as of the room's last tick.
  v1::RoomInfo info() const;
  /// How long ago the room last finished a wakeup's ticks.
  Clock::duration sinceLastTick(Clock::time_point now) const;
  /// Its ticks overrun their period (it runs in slow motion).
  bool overrunning() const { return publishedOverrunning_.load(); }

  void requestFullSnapshot(std::uint32_t client, bool quantized) override;

 private:
  // ----------------------------------------------- strand -> I/O thread
  enum class ReplyKind { Command, Welcome, WelcomeAndSubscribe };
  struct Reply {
    std::uint32_t client;
    v1::ServerMessage message;
    std::size_t bytes;  // the command's frame size (frees the client's reading budget)
    ReplyKind kind = ReplyKind::Command;
  };
  /// One subscriber's own snapshot (personal_stream.h).
  struct PersonalFrame {
    std::uint32_t client;
    SharedFrame frame;
  };
  struct Broadcast {
    std::uint64_t sequence;
    SharedFrame delta;           ///< null without plain subscribers
    SharedFrame quantizedDelta;  ///< null without quantized subscribers
    /// The subscribers with an area or a budget, by client id: theirs.
    std::vector<PersonalFrame> personal;
  };
  /// One subscriber's full snapshot, including broadcasts up to `sequence`.
  struct FullSnapshot {
    std::uint32_t client;
    SharedFrame frame;
    std::uint64_t sequence;
  };
  /// One tick's Events message, for the clients subscribed to events when
  /// it was made.
  struct EventsBroadcast {
    SharedFrame frame;
    std::vector<std::uint32_t> clients;
  };
  using Outgoing = std::variant<Reply, Broadcast, FullSnapshot, EventsBroadcast>;
  using Batch = std::vector<Outgoing>;

  /// Runs `work` on the strand, then posts what it produced to the I/O thread.
  template <class Work>
  void onStrand(Work work);
  /// I/O thread: hands a batch to the members it names.
  void deliver(Batch& batch);
  void deliverReply(Reply& reply);
  void deliverBroadcast(const Broadcast& broadcast);
  void deliverFullSnapshot(FullSnapshot& snapshot);
  void deliverEvents(const EventsBroadcast& events);
  /// A shared owner, so that a session closed by what is sent to it stays
  /// alive until the caller is done with it; null for a non-member.
  std::shared_ptr<Session> member(std::uint32_t client) const;
  /// Tells the strand how many subscribers there are (none: no deltas to build).
  void countSubscribers();

  // ------------------------------------------------------- strand side
  void welcome(std::uint32_t client, bool admin, bool quantized, bool wantSnapshots);
  /// Arms the tick timer for `at`.
  void scheduleTick(Clock::time_point at);
  void onTimer();
  void runTick();
  /// The world steps the time scale owes this tick, as many as fit before
  /// `deadline` (at least one); returns how many ran.
  int runScaledSteps(Clock::time_point deadline);
  /// Runs the oldest Step in progress until `deadline` (at least one tick).
  void advanceStep(Clock::time_point deadline);
  void applyCommands(Clock::time_point deadline);
  /// A command stamped for a coming tick (or this one) waits for it; one
  /// past (within the bound) is applied now; a stamp out of bounds is refused.
  void applyOrSchedule(QueuedCommand& queued, bool admin);
  /// Applies the stamped commands whose tick has come.
  void applyDueCommands();
  /// Applies one queued command for its client, roles checked, and replies.
  void applyQueued(QueuedCommand& queued, bool admin);
  void reply(std::uint32_t client, v1::ServerMessage message, std::size_t bytes);
  /// SetInterestArea or SetBandwidthBudget accepted by its handler: the
  /// client's stream follows (refused for a quantized subscriber).
  void changeStream(std::uint32_t client, const CommandRow& row, const v1::ClientMessage& message,
                    CommandOutcome& outcome);
  /// The personal streams' frames of this broadcast; a stream back to the
  /// whole room without a budget takes a full shared snapshot and ends.
  std::vector<PersonalFrame> personalFrames(const WorldChanges& changes);
  /// Adds the room's statistics to the handler's Pong: only Ping needs them.
  void answerPing(const v1::Ping& ping, v1::ServerMessage& pong);
  void broadcastSnapshot();
  /// The Events messages of the steps since the last call, to the event
  /// subscribers.
  void broadcastEvents();
  /// SubscribeEvents applied: the client joins or leaves the event stream.
  void subscribeEvents(std::uint32_t client, bool enabled);
  /// Snapshots are due when floor(running ticks * snapshot_hz / tick_hz)
  /// changes: on the wall clock's grid, whatever the time scale.
  std::int64_t snapshotSlot() const;
  /// The statistics the world side knows (the I/O thread adds clients and
  /// skipped snapshots when it delivers the Pong).
  v1::ServerStats stats(bool withStateHash);
  void logStats(Clock::time_point now);
  /// Publishes the tick and body count for RoomList and early refusals.
  void publish();

  const std::string name_;
  const RoomBounds bounds_;
  asio::io_context& io_;
  asio::strand<asio::thread_pool::executor_type> strand_;
  const ServerOptions& options_;
  RoomHost& host_;

  // I/O thread only.
  std::map<std::uint32_t, std::shared_ptr<Session>> members_;
  /// Members whose snapshot stream started (a closed session no longer says).
  std::set<std::uint32_t> subscriberIds_;
  /// deliverBroadcast's scratch list of the sessions it offers a snapshot.
  std::vector<std::shared_ptr<Session>> broadcastTargets_;
  /// Snapshots skipped by members that left.
  std::uint64_t snapshotsSkippedByLeavers_ = 0;
  /// Rate-limit pauses of members that left.
  std::uint64_t rateWaitsByLeavers_ = 0;
  /// Ticks the clock ran unpaused (the snapshot grid) and the steps a time
  /// scale owed that did not fit their tick.
  std::uint64_t runningTicks_ = 0;
  std::uint64_t scaledStepsDropped_ = 0;

  // Written by the I/O thread, read by the strand: subscribers to build deltas for.
  std::atomic<std::size_t> subscribers_ = 0;
  std::atomic<std::size_t> quantizedSubscribers_ = 0;
  // Written by the strand, read by the I/O thread.
  std::atomic<std::uint64_t> publishedTick_ = 0;
  std::atomic<std::uint32_t> publishedBodies_ = 0;
  std::atomic<Clock::rep> publishedTickEnd_;
  std::atomic<bool> publishedOverrunning_ = false;

  // Strand only.
  asio::steady_timer timer_;
  Simulation simulation_;
  SnapshotBuilder snapshots_;
  std::uint64_t snapshotSequence_ = 0;
  CommandLimits limits_;
  TickSchedule schedule_;
  TickTimes tickTimes_;
  bool stopped_ = false;
  /// Its ticks took longer than a tick period, on average over the last second.
  bool overrunning_ = false;
  /// The members as the strand knows them, with their role (true: admin).
  std::map<std::uint32_t, bool> clients_;
  /// The members that asked for SNAPSHOT_ENCODING_QUANTIZED.
  std::set<std::uint32_t> quantizedClients_;
  /// The members with an area of interest or a budget (or just back from one).
  std::map<std::uint32_t, PersonalStream> streams_;
  /// The members that asked for events, sorted.
  std::vector<std::uint32_t> eventSubscribers_;
  FairQueue commands_;
  StampedCommands stamped_;
  std::deque<StepJob> steps_;
  Ownership ownership_;
  JointTags jointTags_;
  std::int64_t lastSnapshotSlot_ = 0;
  std::uint64_t lastSnapshotBytes_ = 0;
  Clock::time_point lastStatsLog_;
  Batch outbox_;
};

}  // namespace impulse::server
