#pragma once
/// Client-side prediction (docs/networked-play.md, "Prediction"): the client
/// runs the engine on its own copy of the room's world, a few ticks ahead of
/// the last snapshot, so its own commands show at once.
///
/// Each command goes out stamped for the predicted tick (for_tick) and is
/// applied to the copy at once. When a snapshot arrives, the copy goes back
/// to its own state at the snapshot's tick, takes the server's body states,
/// and replays the commands the snapshot does not hold yet
/// (Snapshot.applied_stamps) up to the predicted tick again. The difference
/// a replay makes to a body is not shown at once: it is shown as an offset
/// that shrinks by a fixed fraction every tick.

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "impulse.pb.h"
#include "impulse/body.h"
#include "impulse/world_state.h"

namespace impulse::client {

class Client;
class LocalWorld;

/// The snapshots cannot keep the copy true (a bandwidth budget withheld
/// states); the predictor that threw it is of no further use.
class PredictionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PredictionOptions {
  /// Ticks the copy runs ahead of the last snapshot: the round trip plus a
  /// margin for jitter, in ticks (docs/networked-play.md, "Prediction").
  /// Commands go out stamped for the snapshot's tick plus this.
  std::uint32_t leadTicks = 12;
  /// Fraction of the shown correction removed each tick: 0.2 leaves 0.8^n
  /// of it after n ticks (half after 3, a tenth after 10 at 60 Hz).
  double blendPerTick = 0.2;
  /// A correction farther than this (m) is shown at once, not blended: the
  /// body was somewhere else altogether (teleported, reset).
  double snapDistance = 2;
  /// The server's solver sub-steps (impulse-server --substeps).
  int subSteps = 4;
  /// A body the client's commands named (pushed, dragged, spawned) is
  /// predicted for this many ticks after the last such command.
  std::uint32_t holdTicks = 180;
};

/// One body as the predictor shows it.
struct PredictedBody {
  BodyState state;          ///< predicted, plus what is left of the correction
  Vec2 correction = Vec2::Zero();  ///< the offset still shown (m)
};

/// A spawn the server's snapshot has not brought yet.
struct PredictedSpawn {
  std::uint64_t requestId = 0;
  PredictedBody body;
  BodyDescription description;
};

class Predictor {
 public:
  /// Copies the client's world as its mirror holds it now: the whole room,
  /// or the bodies of its area of interest (commands naming a body outside
  /// go out stamped, unpredicted). Every snapshot must carry every change
  /// of that area: std::invalid_argument names a client without snapshots,
  /// one whose last snapshot withheld states (Snapshot.states_withheld, a
  /// bandwidth budget too small for its area), or an option out of range
  /// (leadTicks 1..Welcome.max_input_delay_ticks, blendPerTick in (0, 1],
  /// snapDistance > 0, subSteps 1..64).
  Predictor(Client& client, const PredictionOptions& options = {});
  ~Predictor();
  Predictor(const Predictor&) = delete;
  Predictor& operator=(const Predictor&) = delete;

  /// Sends `message` stamped for the predicted tick and, for a kind the
  /// copy predicts (pushes, velocities, target transforms, circle and
  /// polygon spawns, joints made, moved, removed), applies it at once.
  /// While the room is paused the command goes unstamped and unpredicted.
  /// Returns the request id (the reply comes as for Client::send).
  std::uint64_t send(v1::ClientMessage message);
  /// Whether send() applies this kind of command to the copy at once (the
  /// others are only sent stamped: a caller may send those unstamped).
  static bool predicts(const v1::ClientMessage& message);
  /// One tick of the caller's clock (Welcome.tick_hz): takes the newest
  /// snapshot the client applied, when there is one, then steps the copy.
  /// A copy running too far ahead of the snapshots waits a tick instead.
  /// Throws PredictionError naming a snapshot that withheld states: any
  /// the client applied since the last call, not only the newest.
  void advance();

  /// The tick the next command is stamped for.
  std::uint64_t tick() const { return tick_; }
  /// The body (server id) as predicted, with the correction still shown;
  /// nothing for a body the copy does not hold.
  std::optional<PredictedBody> body(std::uint32_t serverBody) const;
  /// The body a spawn sent as `requestId` made in the copy, while the
  /// server's snapshot has not brought it yet; nothing once it has (it is
  /// then body(Client::created(requestId)->body), owned, its jump from the
  /// predicted spawn blended as any correction).
  std::optional<PredictedBody> spawned(std::uint64_t requestId) const;
  /// The spawns shown by spawned() now, each with its body as the copy
  /// made it (shapes, material), oldest first.
  std::vector<PredictedSpawn> unmatchedSpawns() const;
  /// Whether the client's own commands named this body lately (holdTicks):
  /// a viewer shows these from the copy and the others as it did.
  bool owns(std::uint32_t serverBody) const;
  /// The bodies owns() holds now, ascending.
  std::vector<std::uint32_t> ownedBodies() const;
  /// Commands sent and not yet in a snapshot.
  std::size_t pending() const { return pending_.size(); }

