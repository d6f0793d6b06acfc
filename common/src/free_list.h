#pragma once
// Slot reuse for the engine's arrays (bodies, contacts; joints tomorrow):
// removed slots are handed out again, last freed first, so an array grows
// only to its peak population and slot order stays deterministic.

#include <cstdint>
#include <vector>

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

 private:
  std::vector<std::int32_t> free_;
};

}  // namespace impulse
