#include "engine_adapter.h"

#include <cstdio>

namespace bench {

void StageTimes::add(std::initializer_list<double> ms) {
  std::size_t i = 0;
  for (const double stage : ms) {
    if (i < sums_.size()) sums_[i++] += stage;
  }
  ++steps_;
}

std::string StageTimes::describe() const {
  if (steps_ == 0) return {};
  std::string line;
  char part[64];
  for (std::size_t i = 0; i < names_.size(); ++i) {
    std::snprintf(part, sizeof part, "%s%s %.3f", i == 0 ? "" : " ", names_[i].c_str(), sums_[i] / steps_);
    line += part;
  }
  return line + " ms/step";
}

const char* engineName(Engine engine) {
  switch (engine) {
    case Engine::Impulse: return "impulse";
    case Engine::ImpulseSse2: return "impulse-sse2";
    case Engine::Box2D: return "box2d";
    case Engine::Chipmunk: return "chipmunk";
    case Engine::Box2DV3Sse2: return "box2d-v3-sse2";
    case Engine::Box2DV3Avx2: return "box2d-v3-avx2";
  }
  return "?";
}

std::string EngineSetting::label() const {
  const std::string onThreads = threads > 1 ? " x" + std::to_string(threads) : "";
  switch (engine) {
    case Engine::Impulse:
    case Engine::ImpulseSse2:
    case Engine::Box2DV3Sse2:
    case Engine::Box2DV3Avx2: return "sub " + std::to_string(iterations) + onThreads;
    case Engine::Box2D: return "it " + std::to_string(iterations) + "/" + std::to_string(positionIterations);
    case Engine::Chipmunk: return "it " + std::to_string(iterations);
  }
  return "?";
}

std::vector<EngineSetting> allSettings() {
  return {{Engine::Impulse, 1, 0},     {Engine::Impulse, 2, 0},     {Engine::Impulse, 4, 0},
          {Engine::Impulse, 4, 0, 2},  {Engine::Impulse, 8, 0},     {Engine::ImpulseSse2, 4, 0},
          {Engine::Box2D, 8, 3},
          {Engine::Box2D, 30, 10},
          {Engine::Chipmunk, 10, 0},   {Engine::Chipmunk, 30, 0},
#ifdef IMPULSE_BENCH_BOX2D_V3
          {Engine::Box2DV3Sse2, 4, 0}, {Engine::Box2DV3Sse2, 8, 0}, {Engine::Box2DV3Avx2, 4, 0},
          {Engine::Box2DV3Avx2, 4, 0, 2}, {Engine::Box2DV3Avx2, 8, 0},
#endif
  };
}

std::unique_ptr<EngineAdapter> makeAdapter(const SceneDescription& scene, const EngineSetting& setting) {
  switch (setting.engine) {
    case Engine::Impulse: return makeImpulseAdapter(scene, setting.iterations, false, setting.threads);
    case Engine::ImpulseSse2: return makeImpulseAdapter(scene, setting.iterations, true);
    case Engine::Box2D: return makeBox2DAdapter(scene, setting.iterations, setting.positionIterations);
    case Engine::Chipmunk: return makeChipmunkAdapter(scene, setting.iterations);
#ifdef IMPULSE_BENCH_BOX2D_V3
    case Engine::Box2DV3Sse2: return box2d_v3_sse2::makeAdapter(scene, setting.iterations, setting.threads);
    case Engine::Box2DV3Avx2: return box2d_v3_avx2::makeAdapter(scene, setting.iterations, setting.threads);
#else
    case Engine::Box2DV3Sse2:
    case Engine::Box2DV3Avx2: break;  // not built: allSettings() never lists them
#endif
  }
  return nullptr;
}

}  // namespace bench
