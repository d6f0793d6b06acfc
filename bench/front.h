#pragma once
// The speed-against-error front of one scene: the settings no other setting
// beats on both ms/step (median) and headline error.

#include <vector>

#include "runner.h"

namespace bench {

/// The Pareto-optimal runs among `results`, fastest first. A run is on the
/// front when no other run is at least as fast and at least as accurate and
/// strictly better in one of the two.
std::vector<const RunResult*> paretoFront(const std::vector<RunResult>& results);

}  // namespace bench
