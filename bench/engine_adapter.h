#pragma once
// The common face of the engines: build from a SceneDescription, step,
// read poses back in description order.

#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene_description.h"

namespace bench {

/// Box2DV3Sse2/Avx2: Box2D v3 built twice from one source tree, present only
/// when CMake was given IMPULSE_BOX2D_V3_SOURCE (IMPULSE_BENCH_BOX2D_V3).
/// ImpulseSse2: Impulse with its contact solver held to SSE2 (the plain
/// Impulse rows take AVX2 when the CPU has it); results are bit-identical.
enum class Engine { Impulse, ImpulseSse2, Box2D, Chipmunk, Box2DV3Sse2, Box2DV3Avx2 };

const char* engineName(Engine engine);

/// Impulse at either solver width: the same model, so the same closed forms.
inline bool isImpulse(Engine engine) { return engine == Engine::Impulse || engine == Engine::ImpulseSse2; }

/// One engine at one solver setting: Impulse and Box2D v3 sub-steps, Box2D
/// 2.4.1 velocity and position iterations, Chipmunk iterations.
struct EngineSetting {
  Engine engine = Engine::Impulse;
  int iterations = 4;
  int positionIterations = 0;  ///< Box2D only
  int threads = 1;             ///< Impulse and Box2D v3 workers
  std::string label() const;
};

/// Impulse at 1, 2, 4 and 8 sub-steps (and 4 held to SSE2); Box2D at 8/3
/// (default) and 30/10;
/// Chipmunk at 10 (default) and 30 iterations; Box2D v3 (when built) at 4
/// (default) and 8 sub-steps in each of its builds. Impulse and v3 AVX2 at
/// 4 sub-steps also on two threads.
std::vector<EngineSetting> allSettings();

struct Pose {
  Vec2d position;
  double angle = 0;
  Vec2d velocity;
  double angularVelocity = 0;
  bool awake = true;
};

class EngineAdapter {
 public:
  virtual ~EngineAdapter() = default;
  virtual void step(double dt) = 0;
  /// Body `index` in the order of SceneDescription::bodies.
  virtual Pose pose(int index) const = 0;
  /// Where the engine built the scene otherwise than described (empty: as
  /// described); the run's table row says so.
  virtual std::string approximation() const { return {}; }

  /// World queries, for the query bench (query_bench.h); engines whose
  /// adapter does not wire them say so here and are left out of it.
  virtual bool hasQueries() const { return false; }
  /// The nearest hit's fraction of the ray origin -> origin + translation,
  /// or -1 when it hits nothing.
  virtual double castRayClosest(const Vec2d& /*origin*/, const Vec2d& /*translation*/) { return -1; }
  /// How many shapes the ray hits.
  virtual int castRayCount(const Vec2d& /*origin*/, const Vec2d& /*translation*/) { return 0; }
  /// How many shapes have a tight bounding box overlapping lower-upper.
  virtual int overlapBoxCount(const Vec2d& /*lower*/, const Vec2d& /*upper*/) { return 0; }
  /// Which of the engine's optional solver passes ran, and on how much, over
  /// the steps so far (empty: the engine has none to report).
  virtual std::string passes() const { return {}; }
  /// Called after each step of a measured run, outside its timing: counts
  /// for passes() that the engine would take inside the step's time.
  virtual void countStep() {}
  /// Where the engine's own timers put a step's time, mean over the steps
  /// so far (empty: the engine has none to report). Each engine's stages end
  /// where its own timers end them (StageTimes).
  virtual std::string stages() const { return {}; }
};

/// An engine's stage timers summed over its steps, named as the engine
/// names them, and told as mean ms/step: "pairs 0.18 collide 3.06 ...".
class StageTimes {
 public:
  explicit StageTimes(std::vector<std::string> names) : names_(std::move(names)), sums_(names_.size(), 0) {}
  /// One step's times (ms), in the names' order: called inside the timed
  /// step, so it takes a list that allocates nothing.
  void add(std::initializer_list<double> ms);
  std::string describe() const;

 private:
  std::vector<std::string> names_;
  std::vector<double> sums_;
  int steps_ = 0;
};

/// The scene built in the given engine at the given setting.
std::unique_ptr<EngineAdapter> makeAdapter(const SceneDescription& scene, const EngineSetting& setting);

std::unique_ptr<EngineAdapter> makeImpulseAdapter(const SceneDescription& scene, int subSteps,
                                                  bool sse2Only = false, int threads = 1);
std::unique_ptr<EngineAdapter> makeBox2DAdapter(const SceneDescription& scene, int velocityIterations,
                                                int positionIterations);
std::unique_ptr<EngineAdapter> makeChipmunkAdapter(const SceneDescription& scene, int iterations);
// One per v3 build; adapters/box2d_v3_adapter.cpp compiled into each namespace.
namespace box2d_v3_sse2 {
std::unique_ptr<EngineAdapter> makeAdapter(const SceneDescription& scene, int subSteps, int workers);
}
namespace box2d_v3_avx2 {
std::unique_ptr<EngineAdapter> makeAdapter(const SceneDescription& scene, int subSteps, int workers);
}

}  // namespace bench
