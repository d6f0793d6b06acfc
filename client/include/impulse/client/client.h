#pragma once
/// Client library: connects to impulse-server, performs the handshake, sends
/// commands, awaits their replies and keeps a WorldMirror current from the
/// snapshot stream. Single-threaded: it does I/O only inside its own calls,
/// so a game loop can call poll() with a zero timeout once per frame.
///
/// Connection-level failures (refused, closed, a server Error, a malformed
/// frame) throw ConnectionError; after one, the client is unusable. Waiting
/// calls take a timeout and return nothing when it passes.

#include <asio.hpp>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "impulse.pb.h"
#include "impulse/client/commands.h"
#include "impulse/client/world_mirror.h"
#include "impulse/wire/framing.h"

namespace impulse::client {

class ConnectionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ConnectOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 7777;
  std::string name = "impulse-client";
  bool wantSnapshots = true;
  std::chrono::milliseconds timeout{5000};
  /// Largest frame accepted from the server (full snapshots of big worlds).
  std::size_t maxFrameBytes = std::size_t(256) << 20;
  /// SO_RCVBUF in bytes when > 0 (a small one makes a slow reader visible to
  /// the server sooner; tests use it).
  int receiveBufferBytes = 0;
  /// Sent in Hello; only tests change it.
  std::uint32_t protocolVersion = wire::kProtocolVersion;
  /// Hello.token: the server's token, or its admin token for the admin role.
  std::string token;
  /// Hello.room: the room to join (made on first join); "" = "default".
  std::string room;
  /// Hello.snapshot_encoding: QUANTIZED asks for compact snapshots
  /// (docs/snapshots.md); the mirror decodes either.
  v1::SnapshotEncoding snapshotEncoding = v1::SNAPSHOT_ENCODING_PLAIN;
  /// Hello.room_min and room_max: the world bounds of the room this
  /// connection makes (admin role); none: the server's.
  std::optional<Box> roomBounds;
  /// Added round trip (tests, trying a game over a slow link on loopback):
  /// every frame sent leaves half of it later, every frame received is
  /// handled half of it later; 0: none. Delayed frames go out during the
  /// client's own calls (poll, awaitReply, ...), as everything it does.
  std::chrono::milliseconds addedRoundTrip{0};
};

/// "HOST:PORT" (or "[V6]:PORT") split; nothing when malformed.
std::optional<std::pair<std::string, std::uint16_t>> parseHostPort(std::string_view text);

class Client {
 public:
  using Duration = std::chrono::milliseconds;

  /// Connects and completes the handshake (Hello, Welcome, and with
  /// wantSnapshots the first full snapshot).
  explicit Client(const ConnectOptions& options);
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  const v1::Welcome& welcome() const { return welcome_; }
  const WorldMirror& mirror() const { return mirror_; }
  /// The last snapshot applied (its positions from (0, 0), as sent).
  const std::optional<v1::Snapshot>& lastSnapshot() const { return lastSnapshot_; }
  /// The snapshots applied that withheld states (Snapshot.states_withheld):
  /// how many, and the latest one's tick and count. Read between polls, it
  /// tells of every snapshot applied since, not only the last.
  struct WithheldSnapshots {
    std::uint64_t snapshots = 0;
    std::uint64_t lastTick = 0;
    std::uint32_t lastStates = 0;
  };
  const WithheldSnapshots& withheldSnapshots() const { return withheld_; }

  /// Sends a command with a fresh request id, which it returns.
  std::uint64_t send(v1::ClientMessage message);
  /// Waits for the reply to `requestId` (CommandResult, BodyInfo or Pong).
  /// Snapshots that arrive meanwhile are applied; other replies are kept for
  /// their own awaitReply().
  std::optional<v1::ServerMessage> awaitReply(std::uint64_t requestId, Duration timeout);
  /// send() then awaitReply(); throws ConnectionError on timeout.
  v1::ServerMessage request(v1::ClientMessage message, Duration timeout = Duration(10000));
  /// Waits until a snapshot is applied that was not applied before the call.
  std::optional<v1::Snapshot> awaitSnapshot(Duration timeout);
  /// Receives whatever is available within `timeout` and applies snapshots;
  /// returns how many messages were handled. Replies are kept for awaitReply().
  std::size_t poll(Duration timeout = Duration(0));

  /// Called for every snapshot after it was applied, with its frame size.
  void onSnapshot(std::function<void(const v1::Snapshot&, std::size_t frameBytes)> callback) {
    snapshotCallback_ = std::move(callback);
  }

  /// Called for every Events message (after SubscribeEvents), in tick order.
  void onEvents(std::function<void(const v1::Events&)> callback) { eventsCallback_ = std::move(callback); }
  /// The Events messages received since the last call, oldest first; at
  /// most kMaxKeptEvents are kept (older ones are dropped first).
  std::vector<v1::Events> takeEvents();
  static constexpr std::size_t kMaxKeptEvents = 1024;

  /// The ids a command of this client created (CommandResult body_id,
  /// joint_id), by its request id, as its reply named them, whether or not
  /// awaitReply() took the reply; the last kKeptCreations are kept. Nothing
  /// before the reply came, and for a command that created nothing.
  struct Created {
    std::uint32_t body = 0;
    std::uint32_t joint = 0;
  };
  std::optional<Created> created(std::uint64_t requestId) const;
  static constexpr std::size_t kKeptCreations = 256;

  /// Round-trip: a Ping answered after every earlier command was applied.
  /// With `wantStateHash` the stats carry the world's state hash.
  v1::Pong ping(Duration timeout = Duration(10000), bool wantStateHash = false);

 private:
  /// Runs the socket until a message is received or the deadline passes.
  bool receiveOne(std::chrono::steady_clock::time_point deadline);
  void startRead();
  void handle(v1::ServerMessage&& message, std::size_t frameBytes);
  /// Keeps what a reply says its command created (created()).
  void remember(const v1::ServerMessage& reply);
  void throwIfFailed() const;
  /// Writes the frames whose added delay has passed.
  void writeDueFrames();
  void writeFrame(const std::string& frame);
  /// When the next delayed frame is due either way (else `deadline`).
  std::chrono::steady_clock::time_point nextDue(std::chrono::steady_clock::time_point deadline) const;
  bool receivedDue(std::chrono::steady_clock::time_point now) const;

  asio::io_context io_;
  asio::ip::tcp::socket socket_;
  wire::FrameReader reader_;
  std::array<char, 64 * 1024> buffer_{};
  bool reading_ = false;
  std::string failure_;
  struct Received {
    v1::ServerMessage message;
    std::size_t bytes = 0;
    std::chrono::steady_clock::time_point due;  ///< handled from then on
  };
  std::deque<Received> inbox_;
  /// Half the added round trip, each way.
  std::chrono::steady_clock::duration oneWayDelay_{};
  std::deque<std::pair<std::chrono::steady_clock::time_point, std::string>> delayedFrames_;

  v1::Welcome welcome_;
  WorldMirror mirror_;
  std::map<std::uint64_t, v1::ServerMessage> replies_;
  std::map<std::uint64_t, Created> created_;
  std::uint64_t nextRequestId_ = 1;
  std::function<void(const v1::Snapshot&, std::size_t)> snapshotCallback_;
  std::optional<v1::Snapshot> lastSnapshot_;
  WithheldSnapshots withheld_;
  std::function<void(const v1::Events&)> eventsCallback_;
  std::deque<v1::Events> events_;
};

}  // namespace impulse::client
