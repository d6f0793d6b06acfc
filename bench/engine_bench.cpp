// Stress scenes of the engine issue, timed: a 100-row pyramid (sleep off) and
// 2000 circles poured into a box. Prints ms/step (min and median) and error
// figures (top drift, sink, max penetration) per solver setting.
//
//   impulse-engine-bench [--quick] [--substeps N] [--hertz HZ]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "impulse/scenes/stress.h"
#include "impulse/world.h"

namespace {

using impulse::Real;
using impulse::Vec2;

constexpr Real kDt = Real(1.0 / 60.0);

struct Options {
  bool quick = false;
  int subSteps = 4;
  Real hertz = 30;
};

struct Timing {
  double minMs = 0;
  double medianMs = 0;
};

Timing summarise(std::vector<double> samples) {
  std::sort(samples.begin(), samples.end());
  return {samples.front(), samples[samples.size() / 2]};
}

template <typename Step>
Timing timeSteps(int steps, Step&& step) {
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(steps));
  for (int i = 0; i < steps; ++i) {
    auto start = std::chrono::steady_clock::now();
    step();
    samples.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return summarise(std::move(samples));
}

void accumulate(impulse::StepProfile& sum, const impulse::StepProfile& step) {
  sum.pairs += step.pairs;
  sum.collide += step.collide;
  sum.fields += step.fields;
  sum.solve += step.solve;
  sum.continuous += step.continuous;
  sum.sleep += step.sleep;
  sum.total += step.total;
  sum.manifoldUpdates += step.manifoldUpdates;
}

impulse::WorldSettings settingsFor(const Options& options, bool sleep) {
  impulse::WorldSettings settings;
  settings.subSteps = options.subSteps;
  settings.contactHertz = options.hertz;
  settings.enableSleep = sleep;
  return settings;
}

void runPyramid(const Options& options, int rows, int steps) {
  impulse::World world(settingsFor(options, false));
  impulse::Pyramid pyramid = impulse::buildPyramid(world, rows);
  impulse::StepProfile sum;
  Timing timing = timeSteps(steps, [&] {
    world.step(kDt);
    accumulate(sum, world.profile());
  });
  Vec2 top = world.bodyState(pyramid.top)->position;
  std::printf("pyramid %3d rows  %5zu boxes  substeps %d hertz %4.0f  ms/step min %7.3f median %7.3f"
              "  top drift %.4f m  sink %.4f m\n",
              rows, pyramid.boxes.size(), options.subSteps, double(options.hertz), timing.minMs,
              timing.medianMs, double(std::abs(top.x() - pyramid.topStart.x())),
              double(pyramid.topStart.y() - top.y()));
  // fields: a world without force fields pays nothing for the stage.
  std::printf("  mean profile ms/step: pairs %.3f collide %.3f fields %.4f solve %.3f continuous %.3f sleep %.3f"
              " total %.3f  manifolds recomputed %.0f of %d contacts\n",
              sum.pairs / steps, sum.collide / steps, sum.fields / steps, sum.solve / steps, sum.continuous / steps,
              sum.sleep / steps, sum.total / steps, double(sum.manifoldUpdates) / steps, world.contactCount());
}

void runRain(const Options& options, int count, int steps) {
  impulse::World world(settingsFor(options, true));
  std::vector<impulse::BodyId> balls = impulse::buildRain(world, count);
  Timing timing = timeSteps(steps, [&] { world.step(kDt); });
  int awake = world.awakeBodyCount();
  std::printf("rain    %5d circles  substeps %d hertz %4.0f  ms/step min %7.3f median %7.3f  awake at end %d\n",
              count, options.subSteps, double(options.hertz), timing.minMs, timing.medianMs, awake);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      options.quick = true;
    } else if (std::strcmp(argv[i], "--substeps") == 0 && i + 1 < argc) {
      options.subSteps = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--hertz") == 0 && i + 1 < argc) {
      options.hertz = Real(std::atof(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--substeps N] [--hertz HZ]\n", argv[0]);
      std::exit(2);
    }
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  Options options = parse(argc, argv);
  if (options.quick) {
    runPyramid(options, 20, 60);
    runRain(options, 200, 60);
    return 0;
  }
  runPyramid(options, 20, 600);
  runPyramid(options, 100, 600);
  runRain(options, 2000, 600);
  return 0;
}
