#pragma once
// A benchmark scene: its neutral description, how long to run it, and the
// measurement that turns poses into error figures.

#include <memory>
#include <string>
#include <vector>

#include "engine_adapter.h"
#include "scene_description.h"

namespace bench {

inline constexpr double kDt = 1.0 / 60.0;

/// One error figure. The first metric of a scene is its headline error
/// (lower is better): the plot's x axis and the ratio lines use it.
struct Metric {
  std::string name;
  double value = 0;
};

/// Watches one run (the first repeat) of a scene in one engine.
class Measure {
 public:
  virtual ~Measure() = default;
  /// Called after timed step `step` (0-based) when step % observeEvery == 0,
  /// and after the last step; outside the timed region.
  virtual void observe(const EngineAdapter& engine, int step) = 0;
  virtual std::vector<Metric> results(const EngineAdapter& engine) = 0;
};

struct RunLength {
  int warmupSteps = 0;  ///< untimed steps before timing starts
  int steps = 60;       ///< timed steps
  int repeats = 3;      ///< timings: min and median over repeats
  int observeEvery = 1;
};

class Scene {
 public:
  virtual ~Scene() = default;
  /// Unique name, e.g. "pyramid-20".
  virtual std::string name() const = 0;
  virtual SceneDescription describe() const = 0;
  virtual RunLength length() const = 0;
  virtual std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine engine) const = 0;
};

using SceneList = std::vector<std::unique_ptr<Scene>>;

// Families of scenes, each in bench/scenes/<family>.cpp. `quick` shortens the
// runs (scenes keep their full size so each still builds in every engine).
void addStackingScenes(SceneList& scenes, bool quick);    // pyramids, tower, mass ratios, overlap
void addFrictionRampScene(SceneList& scenes, bool quick);
void addCircleScenes(SceneList& scenes, bool quick);      // confined, squeeze, rain, scaling
void addBulletScene(SceneList& scenes, bool quick);
void addClosedFormScenes(SceneList& scenes, bool quick);  // free fall, incline, rolling, bounce
void addSleepingScenes(SceneList& scenes, bool quick);
void addJointScenes(SceneList& scenes, bool quick);  // chains, bridge, pendulum, spring, ragdolls
void addBox2DSuiteScenes(SceneList& scenes, bool quick);  // the ten of Box2D v3's benchmark, "v3-*"
void addSolver2DScenes(SceneList& scenes, bool quick);    // Solver2D's collection and its far twins, "s2d-*"

/// Impulse's own scenes (every family above but the Box2D v3 suite and
/// Solver2D's collection).
SceneList allScenes(bool quick);
/// Box2D v3's benchmark suite: run apart, as it is large (10 000-22 000
/// bodies a scene at full size).
SceneList box2DSuiteScenes(bool quick);
/// Solver2D's scene collection (bench/scenes/solver2d.cpp): run apart, as
/// its scenes are judged by their figures more than timed.
SceneList solver2DScenes(bool quick);

}  // namespace bench
