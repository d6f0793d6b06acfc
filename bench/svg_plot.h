#pragma once
// One SVG per scene: ms/step (median) against the headline error, a point
// per engine setting, each engine's settings joined by a line, and the
// Pareto front (front.h) dashed, so who dominates shows at a glance.

#include <string>
#include <vector>

#include "runner.h"

namespace bench {

/// Writes DIR/<scene>.svg; false when the file cannot be written.
bool writeSvgPlot(const std::string& directory, const std::vector<RunResult>& results);

}  // namespace bench
