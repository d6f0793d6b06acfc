#pragma once
/// What changed in a world since the changes were last taken: the input of
/// the snapshot builder. The Simulation keeps it as it changes the world, so
/// no change can reach a world without reaching the next snapshot.

#include <span>
#include <vector>

#include "impulse/body.h"
#include "impulse/field.h"
#include "impulse/joint.h"

namespace impulse::server {

class WorldChanges {
 public:
  void added(BodyId id);
  /// Listed even if added since the last take: a client that joined in
  /// between got the body in its full snapshot.
  void removed(BodyId id);
  /// Removed by the step for leaving the world bounds far behind: listed in
  /// the next delta's `removed` and `left_world`.
  void leftWorld(BodyId id);
  /// States changed (a step's moved bodies, an impulse while paused);
  /// `bodyCount` bounds the list however many steps pass between takes.
  void changed(std::span<const BodyId> ids, int bodyCount);
  void jointAdded(JointId id);
  /// Listed even if added since the last take, as bodies are; joints that
  /// went with their bodies are listed here too.
  void jointRemoved(JointId id);
  void fieldAdded(FieldId id);
  /// A field added and removed between takes is listed here only (the
  /// snapshot describes fields the world still has).
  void fieldRemoved(FieldId id);
  /// Every body was replaced (clear, preset): the next snapshot is full.
  void replaced();
  bool wasReplaced() const { return replaced_; }
  /// Forgets every change, keeping the lists' capacity.
  void clear();
  /// Each list sorted, without repeats; `changed` includes `added`.
  void normalise();
  const std::vector<BodyId>& addedIds() const { return added_; }
  const std::vector<BodyId>& removedIds() const { return removed_; }
  const std::vector<BodyId>& leftWorldIds() const { return leftWorld_; }
  const std::vector<BodyId>& changedIds() const { return changed_; }
  const std::vector<JointId>& addedJointIds() const { return jointsAdded_; }
  const std::vector<JointId>& removedJointIds() const { return jointsRemoved_; }
  const std::vector<FieldId>& addedFieldIds() const { return fieldsAdded_; }
  const std::vector<FieldId>& removedFieldIds() const { return fieldsRemoved_; }

 private:
  std::vector<BodyId> added_;
  std::vector<BodyId> removed_;
  std::vector<BodyId> leftWorld_;
  std::vector<BodyId> changed_;
  std::vector<JointId> jointsAdded_;
  std::vector<JointId> jointsRemoved_;
  std::vector<FieldId> fieldsAdded_;
  std::vector<FieldId> fieldsRemoved_;
  bool replaced_ = false;
};

}  // namespace impulse::server
