#pragma once
/// Snapshots of a simulation as shared, serialised frames.
///
/// A delta serialises the changes the simulation recorded since the last
/// one, once for every subscriber. Full snapshots are built from the world
/// itself and cached until the world changes, so any number of joining or
/// lagging clients in one tick cost one serialisation.

#include <cstdint>
#include <memory>
#include <string>

#include "impulse/server/simulation.h"
#include "impulse/server/world_changes.h"

namespace impulse::server {

using SharedFrame = std::shared_ptr<const std::string>;

class SnapshotBuilder {
 public:
  explicit SnapshotBuilder(const Simulation& simulation);

  /// `changes` as a ServerMessage frame: a full snapshot when the world was
  /// replaced. Normalises `changes` in place.
  SharedFrame delta(WorldChanges& changes);
  /// Every body now, as a ServerMessage frame.
  SharedFrame full();

 private:
  const Simulation& simulation_;
  // Full-snapshot cache: valid while the simulation's version and meta are equal.
  std::uint64_t cachedVersion_ = ~std::uint64_t(0);
  SnapshotMeta cachedMeta_;
  SharedFrame cachedFull_;
};

}  // namespace impulse::server
