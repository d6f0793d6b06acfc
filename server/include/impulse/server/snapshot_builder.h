#pragma once
/// Snapshots of the world as shared, serialised frames.
///
/// Between two broadcasts the builder accumulates which bodies were added,
/// removed or changed; a broadcast serialises one delta frame from that for
/// every subscriber. Full snapshots are built from the world itself and
/// cached until the world changes, so any number of joining or lagging
/// clients in one tick cost one serialisation.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "impulse/scenes/presets.h"
#include "impulse/world.h"

namespace impulse::server {

using SharedFrame = std::shared_ptr<const std::string>;

/// What a snapshot says besides bodies.
struct SnapshotMeta {
  std::uint64_t tick = 0;
  double simTime = 0;
  bool paused = false;
};

class SnapshotBuilder {
 public:
  explicit SnapshotBuilder(const World& world);

  void bodyAdded(BodyId id);
  void bodyRemoved(BodyId id);
  /// The step removed a body for leaving the world bounds far behind: listed
  /// in the next delta's `removed` and `left_world`.
  void bodyLeftWorld(BodyId id);
  /// A state changed outside a step (an impulse while paused).
  void bodyChanged(BodyId id);
  /// After each step: the world's moved bodies.
  void stepped(std::span<const BodyId> moved);
  /// Gravity or another world-wide value changed.
  void worldChanged();
  /// Every body was replaced (clear, preset): the next delta is a full
  /// snapshot, carrying `preset` (the preset in force).
  void worldReplaced(const PresetInfo& preset);

  /// Anything to send since the last takeDelta()?
  bool pending() const { return pending_; }
  /// The changes since the last call, as a ServerMessage frame: a full
  /// snapshot after worldReplaced(). Resets the accumulated changes.
  SharedFrame takeDelta(const SnapshotMeta& meta);
  /// Forgets accumulated changes (nobody subscribes to them).
  void discardPending();
  /// Every body now, as a ServerMessage frame.
  SharedFrame full(const SnapshotMeta& meta);
  const PresetInfo& preset() const { return preset_; }
  /// Changes with every change noted (step, command, replacement).
  std::uint64_t version() const { return version_; }

 private:
  void markDirty();
  void compactChanged();

  const World& world_;
  PresetInfo preset_;
  std::vector<BodyId> added_;
  std::vector<BodyId> removed_;
  std::vector<BodyId> leftWorld_;
  std::vector<BodyId> changed_;
  bool pending_ = false;
  bool replaced_ = false;
  // Full-snapshot cache: valid while no change was noted and meta is equal.
  std::uint64_t version_ = 0;
  std::uint64_t cachedVersion_ = ~std::uint64_t(0);
  SnapshotMeta cachedMeta_;
  SharedFrame cachedFull_;
};

}  // namespace impulse::server
