// The playout time base: simulated time at any time scale mapped to a time
// that runs with the wall clock, so the playout clock and interpolation stay
// smooth in slow motion and fast forward.
#include "playout_time_base.h"

#include <gtest/gtest.h>

namespace impulse::viewer {
namespace {

TEST(PlayoutTimeBase, AtOneXPlayoutIsSimulatedTime) {
  PlayoutTimeBase base;
  for (double t : {3.0, 3.1, 3.2}) EXPECT_EQ(base.onSnapshot(t, 1), t);
  EXPECT_NEAR(base.toSim(3.15), 3.15, 1e-12);
}

TEST(PlayoutTimeBase, SnapshotsAtEqualWallIntervalsGetEqualPlayoutIntervals) {
  // Snapshots every 1/30 s of wall time carry 4/30 s of simulated time at 4x
  // and 1/120 s at 0.25x: their playout times are 1/30 s apart either way.
  for (double scale : {4.0, 0.25, 0.01, 16.0}) {
    SCOPED_TRACE(scale);
    PlayoutTimeBase base;
    double previous = base.onSnapshot(10, scale);
    for (int k = 1; k <= 20; ++k) {
      const double playout = base.onSnapshot(10 + k * scale / 30, scale);
      EXPECT_NEAR(playout - previous, 1.0 / 30, 1e-9);
      previous = playout;
    }
  }
}

TEST(PlayoutTimeBase, ToSimInvertsBetweenSnapshotsAcrossAScaleChange) {
  PlayoutTimeBase base;
  const double a = base.onSnapshot(1.0, 1);
  const double b = base.onSnapshot(1.1, 1);    // 0.1 s later
  const double c = base.onSnapshot(1.5, 4);    // at 4x: 0.1 s later again
  const double d = base.onSnapshot(1.525, 0.25);  // at 0.25x: 0.1 s later
  EXPECT_NEAR(b - a, 0.1, 1e-12);
  EXPECT_NEAR(c - b, 0.1, 1e-12);
  EXPECT_NEAR(d - c, 0.1, 1e-12);
  EXPECT_NEAR(base.toSim(a), 1.0, 1e-12);
  EXPECT_NEAR(base.toSim(b + 0.05), 1.3, 1e-12) << "halfway through the 4x stretch";
  EXPECT_NEAR(base.toSim(c + 0.05), 1.5125, 1e-12) << "halfway through the 0.25x stretch";
  EXPECT_NEAR(base.toSim(d + 0.04), 1.535, 1e-12) << "past the newest: at its scale";
}

TEST(PlayoutTimeBase, MonotonicPlayoutGivesMonotonicSimulatedTime) {
  PlayoutTimeBase base;
  double sim = 0;
  const double scales[] = {1, 8, 0.5, 16, 0.01, 2};
  for (int k = 0; k < 60; ++k) {
    sim += scales[k % 6] / 30;
    base.onSnapshot(sim, scales[k % 6]);
  }
  double last = -1;
  for (double p = 0; p < 3; p += 0.001) {
    const double s = base.toSim(p);
    EXPECT_GE(s, last);
    last = s;
  }
}

TEST(PlayoutTimeBase, ZeroScaleFromAnOlderServerMeansOneX) {
  PlayoutTimeBase base;
  base.onSnapshot(2, 0);
  EXPECT_EQ(base.onSnapshot(2.5, 0), 2.5);
}

}  // namespace
}  // namespace impulse::viewer
