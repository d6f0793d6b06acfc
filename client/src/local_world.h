#pragma once
/// A client's own engine world, built from its WorldMirror: the bodies,
/// joints and fields the server described, under ids of its own. It knows
/// which of its ids stand for which of the server's, and applies to itself
/// the commands a Predictor predicts, named by the server's ids.

#include <cstdint>
#include <map>
#include <optional>

#include "impulse.pb.h"
#include "impulse/client/world_mirror.h"
#include "impulse/world.h"

namespace impulse::client {

class LocalWorld {
 public:
  explicit LocalWorld(const WorldSettings& settings) : settings_(settings), world_(settings) {}

  /// Starts over from the mirror: every body in its latest state, every
  /// joint (anchored where the bodies are now) and field, the gravity, the
  /// origin (positions relative to the mirror's).
  void rebuild(const WorldMirror& mirror);
  /// Every mirror body this world knows takes the mirror's pose and
  /// velocity (after this world went back to an older state of its own).
  void takeStates(const WorldMirror& mirror);
  /// The mirror holds the bodies and joints this world was built from, no
  /// more and no fewer (a body or joint added or removed since needs a
  /// rebuild).
  bool describes(const WorldMirror& mirror) const;
  /// Bodies and joints made here by predicted commands, not (yet) the
  /// server's.
  int predictedBodies() const { return world_.bodyCount() - int(bodies_.size()); }
  int predictedJoints() const { return world_.jointCount() - int(joints_.size()); }

  /// Applies a command (its positions from (0, 0), as sent) of a predicted
  /// kind (pushes, velocities, target
  /// transforms, circle and polygon spawns, joints made, moved and removed)
  /// for a step of `dt`. False for any other kind and for a command the
  /// world refuses or whose ids it does not know: it changes nothing.
  /// A spawn's body is kept under `requestId` (localSpawn), a tagged
  /// joint's under its tag (CreateJoint.tag, which UpdateJoint and
  /// RemoveJoint may name), until the next rebuild or takeStates.
  bool apply(const v1::ClientMessage& message, Real dt, std::uint64_t requestId = 0);
  /// Whether apply() predicts this kind of command.
  static bool predictsKind(const v1::ClientMessage& message);
  /// The server's id of the body the command names (nothing for a spawn
  /// and for commands naming a joint).
  static std::optional<std::uint32_t> namedBody(const v1::ClientMessage& message);

  World& world() { return world_; }
  const World& world() const { return world_; }
  std::optional<BodyId> localBody(std::uint32_t serverBody) const;
  std::optional<JointId> localJoint(std::uint32_t serverJoint) const;
  /// The body a predicted spawn sent as `requestId` made here.
  std::optional<BodyId> localSpawn(std::uint64_t requestId) const;

 private:
  bool applyJoint(const v1::ClientMessage& message);
  bool spawned(const CreateResult& made, std::uint64_t requestId);
  /// The joint an UpdateJoint or RemoveJoint names: by id, or by the tag a
  /// predicted CreateJoint gave it here.
  std::optional<JointId> namedJoint(std::uint32_t serverJoint, std::uint32_t tag) const;
  /// Forgets the bodies and joints predicted commands made (their
  /// commands are replayed onto the new state).
  void forgetPredictions();

  WorldSettings settings_;
  World world_;
  /// Server id -> this world's id, for the bodies and joints of the mirror.
  std::map<std::uint32_t, BodyId> bodies_;
  std::map<std::uint32_t, JointId> joints_;
  /// Made here by predicted commands: spawns by request id, joints by tag.
  std::map<std::uint64_t, BodyId> spawns_;
  std::map<std::uint32_t, JointId> taggedJoints_;
};

}  // namespace impulse::client
