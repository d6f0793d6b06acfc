// Compact snapshots end to end without sockets: a 2000-body scene falls from
// rest and settles to sleep while an encoder codes every snapshot (30 Hz at a
// 60 Hz tick) and a decoder reads it back. Measures and asserts the bits per
// body per snapshot, and that every decoded state is within a quantum of the
// truth at every snapshot. Prints the figures (quoted in docs/snapshots.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "impulse/wire/quantized_decoder.h"
#include "impulse/wire/quantized_encoder.h"
#include "impulse/world.h"

namespace impulse::wire::quantized {
namespace {

constexpr int kTickHz = 60;
constexpr int kTicksPerSnapshot = 2;
// The world's default substeps and gravity.
const Integration kIntegration = integrationOf(kTickHz, 4, Vec2(0, Real(-9.81)));
constexpr double kPositionBound = double(kPositionQuantum) * kPositionUnit;  // 2^-8
constexpr double kVelocityBound = double(kVelocityQuantum) * kVelocityUnit;  // 2^-5

// The scene of the snapshot cost test (tests/net/net_test_support.h's
// circleGrid: 40 rows of 50 circles at rest) in an open box, every second
// row shifted right by `stagger` metres.
std::vector<std::uint32_t> buildSettlingScene(World& world, double stagger) {
  auto addWall = [&](Vec2 lower, Vec2 upper) {
    const std::array<Vec2, 4> corners = {lower, Vec2(upper.x(), lower.y()), upper,
                                         Vec2(lower.x(), upper.y())};
    world.createPolygon(corners, {.properties = {.isStatic = true}});
  };
  addWall(Vec2(-1, -1), Vec2(25, 0));
  addWall(Vec2(-1, 0), Vec2(0, 20));
  addWall(Vec2(24, 0), Vec2(25, 20));
  std::vector<std::uint32_t> ids;
  for (int row = 0; row < 40; ++row) {
    for (int column = 0; column < 50; ++column) {
      const Vec2 centre(Real(1.2 + 0.45 * column + stagger * (row % 2)), Real(1.5 + 0.42 * row));
      ids.push_back(world.createCircle(centre, Real(0.18)).id.value);
    }
  }
  return ids;
}

std::vector<std::uint32_t> allIds(const World& world) {
  std::vector<std::uint32_t> ids;
  for (const BodyId id : world.bodyIds()) ids.push_back(id.value);
  std::sort(ids.begin(), ids.end());
  return ids;
}

void expectWithinQuantum(const World& world, const BodyState& decoded) {
  const auto truth = world.bodyState(decoded.id);
  ASSERT_TRUE(truth);
  EXPECT_LT(std::abs(decoded.position.x() - truth->position.x()), kPositionBound);
  EXPECT_LT(std::abs(decoded.position.y() - truth->position.y()), kPositionBound);
  EXPECT_LT(std::abs(decoded.angle - truth->angle), kPositionBound);
  EXPECT_LT(std::abs(decoded.linearVelocity.x() - truth->linearVelocity.x()), kVelocityBound);
  EXPECT_LT(std::abs(decoded.linearVelocity.y() - truth->linearVelocity.y()), kVelocityBound);
  EXPECT_LT(std::abs(decoded.angularVelocity - truth->angularVelocity), kVelocityBound);
  EXPECT_EQ(decoded.awake, truth->awake);
}

struct Stream {
  Encoder encoder;
  Decoder decoder;
  std::vector<BodyState> moved;
  std::uint64_t tick = 0;
};

void startWithKeyFrame(World& world, Stream& stream) {
  const auto ids = allIds(world);
  stream.encoder.reset(world, stream.tick);
  const std::string key =
      stream.encoder.keyFrame(world, {.tick = stream.tick, .integration = kIntegration, .added = ids});
  ASSERT_FALSE(stream.decoder.decode(key, true, {}, ids, stream.moved));
  ASSERT_EQ(stream.moved.size(), ids.size());
}

// What coding a scene until it sleeps took.
struct SettleCost {
  double bitsPerBodyPerSnapshot = 0;
  /// Every delta's bytes, key frame aside, per body: how much the whole
  /// settle cost, whatever its length.
  double bytesPerBody = 0;
};

// Codes the settling scene until it sleeps, checking every decoded state
// (zeros after a failure).
SettleCost settleAndMeasure(double stagger) {
  World world;
  const auto circles = buildSettlingScene(world, stagger);
  EXPECT_EQ(circles.size(), 2000u);
  Stream stream;
  startWithKeyFrame(world, stream);
  if (::testing::Test::HasFailure()) return {};

  std::size_t bits = 0;
  int snapshots = 0;
  std::vector<std::uint32_t> changed;
  const int maxSnapshots = 60 * 30;  // one minute
  while (world.awakeBodyCount() > 0 && snapshots < maxSnapshots) {
    changed.clear();
    for (int i = 0; i < kTicksPerSnapshot; ++i) {
      world.step(Real(1) / kTickHz);
      for (const BodyId id : world.movedBodies()) changed.push_back(id.value);
      ++stream.tick;
    }
    const std::string delta = stream.encoder.delta(
        world, {.tick = stream.tick, .integration = kIntegration, .changed = changed});
    EXPECT_FALSE(stream.decoder.decode(delta, false, {}, {}, stream.moved));
    bits += delta.size() * 8;
    ++snapshots;
    for (const BodyState& state : stream.moved) expectWithinQuantum(world, state);
    if (::testing::Test::HasFailure()) return {};
  }
  EXPECT_EQ(world.awakeBodyCount(), 0) << "the scene never fell asleep";
  // Bodies the decoder did not report as moved keep their decoded state:
  // the baselines on both ends hold the same states.
  for (const std::uint32_t id : circles) {
    expectWithinQuantum(world, dequantize(BodyId{id}, stream.decoder.baseline().bodies.at(id), Vec2d::Zero()));
  }
  const SettleCost cost{double(bits) / (2000.0 * snapshots), double(bits) / 8 / 2000.0};
  std::printf("[ measure ] 2000 bodies settling from rest to sleep (rows staggered %.2f m): "
              "%d snapshots (%.1f s), %.0f bytes/snapshot, %.3f bits per body per snapshot, "
              "%.1f bytes per body in all\n",
              stagger, snapshots, snapshots / 30.0, double(bits) / 8 / snapshots, cost.bitsPerBodyPerSnapshot,
              cost.bytesPerBody);
  return cost;
}

// Issue 16's figure: at most 4 bits. The columns land straight, so most
// corrections are of y and vy alone, which the per-delta kinds table codes
// in a few bits (2.09 bits, 15.9 bytes per body in all, asleep after 2 s).
// The per-snapshot figure alone rewards a scene that takes longer to
// sleep (cheap quiet snapshots dilute it), so the whole stream is bounded
// too.
TEST(CompactSnapshots, SettlingScene_AtMostTwoAndAHalfBitsPerBodyPerSnapshot_WithinAQuantum) {
  const SettleCost cost = settleAndMeasure(0);
  ASSERT_FALSE(HasFailure());
  EXPECT_LE(cost.bitsPerBodyPerSnapshot, 2.5);
  EXPECT_LE(cost.bytesPerBody, 20.0);
}

// Staggered rows roll off each other: every residual is busy and wide, and
// the bits go to information, not to the layout (layout 1: 9.75 bits per
// body per snapshot). Per snapshot the figure follows how long the scene
// takes to sleep: a quicker settle leaves fewer quiet snapshots at the end
// and raises it while the whole settle takes fewer bytes. So the whole
// settle is held to its measure, and the per-snapshot figure to a looser
// bound. Today it sleeps after 4.9 s, at 8.2 bits and 150.4 bytes per body.
TEST(CompactSnapshots, StaggeredSettlingScene_AtMostTenAndAHalfBitsAndHundredSeventyBytesPerBody_WithinAQuantum) {
  const SettleCost cost = settleAndMeasure(0.2);
  ASSERT_FALSE(HasFailure());
  EXPECT_LE(cost.bitsPerBodyPerSnapshot, 10.5);
  EXPECT_LE(cost.bytesPerBody, 170.0);
}

}  // namespace
}  // namespace impulse::wire::quantized
