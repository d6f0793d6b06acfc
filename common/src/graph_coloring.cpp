#include "graph_coloring.h"

#include "counting_sort.h"

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
  ColorStarts start{};
  countingSort(colorOf, start, order);
  return start;
}

}  // namespace impulse
