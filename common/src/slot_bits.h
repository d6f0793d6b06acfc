#pragma once
// A set of slots, one bit each. Membership changes in O(1) and a walk visits
// the members in slot order, so it reads the slots' arrays in sequence
// instead of wherever a linked list leads, and its order depends only on
// which slots are members (a restored world walks as the saved one).

#include <bit>
#include <cstdint>
#include <vector>

namespace impulse {

class SlotBits {
 public:
  void insert(std::int32_t slot) {
    const auto word = static_cast<std::size_t>(slot) / kBits;
    if (word >= words_.size()) words_.resize(word + 1, 0);
    words_[word] |= bit(slot);
  }
  void erase(std::int32_t slot) {
    const auto word = static_cast<std::size_t>(slot) / kBits;
    if (word < words_.size()) words_[word] &= ~bit(slot);
  }

  /// Calls visit(slot) for every member, highest slot first. Members
  /// inserted or erased during the walk are seen or missed depending on
  /// where they lie; walk a copy (assign) where that matters.
  template <class Visit>
  void forEachDescending(Visit&& visit) const {
    forEachDescendingExcept(SlotBits{}, visit);
  }
  /// The same walk over the members that `excluded` does not have.
  template <class Visit>
  void forEachDescendingExcept(const SlotBits& excluded, Visit&& visit) const {
    for (std::size_t word = words_.size(); word-- > 0;) {
      std::uint64_t bits = words_[word];
      if (word < excluded.words_.size()) bits &= ~excluded.words_[word];
      while (bits != 0) {
        const int high = kTopBit - std::countl_zero(bits);
        bits &= ~(std::uint64_t{1} << high);
        visit(static_cast<std::int32_t>(word * kBits + static_cast<std::size_t>(high)));
      }
    }
  }
  /// Becomes a copy of `other`, reusing this set's storage.
  void assign(const SlotBits& other) { words_.assign(other.words_.begin(), other.words_.end()); }

 private:
  static constexpr std::size_t kBits = 64;
  static constexpr int kTopBit = 63;
  static std::uint64_t bit(std::int32_t slot) {
    return std::uint64_t{1} << (static_cast<std::uint32_t>(slot) % kBits);
  }

  std::vector<std::uint64_t> words_;
};

}  // namespace impulse
