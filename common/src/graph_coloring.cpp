#include "graph_coloring.h"

#include <algorithm>
#include <bit>

namespace impulse {

int GraphColoring::take(std::int32_t stateA, std::int32_t stateB) {
  std::uint64_t taken = (stateA != 0 ? used_[stateA] : 0) | (stateB != 0 ? used_[stateB] : 0);
  if (taken == ~std::uint64_t(0)) return kOverflow;
  int color = std::countr_one(taken);
  if (stateA != 0) used_[stateA] |= std::uint64_t(1) << color;
  if (stateB != 0) used_[stateB] |= std::uint64_t(1) << color;
  return color;
}

ColorStarts sortByColor(std::span<const std::int32_t> colorOf, std::vector<std::int32_t>& order) {
  // Counting sort: one pass to count, one to place.
  ColorStarts start{};
  for (std::int32_t color : colorOf) ++start[color + 1];
  for (int color = 0; color <= GraphColoring::kOverflow; ++color) start[color + 1] += start[color];
  order.resize(colorOf.size());
  std::array<std::int32_t, GraphColoring::kOverflow + 1> next{};
  std::copy(start.begin(), start.end() - 1, next.begin());
  for (std::size_t i = 0; i < colorOf.size(); ++i) {
    order[next[colorOf[i]]++] = static_cast<std::int32_t>(i);
  }
  return start;
}

}  // namespace impulse
