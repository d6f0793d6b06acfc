#pragma once
// Union-find forests kept as parent arrays (a root is its own parent).
// Two ways to use one: any root, found with unionFindRoot (the stacks of the
// support pass and the joint tree pass's groups, whose roots name them), or
// roots that are each set's lowest item, joined with joinBelow and read
// with flattenBelow in one pass (the push pass's islands: 3-4 times faster
// on a crowd, where the partition alone is read).

#include <cstdint>
#include <utility>
#include <vector>

namespace impulse {

inline std::int32_t unionFindRoot(std::vector<std::int32_t>& parent, std::int32_t item) {
  while (parent[std::size_t(item)] != item) {
    parent[std::size_t(item)] = parent[std::size_t(parent[std::size_t(item)])];
    item = parent[std::size_t(item)];
  }
  return item;
}

/// Joins the sets of a and b in a forest where no parent's index exceeds
/// its child's (Rem's union-find with splicing): each step hooks the item
/// with the higher parent onto the lower parent, which keeps that order and
/// shortens the paths it walks.
inline void joinBelow(std::vector<std::int32_t>& parent, std::int32_t a, std::int32_t b) {
  while (parent[std::size_t(a)] != parent[std::size_t(b)]) {
    if (parent[std::size_t(a)] < parent[std::size_t(b)]) std::swap(a, b);
    const std::int32_t above = parent[std::size_t(a)];
    parent[std::size_t(a)] = parent[std::size_t(b)];
    if (above == a) return;
    a = above;
  }
}

/// Points every item of a joinBelow forest at its root, its set's lowest
/// item: one pass in index order, a parent's entry already holding its root.
inline void flattenBelow(std::vector<std::int32_t>& parent) {
  for (std::size_t item = 0; item < parent.size(); ++item) parent[item] = parent[std::size_t(parent[item])];
}

}  // namespace impulse
