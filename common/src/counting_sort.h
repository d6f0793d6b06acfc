#pragma once
// A stable counting sort of positions by small integer keys, in linear time:
// the solver orders its constraints by colour and the narrow phase its
// touching contacts by body this way. And the positions that pass a test,
// listed without a branch on it.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

namespace impulse {

/// Fills `order` with the positions 0..n-1 of `keys`, sorted by key, ties in
/// position order. `starts` (one entry per possible key, plus one) receives
/// where each key's positions begin: key k holds [starts[k], starts[k + 1]).
inline void countingSort(std::span<const std::int32_t> keys, std::span<std::int32_t> starts,
                         std::vector<std::int32_t>& order) {
  std::fill(starts.begin(), starts.end(), 0);
  for (const std::int32_t key : keys) ++starts[static_cast<std::size_t>(key)];
  // Each entry becomes where its key ends; placing from the back then moves
  // it to where its key begins, and keeps ties in order.
  std::partial_sum(starts.begin(), starts.end(), starts.begin());
  order.resize(keys.size());
  for (std::size_t i = keys.size(); i-- > 0;) {
    order[static_cast<std::size_t>(--starts[static_cast<std::size_t>(keys[i])])] = static_cast<std::int32_t>(i);
  }
}

/// The inverse of an order: place[order[k]] = k, each entry's position in
/// the sorted order. Writing entries to their places while reading them in
/// their own order costs far less than reading them in the sorted order.
inline void placesInOrder(std::span<const std::int32_t> order, std::vector<std::int32_t>& place) {
  place.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) place[static_cast<std::size_t>(order[k])] = static_cast<std::int32_t>(k);
}

/// The positions i in [0, count) where takes(i), in order, into `list`,
/// without a branch on takes(i): where the test is a coin toss (whether a
/// crowd's contact is level, whether a bundle may bounce), the loops that
/// branched on it mispredicted about half the time.
template <class Takes>
void listWhere(std::size_t count, Takes&& takes, std::vector<std::int32_t>& list) {
  list.resize(count);
  std::size_t listed = 0;
  for (std::size_t i = 0; i < count; ++i) {
    list[listed] = static_cast<std::int32_t>(i);
    listed += takes(i) ? 1 : 0;
  }
  list.resize(listed);
}

}  // namespace impulse
