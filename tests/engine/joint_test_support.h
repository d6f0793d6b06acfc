#pragma once
// Helpers for the joint tests: joints in one line, and measurements of
// oscillations (crossing times, extrema) from sampled signals.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "impulse/joint.h"
#include "world_test_support.h"

namespace impulse::test {

/// Creates a joint that must be accepted (a refusal fails the test).
inline JointId addJoint(World& world, BodyId a, BodyId b, Vec2 anchorA, Vec2 anchorB,
                        JointSettings settings, bool collideConnected = false) {
  JointDef def{a, b, anchorA, anchorB, collideConnected, settings};
  JointResult result = world.createJoint(def);
  EXPECT_TRUE(result.ok()) << result.error;
  return result.id;
}

inline double massOf(const World& world, BodyId id) { return world.bodyDescription(id)->mass.mass; }

/// A signal sampled every tick.
struct Samples {
  std::vector<double> time;
  std::vector<double> value;
  void add(double t, double v) {
    time.push_back(t);
    value.push_back(v);
  }
  /// Times where the signal rises through `level`, linearly interpolated.
  std::vector<double> risingCrossings(double level) const {
    std::vector<double> times;
    for (std::size_t i = 1; i < value.size(); ++i) {
      if (value[i - 1] < level && value[i] >= level) {
        double f = (level - value[i - 1]) / (value[i] - value[i - 1]);
        times.push_back(time[i - 1] + f * (time[i] - time[i - 1]));
      }
    }
    return times;
  }
  /// The mean period between the first and the last rising crossing.
  double meanPeriod(double level) const {
    std::vector<double> t = risingCrossings(level);
    if (t.size() < 2) return 0;
    return (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  }
};

/// Steps the world, sampling `measure` after every tick.
template <class Measure>
Samples record(World& world, double seconds, Measure&& measure) {
  Samples samples;
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
    world.step(kDt);
    samples.add(i * double(kDt), measure());
  }
  return samples;
}

/// The largest value `measure` gives after any tick over `seconds`.
template <class Measure>
double highestOver(World& world, double seconds, Measure&& measure) {
  Samples s = record(world, seconds, measure);
  return *std::max_element(s.value.begin(), s.value.end());
}

}  // namespace impulse::test
