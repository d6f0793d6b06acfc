#pragma once
// Runs one scene in one engine setting: repeats, timing, measurement.

#include <string>
#include <vector>

#include "scene.h"

namespace bench {

struct RunResult {
  std::string scene;
  EngineSetting setting;
  /// Empty when the run worked; otherwise why not (unsupported, failed).
  std::string problem;
  bool failed = false;  ///< built but threw or produced non-finite numbers
  std::string approximation;  ///< EngineAdapter::approximation()
  std::string passes;         ///< EngineAdapter::passes() after the first repeat
  std::string stages;         ///< EngineAdapter::stages() after the first repeat
  double minMs = 0;     ///< ms/step, min and median over repeats
  double medianMs = 0;
  std::vector<Metric> metrics;

  bool ok() const { return problem.empty(); }
  double error() const { return metrics.empty() ? 0 : metrics.front().value; }
};

RunResult runScene(const Scene& scene, const SceneDescription& description, const EngineSetting& setting);

}  // namespace bench
