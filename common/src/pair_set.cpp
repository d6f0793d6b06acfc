#include "pair_set.h"

#include <algorithm>
#include <bit>
#include <utility>

#include "prefetch.h"

namespace impulse {

namespace {
constexpr std::size_t kMinSlots = 64;
}  // namespace

// Fibonacci hashing: the multiply spreads keys that differ in any bit over
// the high bits, which pick the slot.
std::size_t PairSet::home(std::uint64_t key) const {
  const int shift = 64 - std::countr_zero(slots_.size());
  return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift);
}

bool PairSet::contains(std::uint64_t key) const {
  if (slots_.empty()) return false;
  for (std::size_t slot = home(key);; slot = next(slot)) {
    if (slots_[slot] == key) return true;
    if (slots_[slot] == kEmpty) return false;
  }
}

void PairSet::prefetch(std::uint64_t key) const {
  if (!slots_.empty()) fetchLines(&slots_[home(key)]);
}

bool PairSet::insert(std::uint64_t key) {
  if (2 * (size_ + 1) > slots_.size()) grow();
  std::size_t slot = home(key);
  for (; slots_[slot] != kEmpty; slot = next(slot)) {
    if (slots_[slot] == key) return false;
  }
  slots_[slot] = key;
  ++size_;
  return true;
}

// Backward-shift deletion: the keys after the hole that could sit in it move
// back, so a probe never stops early at a hole and no tombstones build up.
void PairSet::erase(std::uint64_t key) {
  if (slots_.empty()) return;
  std::size_t hole = home(key);
  for (; slots_[hole] != key; hole = next(hole)) {
    if (slots_[hole] == kEmpty) return;
  }
  for (std::size_t slot = next(hole); slots_[slot] != kEmpty; slot = next(slot)) {
    // The key at `slot` may fill the hole when its home is not cyclically in
    // (hole, slot].
    const std::size_t wanted = home(slots_[slot]);
    const bool homeAfterHole = hole <= slot ? (hole < wanted && wanted <= slot) : (hole < wanted || wanted <= slot);
    if (homeAfterHole) continue;
    slots_[hole] = slots_[slot];
    hole = slot;
  }
  slots_[hole] = kEmpty;
  --size_;
}

void PairSet::grow() {
  std::vector<std::uint64_t> old = std::exchange(slots_, std::vector<std::uint64_t>(std::max(kMinSlots, 2 * slots_.size()), kEmpty));
  size_ = 0;
  for (std::uint64_t key : old) {
    if (key != kEmpty) insert(key);
  }
}

}  // namespace impulse
