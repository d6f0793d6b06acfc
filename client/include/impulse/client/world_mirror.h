#pragma once
/// A client's copy of the server's world, kept current by applying snapshots
/// in the order they arrive. Its positions are floats relative to its
/// origin (the room's, Welcome.world_origin: Client sets it), so a room far
/// from (0, 0) keeps the precision the wire's doubles bring.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "impulse.pb.h"
#include "impulse/body.h"
#include "impulse/field_kinds.h"
#include "impulse/joint.h"
#include "impulse/material.h"
#include "impulse/scenes/presets.h"
#include "impulse/shape.h"
#include "impulse/wire/quantized_decoder.h"

namespace impulse::client {

/// One body as the server described it, with its latest state.
struct MirrorBody {
  BodyId id;
  Shape shape;  ///< body-local (its origin the body's centre of mass)
  /// A compound body's further shapes, body-local.
  std::vector<Shape> extraShapes;
  Material material = Material::Solid;
  bool isStatic = false;
  bool isKinematic = false;
  bool ignoreGravity = false;
  /// The first shape's filter, sensor flag and events.
  ShapeInteraction flags;
  /// Every shape's id (events name them), in the order shape, extraShapes.
  std::vector<std::uint32_t> shapeIds;
  BodyState state;
};

class WorldMirror {
 public:
  /// Applies one snapshot: a full one replaces everything; a delta removes
  /// (bodies removed, or out of the client's area of interest), then adds
  /// (or replaces) descriptors, then sets states (from `bodies`,
  /// or decoded from `quantized_bodies`, docs/snapshots.md). On a malformed
  /// snapshot (a shape that does not decode, a state for an unknown body)
  /// returns false with the reason; bodies already applied stay applied.
  bool apply(const v1::Snapshot& snapshot, std::string* error = nullptr);

  /// Positions of the snapshots applied from now on are kept relative to
  /// `origin` (metres from (0, 0)); set it before the first snapshot.
  void setOrigin(const Vec2d& origin);
  const Vec2d& origin() const { return origin_; }
  /// A position of this mirror, from (0, 0); and one from (0, 0), relative
  /// to the origin (as commands and the wire give them).
  Vec2d toGlobal(const Vec2& position) const { return origin_ + position.cast<double>(); }
  Vec2 toLocal(const Vec2d& point) const { return (point - origin_).cast<Real>(); }

  /// Bodies by id (ascending).
  const std::map<std::uint32_t, MirrorBody>& bodies() const { return bodies_; }
  const MirrorBody* find(BodyId id) const;
  /// Joints by id (ascending), as the server described them.
  const std::map<std::uint32_t, JointDescription>& joints() const { return joints_; }
  /// Fields by id (ascending), as the server described them.
  const std::map<std::uint32_t, FieldDef>& fields() const { return fields_; }

  std::uint64_t tick() const { return tick_; }
  double simTime() const { return simTime_; }
  Vec2 gravity() const { return gravity_; }
  bool paused() const { return paused_; }
  /// Simulated seconds per wall second (1 from a server that sends none).
  double timeScale() const { return timeScale_; }
  /// The preset of the last full snapshot, once one arrived.
  const std::optional<PresetInfo>& preset() const { return preset_; }
  std::uint64_t snapshotsApplied() const { return snapshotsApplied_; }

 private:
  std::map<std::uint32_t, MirrorBody> bodies_;
  std::map<std::uint32_t, JointDescription> joints_;
  std::map<std::uint32_t, FieldDef> fields_;
  std::uint64_t tick_ = 0;
  double simTime_ = 0;
  Vec2 gravity_ = Vec2::Zero();
  bool paused_ = false;
  double timeScale_ = 1;
  std::optional<PresetInfo> preset_;
  std::uint64_t snapshotsApplied_ = 0;
  wire::quantized::Decoder decoder_;
  std::vector<BodyState> decoded_;
  std::vector<std::uint32_t> addedIds_;

  Vec2d origin_ = Vec2d::Zero();

  /// apply(), the snapshot's positions relative to the origin.
  bool applyRelative(const v1::Snapshot& snapshot, std::string* error);
  std::optional<std::string> applyQuantized(const v1::Snapshot& snapshot);
};

}  // namespace impulse::client
