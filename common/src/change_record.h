#pragma once
// The world's one record of what changed since its changes were last
// cleared (World::changes). Every edit path and the step mark what they
// change here, so a reader learns it in one place instead of wrapping each
// call. A mark is an append, after a check that the id is not listed yet;
// a world nobody reads the changes of keeps no lists (keepLists).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "impulse/change_view.h"

namespace impulse {

/// Ids listed once each. A mark per slot holds the id of that slot that is
/// listed, so a slot reused by a new body (another generation) lists the
/// new id beside the old one.
template <class Id>
class UniqueIds {
 public:
  void add(Id id) {
    const auto slot = static_cast<std::size_t>(id.slot());
    if (slot >= listed_.size()) listed_.resize(slot + 1, 0);
    if (listed_[slot] == id.value) return;
    listed_[slot] = id.value;
    ids_.push_back(id);
  }
  /// Keeps the capacity, so a record cleared every snapshot stops allocating.
  void clear() {
    for (const Id id : ids_) listed_[static_cast<std::size_t>(id.slot())] = 0;
    ids_.clear();
  }
  std::span<const Id> ids() const { return ids_; }

 private:
  std::vector<Id> ids_;
  std::vector<std::uint32_t> listed_;
};

enum class BodyChange { Created, Redescribed, Moved, Destroyed, Escaped, Count };
enum class JointChange { Created, Updated, Destroyed, Count };
enum class FieldChange { Added, Removed, Count };
enum class WorldChange { Settings, Origin };

class ChangeRecord {
 public:
  /// Off (the default), a mark only moves the revision: a world nobody
  /// mirrors keeps no lists, which would otherwise grow with every body
  /// ever made.
  void keepLists(bool on) { keepLists_ = on; }
  /// A null id (a joint's missing second body) marks nothing.
  void mark(BodyChange change, BodyId id);
  void mark(JointChange change, JointId id);
  void mark(FieldChange change, FieldId id);
  void mark(WorldChange change);
  /// A step: what it moved. Its removals were marked as they happened.
  void stepped(std::span<const BodyId> moved);
  /// The contents were replaced: every list is dropped.
  void replaced();
  /// Forgets every change; the revision stays.
  void clear();
  ChangeView view() const;

 private:
  std::uint64_t revision_ = 0;
  bool keepLists_ = false;
  bool replaced_ = false;
  bool settingsChanged_ = false;
  bool originShifted_ = false;
  std::array<UniqueIds<BodyId>, std::size_t(BodyChange::Count)> bodies_;
  std::array<UniqueIds<JointId>, std::size_t(JointChange::Count)> joints_;
  // Field ids are never reused, so each is marked once of each kind.
  std::array<std::vector<FieldId>, std::size_t(FieldChange::Count)> fields_;
};

}  // namespace impulse
