#pragma once
/// What changed in a world since the changes were last taken, as the
/// snapshot builder reads it: the world's own change record
/// (World::changes) in snapshot terms.

#include <vector>

#include "impulse/body.h"
#include "impulse/change_view.h"
#include "impulse/field.h"
#include "impulse/joint.h"

namespace impulse::server {

class WorldChanges {
 public:
  /// Replaces these lists with the world's changes: a body created or
  /// redescribed is `added` (Snapshot.added replaces a client's descriptor),
  /// a joint created or updated is in `addedJointIds`, and a body that left
  /// the world is in `removed` and `leftWorld`.
  void assign(const ChangeView& world);
  /// Every body was replaced (clear, preset, scene): the next snapshot is full.
  bool wasReplaced() const { return replaced_; }
  /// Each list sorted, without repeats; `changed` includes `added`.
  void normalise();
  const std::vector<BodyId>& addedIds() const { return added_; }
  /// Listed even if added since the last take: a client that joined in
  /// between got the body in its full snapshot.
  const std::vector<BodyId>& removedIds() const { return removed_; }
  const std::vector<BodyId>& leftWorldIds() const { return leftWorld_; }
  const std::vector<BodyId>& changedIds() const { return changed_; }
  const std::vector<JointId>& addedJointIds() const { return jointsAdded_; }
  /// Listed even if added since the last take, as bodies are; joints that
  /// went with their bodies are listed here too.
  const std::vector<JointId>& removedJointIds() const { return jointsRemoved_; }
  const std::vector<FieldId>& addedFieldIds() const { return fieldsAdded_; }
  /// A field added and removed between takes is in both lists; the
  /// snapshot describes only fields the world still has.
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
