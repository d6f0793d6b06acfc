#include "interpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace impulse::viewer {
namespace {

constexpr double kInterval = 1.0 / 30.0;
constexpr float kPi = std::numbers::pi_v<float>;

BodySample moving(std::uint32_t id, double x, double vx = 0, float angle = 0, float w = 0) {
  BodySample s;
  s.id = id;
  s.position = Vec2(Real(x), 5);
  s.velocity = Vec2(Real(vx), 0);
  s.angle = angle;
  s.angularVelocity = w;
  s.awake = true;
  return s;
}

SnapshotFrame frame(double time, std::vector<BodySample> bodies, bool full = false) {
  SnapshotFrame f;
  f.time = time;
  f.full = full;
  f.bodies = std::move(bodies);
  return f;
}

// A body moving at 3 m/s along x, one snapshot per interval from t = 0.
SnapshotBuffer steadyStream(int frames) {
  SnapshotBuffer buffer({kInterval});
  for (int i = 0; i < frames; ++i) {
    const double t = i * kInterval;
    buffer.push(frame(t, {moving(1, 3 * t, 3)}));
  }
  return buffer;
}

TEST(SnapshotBuffer, EmptyBufferSamplesNothing) {
  SnapshotBuffer buffer;
  std::vector<BodySample> out{moving(1, 0)};
  EXPECT_EQ(buffer.sample(1.0, out), SampleMode::Empty);
  EXPECT_TRUE(out.empty());
}

TEST(SnapshotBuffer, SteadyStream_InterpolatesPositionsLinearly) {
  const SnapshotBuffer buffer = steadyStream(10);
  std::vector<BodySample> out;
  for (double t = 0.01; t < 9 * kInterval; t += 0.0071) {
    ASSERT_EQ(buffer.sample(t, out), SampleMode::Interpolated) << t;
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out[0].position.x(), 3 * t, 1e-5) << t;
  }
}

TEST(SnapshotBuffer, UnevenSpacing_InterpolatesByServerTime) {
  // Jitter in arrival does not matter; uneven server times (skipped ticks) do.
  SnapshotBuffer buffer({kInterval});
  buffer.push(frame(0.0, {moving(1, 0, 10)}));
  buffer.push(frame(0.1, {moving(1, 1, 10)}));
  buffer.push(frame(0.125, {moving(1, 2, 40)}));
  std::vector<BodySample> out;
  buffer.sample(0.075, out);
  EXPECT_NEAR(out[0].position.x(), 0.75, 1e-6);
  buffer.sample(0.11, out);
  EXPECT_NEAR(out[0].position.x(), 1.4, 1e-5);
}

TEST(SnapshotBuffer, BeforeOldest_ShowsOldest) {
  const SnapshotBuffer buffer = steadyStream(3);
  std::vector<BodySample> out;
  EXPECT_EQ(buffer.sample(-1.0, out), SampleMode::BeforeOldest);
  EXPECT_FLOAT_EQ(out[0].position.x(), 0);
}

TEST(SnapshotBuffer, Starved_ExtrapolatesOneIntervalAtMostThenHolds) {
  const SnapshotBuffer buffer = steadyStream(4);  // newest at 3 intervals, x = 0.3
  const double newest = 3 * kInterval;
  std::vector<BodySample> out;
  EXPECT_EQ(buffer.sample(newest + kInterval / 2, out), SampleMode::Extrapolated);
  EXPECT_NEAR(out[0].position.x(), 3 * (newest + kInterval / 2), 1e-5);
  EXPECT_EQ(buffer.sample(newest + 5 * kInterval, out), SampleMode::Held);
  EXPECT_NEAR(out[0].position.x(), 3 * (newest + kInterval), 1e-5);
  buffer.sample(newest + 50 * kInterval, out);
  EXPECT_NEAR(out[0].position.x(), 3 * (newest + kInterval), 1e-5);
}

TEST(SnapshotBuffer, Starved_SleepingBodiesAndPausedServerAreNotExtrapolated) {
  SnapshotBuffer buffer({kInterval});
  BodySample asleep = moving(2, 1, 3);
  asleep.awake = false;
  buffer.push(frame(0, {moving(1, 0, 3), asleep}));
  std::vector<BodySample> out;
  buffer.sample(kInterval, out);
  EXPECT_NEAR(out[0].position.x(), 0.1, 1e-6);
  EXPECT_FLOAT_EQ(out[1].position.x(), 1);

  SnapshotFrame paused = frame(kInterval, {moving(1, 0.1, 3)});
  paused.paused = true;
  buffer.push(paused);
  buffer.sample(10 * kInterval, out);
  EXPECT_NEAR(out[0].position.x(), 0.1, 1e-6);
}

TEST(SnapshotBuffer, Gap_InterpolatesAcrossMissingSnapshots) {
  SnapshotBuffer buffer({kInterval});
  buffer.push(frame(0, {moving(1, 0, 3)}));
  buffer.push(frame(4 * kInterval, {moving(1, 0.4, 3)}));  // three skipped
  std::vector<BodySample> out;
  EXPECT_EQ(buffer.sample(2 * kInterval, out), SampleMode::Interpolated);
  EXPECT_NEAR(out[0].position.x(), 0.2, 1e-6);
}

