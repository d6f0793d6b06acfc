#pragma once
/// What changed in a World since its changes were last cleared
/// (World::changes, World::clearChanges): what a reader that mirrors the
/// world (the server's snapshots, a game's renderer) must read again.

#include <cstdint>
#include <span>

#include "impulse/body.h"
#include "impulse/field.h"
#include "impulse/joint.h"

namespace impulse {

/// Spans into the world's memory, valid until the next non-const call on
/// it. Each list names an id at most once, in the order it was first
/// marked; an id may be in several lists (a body created, moved and
/// destroyed since the last clear is in all three). Bodies an edit wakes
/// as a side effect (what touched a teleported body, every body when
/// gravity changes) are listed by the next step, which moves them.
struct ChangeView {
  /// Moves with every change and every step, never goes back (not when the
  /// changes are cleared, nor when the world is cleared, loaded or assigned
  /// another): equal revisions name the same state of this world.
  std::uint64_t revision = 0;
  /// The world's contents were replaced (clear, importState, a World moved
  /// into it) and the lists dropped: read it whole. What changed after the
  /// replacement is listed as usual.
  bool replaced = false;
  /// setGravity or setSettings.
  bool settingsChanged = false;
  /// shiftOrigin: every position given relative to the origin (bodies,
  /// joint targets, built-in fields) is new. Its bodies are in movedBodies.
  bool originShifted = false;

  std::span<const BodyId> createdBodies;
  /// Their description changed (shapes added or removed, material, type,
  /// shape filters and flags); their mass and centre may have too.
  std::span<const BodyId> redescribedBodies;
  /// Their state (BodyState) changed: moved by a step (World::movedBodies),
  /// or set by an edit (teleport, velocity, impulse, force, target
  /// transform, a joint made or removed between them and another body).
  /// May name bodies destroyed since: they are in destroyedBodies too.
  std::span<const BodyId> movedBodies;
  /// destroyBody's and the step's removals (escapedBodies included).
  std::span<const BodyId> destroyedBodies;
  /// Removed by a step for leaving the bounds far behind (also destroyed).
  std::span<const BodyId> escapedBodies;

  std::span<const JointId> createdJoints;
  /// updateJoint: a motor's speed or force, a mouse target.
  std::span<const JointId> updatedJoints;
  /// destroyJoint's, and the joints that went with their bodies.
  std::span<const JointId> destroyedJoints;

  std::span<const FieldId> addedFields;
  std::span<const FieldId> removedFields;
};

}  // namespace impulse
