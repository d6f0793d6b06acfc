#pragma once
// Slot arrays: the engine's elements (bodies, contacts, joints) live in
// vectors whose removed slots are handed out again, last freed first, so an
// array grows only to its peak population and slot order stays
// deterministic. Bodies and joints are named by ids that carry the slot and
// its generation (BodyId, JointId), so a stale id finds nothing.

#include <cstdint>
#include <utility>
#include <vector>

#include "impulse/body.h"

namespace impulse {

class FreeList {
 public:
  /// A freed slot, or `size` (the next new slot) when none is free; the
  /// caller grows its arrays when it gets `size`.
  std::int32_t acquire(std::size_t size) {
    if (free_.empty()) return static_cast<std::int32_t>(size);
    std::int32_t slot = free_.back();
    free_.pop_back();
    return slot;
  }
  void release(std::int32_t slot) { free_.push_back(slot); }
  /// Free slots, the next one handed out last (for saving a world).
  const std::vector<std::int32_t>& slots() const { return free_; }
  /// Replaces the free slots (the caller has checked them).
  void assign(std::vector<std::int32_t> slots) { free_ = std::move(slots); }

 private:
  std::vector<std::int32_t> free_;
};

/// The live element `id` names (slot in range, alive, same generation), or
/// null. Elements have `alive` and `generation`; ids have slot(),
/// generation() and isNull(), with BodyId's generation bits.
template <class Elements, class Id>
auto findLive(Elements& elements, Id id) -> decltype(&elements[0]) {
  const std::int32_t slot = id.slot();
  if (id.isNull() || slot < 0 || slot >= static_cast<std::int32_t>(elements.size())) return nullptr;
  auto& element = elements[std::size_t(slot)];
  if (!element.alive || (element.generation & BodyId::kGenerationMask) != id.generation()) {
    return nullptr;
  }
  return &element;
}

/// The ids of every live element, in slot order (`count` of them).
template <class Id, class Elements>
std::vector<Id> liveIds(const Elements& elements, int count) {
  std::vector<Id> ids;
  ids.reserve(std::size_t(count));
  for (std::size_t slot = 0; slot < elements.size(); ++slot) {
    if (elements[slot].alive) ids.push_back(Id::make(std::int32_t(slot), elements[slot].generation));
  }
  return ids;
}

}  // namespace impulse
