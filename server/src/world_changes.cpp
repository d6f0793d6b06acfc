#include "impulse/server/world_changes.h"

#include <algorithm>
#include <span>

namespace impulse::server {

namespace {

template <class Id>
void sortUnique(std::vector<Id>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// Keeps the list's capacity, so a broadcast allocates no new lists.
template <class Id>
void assignUnion(std::vector<Id>& list, std::span<const Id> first,
                 std::span<const Id> second = {}) {
  list.assign(first.begin(), first.end());
  list.insert(list.end(), second.begin(), second.end());
}

}  // namespace

void WorldChanges::assign(const ChangeView& world) {
  assignUnion(added_, world.createdBodies, world.redescribedBodies);
  assignUnion(removed_, world.destroyedBodies);
  assignUnion(leftWorld_, world.escapedBodies);
  assignUnion(changed_, world.movedBodies);
  assignUnion(jointsAdded_, world.createdJoints, world.updatedJoints);
  assignUnion(jointsRemoved_, world.destroyedJoints);
  assignUnion(fieldsAdded_, world.addedFields);
  assignUnion(fieldsRemoved_, world.removedFields);
  replaced_ = world.replaced;
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
