#pragma once
/// One client connection: framed reads, the handshake, and a bounded
/// outbound queue (Asio chat-server pattern: the session owns itself through
/// shared_ptr captures; one write in flight at a time).
///
/// Memory per session is bounded whatever the peer does: one read buffer, one
/// frame of at most max-frame-bytes, queued command bytes up to a cap (reading
/// pauses beyond it), replies up to a cap (the session is dropped beyond it;
/// one reply larger than the cap may wait beside them)
/// and at most one unsent snapshot, which a newer one replaces.

#include <asio.hpp>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "impulse.pb.h"
#include "impulse/server/rate_limiter.h"
#include "impulse/server/snapshot_builder.h"
#include "impulse/server/tick_schedule.h"
#include "impulse/wire/framing.h"

namespace impulse::server {

class Session;

/// What a session needs from the server.
class SessionHost {
 public:
  virtual ~SessionHost() = default;
  /// A valid Hello arrived: answer with Welcome (and subscribe if asked).
  virtual void onHello(const std::shared_ptr<Session>& session, const v1::Hello& hello) = 0;
  /// A command to queue for the next tick; `bytes` is its frame size.
  virtual void onCommand(const std::shared_ptr<Session>& session, v1::ClientMessage&& message,
                         std::size_t bytes) = 0;
  virtual void onClosed(Session& session) = 0;
};

/// Where a subscriber's full snapshots come from: its room.
class SnapshotSource {
 public:
  virtual ~SnapshotSource() = default;
  /// Asks for a full snapshot of the world (a quantized key frame when
  /// `quantized`). The answer comes later, on the I/O thread, as
  /// Session::takeFullSnapshot; the session never waits for the world.
  virtual void requestFullSnapshot(std::uint32_t client, bool quantized) = 0;
};

struct SessionLimits {
  std::size_t maxFrameBytes = wire::kDefaultMaxFrameBytes;
  /// Replies waiting to be sent; a client past this is not reading: dropped.
  /// Besides them, one reply larger than this may wait (a client is never
  /// closed for the size of what it asked for); a scene that fits neither
  /// is answered by a refusal.
  std::size_t maxQueuedReplyBytes = std::size_t(1) << 20;
  /// Commands waiting for the next tick; reading pauses past this.
  std::size_t maxPendingCommandBytes = std::size_t(1) << 20;
  Clock::duration stallTimeout = std::chrono::seconds(10);
  /// A client past Hello that sends nothing for this long is dropped: one
  /// that subscribes to nothing, or a subscriber that was offered no
  /// snapshot either (its room is paused).
  Clock::duration idleTimeout = std::chrono::seconds(30);
  /// Commands per second, after a burst of two seconds' worth. Past it the
  /// session stops reading until the budget refills: TCP flow control slows
  /// the client, nothing is refused and replies stay in order.
  double commandsPerSecond = 2000;
};

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(asio::ip::tcp::socket socket, SessionHost& host, std::uint32_t id,
          const SessionLimits& limits);

  void start();
  /// Sends Error(message) and closes without reading anything (server full).
  void reject(const std::string& message);

  void send(const v1::ServerMessage& message);
  /// Starts the snapshot stream with a full snapshot from `source`, which
  /// outlives the session's stream (a room keeps its members).
  void subscribe(SnapshotSource& source);
  bool subscribed() const { return phase_ == Phase::Streaming; }
  /// Broadcast `sequence` (delta against broadcast sequence - 1). A session
  /// that did not get every earlier broadcast gets a full snapshot instead.
  void offerSnapshot(std::uint64_t sequence, const SharedFrame& delta);
  /// The full snapshot requested from the SnapshotSource: it includes the
  /// changes of every broadcast up to `sequence`.
  void takeFullSnapshot(SharedFrame frame, std::uint64_t sequence);
  /// An Events message: queued beside the replies while they leave it room,
  /// dropped otherwise (the client sees the gap in Events.sequence); a
  /// client slow to read its events is never closed for them.
  void offerEvents(const SharedFrame& frame);
  /// Commands of `bytes` were applied: reading may resume.
  void commandsApplied(std::size_t bytes);
  /// Drops the session if it stalled (see SessionLimits) or never said Hello.
  void checkTimeouts(Clock::time_point now);
  void close(const std::string& reason);

  std::uint32_t id() const { return id_; }
  /// The room it joined: named on its log lines from now on.
  void setRoom(std::string room) { room_ = std::move(room); }
  /// A log line about this client: "room R, client N 'name' (address:port) MESSAGE".
  void log(std::string_view message) const;
  /// Logs a refused command (its error in the user's words), at most
  /// kRefusalLinesPerSecond lines a second after a burst: a client sending
  /// only bad commands cannot flood the log, and the next line logged says
  /// how many were left out.
  void logRefusal(std::string_view error);
  /// The role granted at Hello (docs/protocol.md, Access).
  bool admin() const { return admin_; }
  void setAdmin(bool admin) { admin_ = admin; }
  /// Hello.snapshot_encoding was SNAPSHOT_ENCODING_QUANTIZED.
  bool quantized() const { return quantized_; }
  /// When the peer last sent bytes or had a command applied (or connected).
  Clock::time_point lastActive() const { return lastActive_; }
  /// Silent for a while, not subscribed, nothing queued either way: may be
  /// closed to make room for a new connection.
  bool evictable(Clock::time_point now) const;
  /// Closes with an Error saying room was needed.
  void evict(Clock::time_point now);
  /// The peer's IP address ("" when unknown).
  const std::string& address() const { return address_; }
  /// Not closed and not closing after an error (a phase before Flushing).
  bool acceptingTraffic() const { return phase_ <= Phase::Streaming; }
  const std::string& name() const { return name_; }
  std::uint64_t snapshotsSkipped() const { return snapshotsSkipped_; }
  std::uint64_t eventsDropped() const { return eventsDropped_; }
  /// Times reading paused because the client was past its command rate.
  std::uint64_t rateWaits() const { return rateWaits_; }