  /// The largest distance (m) a replay moved an owned body, over the last
  /// snapshot taken and over all of them; and the largest correction still
  /// shown on an owned body.
  double lastCorrection() const { return lastCorrection_; }
  double largestCorrection() const { return largestCorrection_; }
  double shownCorrection() const;
  /// Snapshots taken, and how many of them rebuilt the copy from the mirror
  /// (a body or joint added or removed) instead of replaying from its own
  /// older state.
  std::uint64_t snapshotsTaken() const { return snapshotsTaken_; }
  std::uint64_t rebuilds() const { return rebuilds_; }

 private:
  struct Command {
    std::uint64_t requestId = 0;
    std::uint64_t forTick = 0;
    v1::ClientMessage message;
  };
  struct Offset {
    Vec2 position = Vec2::Zero();
    Real angle = 0;
  };

  /// The body (server id) a command acts on: named, or its joint's body A.
  std::optional<std::uint32_t> bodyNamedBy(const v1::ClientMessage& message) const;
  /// Applies a pending command to the copy; a joint named by tag whose
  /// CreateJoint the server answered is named by the server's id.
  void applyToCopy(const Command& command);
  void rememberTag(const v1::CreateJoint& joint, std::uint64_t requestId);
  /// The server's id of the joint a tag names, once the reply to its
  /// CreateJoint came.
  std::optional<std::uint32_t> taggedJoint(std::uint32_t tag) const;
  /// The pending spawns whose replies named the server's body, with
  /// their bodies' states in the copy (to blend the jump when the
  /// snapshot brings them).
  std::map<std::uint32_t, BodyState> answeredSpawns();
  /// Goes back to the snapshot's tick and replays up to the predicted tick.
  void takeSnapshot(const v1::Snapshot& snapshot);
  /// Forgets the commands the snapshot holds.
  void acknowledge(const v1::Snapshot& snapshot);
  /// A mouse joint's target the server applied: a snapshot describes the
  /// joint with the target it was made with, so a copy rebuilt from the
  /// mirror takes the latest one again (restoreTargets).
  void rememberTarget(const v1::ClientMessage& message);
  void restoreTargets();
  /// The copy at `tick` with the server's states: its own older state when
  /// it kept one that still describes the room, else rebuilt from the mirror.
  void rewindTo(std::uint64_t tick);
  /// Steps the copy from `from` to tick_, applying the pending commands of
  /// each tick (those stamped earlier at the first one).
  void replayFrom(std::uint64_t from);
  /// One step, then the state at the new tick kept for later rewinds.
  void stepOnce();
  /// After a replay: each owned body's jump becomes an offset shown.
  void blendCorrections(const std::map<std::uint32_t, BodyState>& before);
  /// Each shown offset shrinks by blendPerTick; negligible ones go.
  void fadeOffsets();
  std::map<std::uint32_t, BodyState> ownedStates() const;

  Client& client_;
  PredictionOptions options_;
  Real dt_;
  std::unique_ptr<LocalWorld> local_;
  /// The copy's state at each tick not yet covered by a snapshot, before
  /// that tick's commands.
  std::deque<std::pair<std::uint64_t, WorldState>> history_;
  std::deque<Command> pending_;
  std::map<std::uint32_t, Offset> offsets_;
  /// Body (server id) -> the predicted tick of the last command naming it.
  std::map<std::uint32_t, std::uint64_t> touched_;
  /// CreateJoint.tag -> the tagged CreateJoint's request id and body A
  /// (the last kKeptTags tags).
  struct TaggedJoint {
    std::uint64_t requestId = 0;
    std::uint32_t bodyA = 0;
  };
  std::map<std::uint32_t, TaggedJoint> tags_;
  /// Server joint id -> the last UpdateJoint with a target the server applied.
  std::map<std::uint32_t, v1::ClientMessage> targets_;
  static constexpr std::size_t kKeptTags = 64;
  std::uint64_t tick_ = 0;
  std::uint64_t snapshotsSeen_ = 0;
  /// Client::withheldSnapshots().snapshots when the copy last took one.
  std::uint64_t withheldSeen_ = 0;
  std::uint64_t snapshotTick_ = 0;
  double lastCorrection_ = 0;
  double largestCorrection_ = 0;
  std::uint64_t snapshotsTaken_ = 0;
  std::uint64_t rebuilds_ = 0;
};

}  // namespace impulse::client
