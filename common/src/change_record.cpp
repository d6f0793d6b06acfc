#include "change_record.h"

namespace impulse {

void ChangeRecord::mark(BodyChange change, BodyId id) {
  ++revision_;
  if (keepLists_ && !id.isNull()) bodies_[std::size_t(change)].add(id);
}

void ChangeRecord::mark(JointChange change, JointId id) {
  ++revision_;
  if (keepLists_) joints_[std::size_t(change)].add(id);
}

void ChangeRecord::mark(FieldChange change, FieldId id) {
  ++revision_;
  if (keepLists_) fields_[std::size_t(change)].push_back(id);
}

void ChangeRecord::mark(WorldChange change) {
  ++revision_;
  (change == WorldChange::Settings ? settingsChanged_ : originShifted_) = true;
}

void ChangeRecord::stepped(std::span<const BodyId> moved) {
  ++revision_;
  if (!keepLists_) return;
  UniqueIds<BodyId>& listed = bodies_[std::size_t(BodyChange::Moved)];
  for (const BodyId id : moved) listed.add(id);
}

void ChangeRecord::replaced() {
  clear();
  ++revision_;
  replaced_ = true;
}

void ChangeRecord::clear() {
  replaced_ = false;
  settingsChanged_ = false;
  originShifted_ = false;
  for (UniqueIds<BodyId>& ids : bodies_) ids.clear();
  for (UniqueIds<JointId>& ids : joints_) ids.clear();
  for (std::vector<FieldId>& ids : fields_) ids.clear();
}

ChangeView ChangeRecord::view() const {
  auto bodies = [&](BodyChange change) { return bodies_[std::size_t(change)].ids(); };
  auto joints = [&](JointChange change) { return joints_[std::size_t(change)].ids(); };
  auto fields = [&](FieldChange change) {
    return std::span<const FieldId>(fields_[std::size_t(change)]);
  };
  return {.revision = revision_,
          .replaced = replaced_,
          .settingsChanged = settingsChanged_,
          .originShifted = originShifted_,
          .createdBodies = bodies(BodyChange::Created),
          .redescribedBodies = bodies(BodyChange::Redescribed),
          .movedBodies = bodies(BodyChange::Moved),
          .destroyedBodies = bodies(BodyChange::Destroyed),
          .escapedBodies = bodies(BodyChange::Escaped),
          .createdJoints = joints(JointChange::Created),
          .updatedJoints = joints(JointChange::Updated),
          .destroyedJoints = joints(JointChange::Destroyed),
          .addedFields = fields(FieldChange::Added),
          .removedFields = fields(FieldChange::Removed)};
}

}  // namespace impulse
