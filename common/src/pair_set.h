#pragma once
// The set of shape pairs that have a contact (contactPairKey values), looked
// up for every overlap the broad phase finds: in a churning pile that is
// most of the pair search. Open addressing with linear probing in one array,
// so a lookup is usually one cache line where a node-based set chases a
// pointer per bucket.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impulse {

class PairSet {
 public:
  /// Whether the key is in the set. Safe from several threads at once while
  /// nothing inserts or erases.
  bool contains(std::uint64_t key) const;
  /// Starts loading the slot where contains(key) begins its search.
  void prefetch(std::uint64_t key) const;
  /// Adds the key; false when it was there already. Keys are never 0 (a
  /// pair's two shapes differ).
  bool insert(std::uint64_t key);
  /// Removes the key if present.
  void erase(std::uint64_t key);
  std::size_t size() const { return size_; }

 private:
  static constexpr std::uint64_t kEmpty = 0;

  std::size_t home(std::uint64_t key) const;
  std::size_t next(std::size_t slot) const { return (slot + 1) & (slots_.size() - 1); }
  void grow();

  std::vector<std::uint64_t> slots_;  // a power of two long, at most half full
  std::size_t size_ = 0;
};

}  // namespace impulse
