#pragma once
// Overlap measured from poses alone, the same way for every engine: the
// deepest penetration between any two bodies (exact for circles and convex
// polygons), whatever each engine reports internally.

#include <vector>

#include "engine_adapter.h"

namespace bench {

class PenetrationProbe {
 public:
  explicit PenetrationProbe(const SceneDescription& scene);
  /// Deepest overlap (m) between any two bodies at the engine's current poses.
  double maxPenetration(const EngineAdapter& engine);

 private:
  const SceneDescription& scene_;
  std::vector<int> statics_;
  std::vector<int> dynamics_;
  double cell_ = 1;
};

}  // namespace bench
