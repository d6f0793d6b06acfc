#pragma once
/// Snapshots of a simulation as shared, serialised frames.
///
/// A delta serialises the changes the simulation recorded since the last
/// one, once for every subscriber. Full snapshots are built from the world
/// itself and cached until the world changes, so any number of joining or
/// lagging clients in one tick cost one serialisation.
///
/// Quantized snapshots (docs/snapshots.md) come from one encoder per room:
/// every subscriber that took the previous broadcast holds the same baseline,
/// so a quantized delta too is serialised once for all of them; a subscriber
/// that joins or skips gets a key frame, cached like the full snapshot.
///
/// Personal snapshots (personal_stream.h) are built for one subscriber each,
/// from the places of the bodies taken once per broadcast.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "impulse/server/interest_area.h"
#include "impulse/server/personal_stream.h"
#include "impulse/server/simulation.h"
#include "impulse/server/world_changes.h"
#include "impulse/wire/quantized_encoder.h"

namespace impulse::server {

using SharedFrame = std::shared_ptr<const std::string>;
/// Per client, the request id of its last stamped command the room processed.
using AppliedStamps = std::map<std::uint32_t, std::uint64_t>;

class SnapshotBuilder {
 public:
  explicit SnapshotBuilder(const Simulation& simulation);

  /// The room processed `client`'s stamped command `requestId` (applied or
  /// refused at its tick): every later snapshot lists it in applied_stamps,
  /// so a predicting client knows which of its commands the state holds.
  void stampProcessed(std::uint32_t client, std::uint64_t requestId);
  /// The client left: its entry is listed no more.
  void forgetClient(std::uint32_t client);

  /// `changes` as a ServerMessage frame: a full snapshot when the world was
  /// replaced. Normalises `changes` in place.
  SharedFrame delta(WorldChanges& changes);
  /// Every body now, as a ServerMessage frame.
  SharedFrame full();

  /// The same changes for SNAPSHOT_ENCODING_QUANTIZED subscribers, coded
  /// against the previous quantized broadcast (with or without delta()).
  /// Normalises `changes` in place.
  SharedFrame quantizedDelta(WorldChanges& changes);
  /// Every body for a quantized subscriber: a key frame whose states are the
  /// ones the last quantized delta left, so the next delta applies to it.
  SharedFrame quantizedFull();
  /// No quantized subscriber took this broadcast: the baseline is stale, and
  /// the next quantized snapshot starts over from the world.
  void skipQuantized() { encoder_.forget(); }

  /// Takes the bodies' places for this broadcast's personal snapshots;
  /// `changes` is normalised.
  void updatePlaces(const WorldChanges& changes);
  /// Takes the bodies' places now, between broadcasts (for a full personal snapshot).
  void refreshPlaces();
  /// No personal snapshot this broadcast: the places kept lapse.
  void forgetPlaces() { placesCurrent_ = false; }
  /// The stream's next snapshot after updatePlaces(): a delta, or a full
  /// one when the stream starts over or the world was replaced.
  SharedFrame personalDelta(PersonalStream& stream, const WorldChanges& changes);
  /// Every body in the stream's area, as a full snapshot.
  SharedFrame personalFull(PersonalStream& stream);

 private:
  void startQuantized();
  /// Adds the plan's ranked states, highest first, while the `allowance`
  /// (bytes; none: no budget) lasts; returns how many.
  std::size_t addRankedStates(const PersonalDelta& plan, std::optional<double> allowance, v1::Snapshot* snapshot);

  const Simulation& simulation_;
  // Full-snapshot cache: valid while the simulation's version and meta are equal.
  std::uint64_t cachedVersion_ = ~std::uint64_t(0);
  AppliedStamps appliedStamps_;
  /// Changes with appliedStamps_: the cached frames list them too.
  std::uint64_t stampsVersion_ = 0;
  std::uint64_t cachedStampsVersion_ = 0;
  SnapshotMeta cachedMeta_;
  SharedFrame cachedFull_;
  wire::quantized::Encoder encoder_;
  std::vector<std::uint32_t> changedIds_;
  // Key-frame cache: valid while version, meta and the encoder's generation are equal.
  std::uint64_t cachedKeyVersion_ = ~std::uint64_t(0);
  std::uint64_t cachedKeyGeneration_ = ~std::uint64_t(0);
  std::uint64_t cachedKeyStampsVersion_ = 0;
  SnapshotMeta cachedKeyMeta_;
  SharedFrame cachedKey_;
  BodyPlaces places_;
  /// places_ followed every broadcast's changes up to now.
  bool placesCurrent_ = false;
};

}  // namespace impulse::server
