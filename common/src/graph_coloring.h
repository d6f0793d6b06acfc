#pragma once
// Graph colouring of the step's constraints, every kind together: no two
// constraints of one colour share an awake body, so the constraints of a
// colour can be solved side by side (SIMD lanes today, threads tomorrow)
// without one overwriting another's body. Static and sleeping bodies (solver
// state 0) never block a colour.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace impulse {

class GraphColoring {
 public:
  static constexpr int kColorCount = 64;  // one bit each in a per-body mask
  /// The colour of a constraint that found none free: solved one by one.
  static constexpr int kOverflow = kColorCount;

  /// Starts a step with `stateCount` solver states, every colour free.
  void reset(std::size_t stateCount) { used_.assign(stateCount, 0); }

  /// The lowest colour free at both states, now taken there; kOverflow when
  /// every colour is taken.
  int take(std::int32_t stateA, std::int32_t stateB);

 private:
  std::vector<std::uint64_t> used_;
};

/// Where each colour's constraints start in an order sorted by colour
/// (overflow last): colour c holds [start[c], start[c + 1]).
using ColorStarts = std::array<std::int32_t, GraphColoring::kColorCount + 2>;

/// Sorts constraint positions by colour, stable within a colour so the row
/// order stays deterministic: `order` receives the positions of colorOf.
ColorStarts sortByColor(std::span<const std::int32_t> colorOf, std::vector<std::int32_t>& order);

/// How many colours a walk through them visits: up to the last that holds
/// anything. `starts[c]` is where colour c starts and starts[kOverflow] where
/// the coloured items end (a ColorStarts, or the same cut into bundles).
/// Colours start in order, so from the first that starts at that end, every
/// colour is empty.
inline int coloursTaken(std::span<const std::int32_t> starts) {
  const std::int32_t colouredEnd = starts[GraphColoring::kOverflow];
  int colours = 0;
  while (colours < GraphColoring::kOverflow && starts[std::size_t(colours)] < colouredEnd) ++colours;
  return colours;
}

}  // namespace impulse
