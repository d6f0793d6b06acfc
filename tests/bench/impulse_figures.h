#pragma once
// A bench scene run in Impulse at its default 4 sub-steps for its bench
// length, observed every step: the figures impulse-bench prints for it.
// Every run prints what it measured ("measured:").

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "scene.h"

namespace bench {

struct Figures {
  std::vector<Metric> metrics;

  double operator[](const std::string& name) const {
    for (const Metric& metric : metrics) {
      if (metric.name == name) return metric.value;
    }
    ADD_FAILURE() << "no figure named " << name;
    return std::nan("");
  }
};

/// The scene of `scenes` named `name`, run in Impulse.
inline Figures runInImpulse(const SceneList& scenes, const std::string& name) {
  for (const auto& scene : scenes) {
    if (scene->name() != name) continue;
    const SceneDescription description = scene->describe();
    std::unique_ptr<EngineAdapter> engine = makeImpulseAdapter(description, 4);
    std::unique_ptr<Measure> measure = scene->measure(description, Engine::Impulse);
    for (int step = 0; step < scene->length().steps; ++step) {
      engine->step(kDt);
      measure->observe(*engine, step);
    }
    Figures figures{measure->results(*engine)};
    std::printf("measured: %s", name.c_str());
    for (const Metric& metric : figures.metrics) std::printf("  %s %.4g", metric.name.c_str(), metric.value);
    std::printf("\n");
    return figures;
  }
  ADD_FAILURE() << "no scene named " << name;
  return {};
}

}  // namespace bench