TEST(SnapshotBuffer, AngleWrapAround_TakesTheShortArc) {
  SnapshotBuffer buffer({kInterval});
  buffer.push(frame(0, {moving(1, 0, 0, kPi - 0.1f)}));
  buffer.push(frame(kInterval, {moving(1, 0, 0, -kPi + 0.1f)}));
  std::vector<BodySample> out;
  buffer.sample(kInterval / 2, out);
  // Halfway along the 0.2 rad arc through pi, not back through zero.
  EXPECT_NEAR(std::abs(std::remainder(out[0].angle - kPi, 2 * kPi)), 0, 1e-4);
}

TEST(InterpolateAngle, ShortArcBothWaysAndFastSpinKeepsDirection) {
  EXPECT_NEAR(interpolateAngle(0.1f, -0.1f, 0.5f), 0, 1e-6);
  EXPECT_NEAR(interpolateAngle(-3.0f, 3.0f, 0.5f), -3.0f - (2 * kPi - 6) / 2, 1e-5);
  // 0.8 turn per interval anticlockwise: the short arc would run backwards.
  const float turn = 0.8f * 2 * kPi;
  const float b = std::remainder(turn, 2 * kPi);
  EXPECT_NEAR(interpolateAngle(0, b, 0.5f, turn), turn / 2, 1e-4);
}

TEST(SnapshotBuffer, Teleport_SnapsInsteadOfSliding) {
  SnapshotBuffer buffer({kInterval});
  buffer.push(frame(0, {moving(1, 0, 1)}));
  buffer.push(frame(kInterval, {moving(1, 10, 1)}));
  std::vector<BodySample> out;
  buffer.sample(kInterval * 0.9, out);
  EXPECT_FLOAT_EQ(out[0].position.x(), 0);
  buffer.sample(kInterval, out);
  EXPECT_FLOAT_EQ(out[0].position.x(), 10);
}

TEST(SnapshotBuffer, FullSnapshot_SnapsAtItsTime) {
  SnapshotBuffer buffer({kInterval});
  buffer.push(frame(0, {moving(1, 0), moving(2, 4)}));
  buffer.push(frame(kInterval, {moving(3, 8)}, true));  // a preset loaded
  std::vector<BodySample> out;
  buffer.sample(kInterval * 0.5, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].id, 1u);
  buffer.sample(kInterval * 1.01, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].id, 3u);
}

TEST(SnapshotBuffer, AddedAndRemovedBodiesChangeAtTheirFrame) {
  SnapshotBuffer buffer({kInterval});
  buffer.push(frame(0, {moving(1, 0), moving(2, 4)}));
  buffer.push(frame(kInterval, {moving(2, 4), moving(5, 6)}));
  std::vector<BodySample> out;
  buffer.sample(kInterval * 0.5, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].id, 1u);
  EXPECT_EQ(out[1].id, 2u);
  buffer.sample(kInterval * 1.5, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1].id, 5u);
}

TEST(SnapshotBuffer, DiscardBefore_KeepsTheFrameTheTimeFallsAfter) {
  SnapshotBuffer buffer = steadyStream(10);
  buffer.discardBefore(4.5 * kInterval);
  EXPECT_EQ(buffer.size(), 6u);
  EXPECT_NEAR(buffer.oldestTime(), 4 * kInterval, 1e-12);
  std::vector<BodySample> out;
  EXPECT_EQ(buffer.sample(4.5 * kInterval, out), SampleMode::Interpolated);
  EXPECT_NEAR(out[0].position.x(), 3 * 4.5 * kInterval, 1e-5);
}

TEST(SnapshotBuffer, Reset_ForgetsEveryFrame_AndOlderTimeResets) {
  SnapshotBuffer buffer = steadyStream(5);
  buffer.reset();
  EXPECT_TRUE(buffer.empty());
  buffer = steadyStream(5);
  buffer.push(frame(0.01, {moving(7, 1)}));  // a restarted server
  EXPECT_EQ(buffer.size(), 1u);
  std::vector<BodySample> out;
  buffer.sample(0.01, out);
  EXPECT_EQ(out[0].id, 7u);
}

TEST(SnapshotBuffer, SameTime_ReplacesNewest) {
  SnapshotBuffer buffer({kInterval});
  buffer.push(frame(1, {moving(1, 0)}));
  buffer.push(frame(1, {moving(2, 0)}, true));
  EXPECT_EQ(buffer.size(), 1u);
  std::vector<BodySample> out;
  buffer.sample(1, out);
  EXPECT_EQ(out[0].id, 2u);
}

TEST(SnapshotBuffer, BoundedFrames) {
  InterpolationSettings settings;
  settings.maxFrames = 8;
  SnapshotBuffer buffer(settings);
  for (int i = 0; i < 100; ++i) buffer.push(frame(i, {}));
  EXPECT_EQ(buffer.size(), 8u);
}

}  // namespace
}  // namespace impulse::viewer