 private:
  /// The session's life, in order: a phase only ever moves forward.
  /// AwaitingHello -> Serving (Hello accepted) -> Streaming (subscribed);
  /// any of those -> Flushing (an Error queued: nothing more is read or
  /// queued) -> Lingering (Error sent, half-closed, draining input until
  /// EOF); any -> Closed.
  enum class Phase { AwaitingHello, Serving, Streaming, Flushing, Lingering, Closed };
  static bool allowed(Phase from, Phase to);
  void enter(Phase next);

  struct Outgoing {
    SharedFrame frame;  // null: a full snapshot, requested when it is next to be written
    bool snapshot = false;
  };

  /// Queues a frame that may wait (the reply budget was checked).
  void enqueue(Outgoing item);
  void readMore();
  /// True when the rate budget has a command; otherwise pauses reading
  /// until it will have one.
  bool rateAllowsACommand();
  void sizeReadBuffer();
  void onRead(const asio::error_code& ec, std::size_t bytes);
  void processBuffered();
  void handleFrame(std::string_view payload);
  /// Protocol violation: Error, then close once it is flushed.
  void fatal(const std::string& message);
  /// After the Error is flushed: half-close and drain input until EOF.
  void startLinger();
  void push(Outgoing item);
  /// A reply of `bytes` may join the queue (see SessionLimits::maxQueuedReplyBytes).
  bool replyFits(std::size_t bytes) const;
  /// The counter a reply of `bytes` is counted in.
  std::size_t& replyBytesOf(std::size_t bytes);
  /// The CommandResult answering a SaveScene whose scene does not fit.
  v1::ServerMessage sceneNotQueued(std::uint64_t requestId, std::size_t bytes) const;
  void writeMore();
  /// The queue's first item is a full snapshot still to be built: asks the
  /// source for it (once) and returns true while it is awaited.
  bool awaitingFullSnapshot();
  void onWritten(std::size_t bytes);
  std::size_t lockedItems() const;
  std::string label() const;

  asio::ip::tcp::socket socket_;
  SessionHost& host_;
  std::uint32_t id_;
  SessionLimits limits_;
  std::string name_;
  std::string room_;
  std::string peer_;
  std::string address_;
  Clock::time_point connectedAt_;
  Clock::time_point lastActive_;
  RateLimiter rate_;
  asio::steady_timer rateTimer_;
  bool waitingForRate_ = false;
  std::uint64_t rateWaits_ = 0;
  RateLimiter refusalLines_;
  std::uint64_t refusalsNotLogged_ = 0;
  bool admin_ = false;
  bool quantized_ = false;

  /// Starts small; doubles while reads fill it, shrinks back once they do not.
  std::vector<char> readBuffer_;
  std::size_t lastReadBytes_ = 0;
  std::size_t readBegin_ = 0;
  std::size_t readEnd_ = 0;
  wire::FrameReader reader_;
  /// A read is in flight (at most one at a time).
  bool reading_ = false;
  std::size_t pendingCommandBytes_ = 0;

  std::deque<Outgoing> queue_;
  /// Replies queued, within SessionLimits::maxQueuedReplyBytes...
  std::size_t queuedReplyBytes_ = 0;
  /// ...and the one reply larger than that cap which may wait beside them.
  std::size_t oversizedReplyBytes_ = 0;
  /// Queue items in the write call in flight (0: none in flight).
  std::size_t inFlight_ = 0;
  std::size_t writeOffset_ = 0;
  /// A snapshot waits in queue_, not yet taken into a write: a newer one
  /// replaces it instead of queueing behind it.
  bool unsentSnapshot_ = false;
  Clock::time_point lastWriteProgress_;

  Phase phase_ = Phase::AwaitingHello;
  Clock::time_point lingerSince_;
  SnapshotSource* snapshotSource_ = nullptr;
  /// A full snapshot was requested and has not come yet. Every broadcast
  /// offered meanwhile is in it: the source answers after the broadcasts it
  /// made before the request reached it.
  bool fullSnapshotRequested_ = false;
  /// The broadcast the client's snapshots are up to (none before the first).
  std::optional<std::uint64_t> lastSnapshotSequence_;
  /// When a snapshot was last offered (or the stream started).
  Clock::time_point lastSnapshot_;
  std::uint64_t snapshotsSkipped_ = 0;
  std::uint64_t eventsDropped_ = 0;
};

}  // namespace impulse::server
