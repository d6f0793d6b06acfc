#include "impulse/server/world_changes.h"

#include <algorithm>

namespace impulse::server {

namespace {

template <class Id>
void sortUnique(std::vector<Id>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

}  // namespace

void WorldChanges::added(BodyId id) { added_.push_back(id); }

void WorldChanges::removed(BodyId id) { removed_.push_back(id); }

void WorldChanges::jointAdded(JointId id) { jointsAdded_.push_back(id); }

void WorldChanges::jointRemoved(JointId id) { jointsRemoved_.push_back(id); }

void WorldChanges::fieldAdded(FieldId id) { fieldsAdded_.push_back(id); }

void WorldChanges::fieldRemoved(FieldId id) { fieldsRemoved_.push_back(id); }

void WorldChanges::leftWorld(BodyId id) {
  leftWorld_.push_back(id);
  removed(id);
}

void WorldChanges::changed(std::span<const BodyId> ids, int bodyCount) {
  changed_.insert(changed_.end(), ids.begin(), ids.end());
  // Several steps between snapshots repeat the same ids.
  const std::size_t limit = 4 * std::max<std::size_t>(std::size_t(bodyCount), 256);
  if (changed_.size() > limit) sortUnique(changed_);
}

void WorldChanges::replaced() {
  clear();
  replaced_ = true;
}

void WorldChanges::clear() {
  added_.clear();
  removed_.clear();
  leftWorld_.clear();
  changed_.clear();
  jointsAdded_.clear();
  jointsRemoved_.clear();
  fieldsAdded_.clear();
  fieldsRemoved_.clear();
  replaced_ = false;
}

void WorldChanges::normalise() {
  sortUnique(removed_);
  sortUnique(added_);
  sortUnique(jointsAdded_);
  sortUnique(jointsRemoved_);
  changed_.insert(changed_.end(), added_.begin(), added_.end());
  sortUnique(changed_);
}

}  // namespace impulse::server
