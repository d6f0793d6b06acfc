#include "runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

namespace bench {

namespace {

bool finitePoses(const EngineAdapter& engine, const SceneDescription& scene) {
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
    Pose pose = engine.pose(i);
    for (double v : {pose.position.x, pose.position.y, pose.angle, pose.velocity.x, pose.velocity.y,
                     pose.angularVelocity}) {
      if (!std::isfinite(v)) return false;
    }
  }
  return true;
}

}  // namespace

RunResult runScene(const Scene& scene, const SceneDescription& description, const EngineSetting& setting) {
  RunResult result{scene.name(), setting, {}, false, {}, {}, {}, 0, 0, {}};
  const RunLength length = scene.length();
  std::vector<double> msPerStep;
  try {
    for (int repeat = 0; repeat < length.repeats; ++repeat) {
      std::unique_ptr<EngineAdapter> engine = makeAdapter(description, setting);
      for (int i = 0; i < length.warmupSteps; ++i) engine->step(kDt);
      // The scene's behaviour is deterministic in every engine: measure the
      // first repeat only, time them all.
      std::unique_ptr<Measure> measure = repeat == 0 ? scene.measure(description, setting.engine) : nullptr;
      double elapsed = 0;
      for (int step = 0; step < length.steps; ++step) {
        auto start = std::chrono::steady_clock::now();
        engine->step(kDt);
        elapsed += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (measure) engine->countStep();
        if (measure && (step % length.observeEvery == 0 || step == length.steps - 1)) {
          measure->observe(*engine, step);
        }
      }
      msPerStep.push_back(elapsed / length.steps);
      if (!finitePoses(*engine, description)) {
        result.problem = "FAILED: non-finite pose";
        result.failed = true;
        return result;
      }
      if (measure) {
        result.metrics = measure->results(*engine);
        result.approximation = engine->approximation();
        result.passes = engine->passes();
        result.stages = engine->stages();
      }
    }
  } catch (const Unsupported& e) {
    result.problem = std::string("skipped: ") + e.what();
    return result;
  } catch (const std::exception& e) {
    result.problem = std::string("FAILED: ") + e.what();
    result.failed = true;
    return result;
  }
  for (const Metric& metric : result.metrics) {
    if (!std::isfinite(metric.value)) {
      result.problem = "FAILED: non-finite " + metric.name;
      result.failed = true;
    }
  }
  std::sort(msPerStep.begin(), msPerStep.end());
  result.minMs = msPerStep.front();
  std::size_t middle = msPerStep.size() / 2;
  result.medianMs = msPerStep.size() % 2 == 1 ? msPerStep[middle] : 0.5 * (msPerStep[middle - 1] + msPerStep[middle]);
  return result;
}

}  // namespace bench
