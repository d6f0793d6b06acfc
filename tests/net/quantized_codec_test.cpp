// The compact snapshot codec's parts: bits, the prediction against its
// closed form, deterministic round trips, key frames for late joiners, and
// hostile bytes (an error that says what, never a crash).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "impulse/wire/bit_reader.h"
#include "impulse/wire/bit_writer.h"
#include "impulse/wire/quantized_decoder.h"
#include "impulse/wire/quantized_encoder.h"
#include "impulse/wire/quantized_layout.h"
#include "impulse/world.h"

namespace impulse::wire {
namespace {

TEST(BitCodec, ValuesOfEveryKind_ReadBackAsWritten) {
  std::mt19937_64 random(7);
  std::vector<std::int64_t> values = {0, 1, -1, 2, -2, (std::int64_t(1) << 61) - 1,
                                      -(std::int64_t(1) << 61)};
  for (int i = 0; i < 1000; ++i) values.push_back(std::int64_t(random() >> (2 + i % 60)) - (1 << 20));
  BitWriter writer;
  for (const std::int64_t value : values) {
    writer.writeSigned(value);
    writer.writeBits(std::uint64_t(value) & 0x1f, 5);
    writer.writeExpGolomb(std::uint64_t(std::abs(value)));
  }
  BitReader reader(writer.bytes());
  for (const std::int64_t value : values) {
    EXPECT_EQ(reader.readSigned(), value);
    EXPECT_EQ(reader.readBits(5), std::uint64_t(value) & 0x1f);
    EXPECT_EQ(reader.readExpGolomb(), std::uint64_t(std::abs(value)));
  }
  EXPECT_FALSE(reader.failed());
  EXPECT_LT(reader.bitsLeft(), 8u);
}

TEST(BitCodec, SmallNumbersAreShort) {
  BitWriter writer;
  writer.writeExpGolomb(0);
  EXPECT_EQ(writer.bitCount(), 1u);
  writer.writeSigned(-1);  // zigzag 1: 3 bits
  EXPECT_EQ(writer.bitCount(), 4u);
  writer.writeSigned(3);  // zigzag 6: 5 bits
  EXPECT_EQ(writer.bitCount(), 9u);
}

TEST(BitCodec, ExpGolombOfEveryOrder_ReadsBackAndTakesTheStatedLength) {
  const std::vector<std::uint64_t> values = {0, 1, 2, 7, 8, 100, 12345, (std::uint64_t(1) << 62) - 1};
  for (int order = 0; order <= quantized::kMaxOrder; ++order) {
    BitWriter writer;
    for (const std::uint64_t value : values) {
      const std::size_t before = writer.bitCount();
      writer.writeExpGolomb(value, order);
      EXPECT_EQ(writer.bitCount() - before, std::size_t(BitWriter::expGolombLength(value, order)));
    }
    BitReader reader(writer.bytes());
    for (const std::uint64_t value : values) EXPECT_EQ(reader.readExpGolomb(order), value) << order;
    EXPECT_FALSE(reader.failed());
  }
  // Order 2: 5 is 1 (EG "010") then 01.
  BitWriter five;
  five.writeExpGolomb(5, 2);
  EXPECT_EQ(five.bitCount(), 5u);
  EXPECT_EQ(five.bytes(), std::string(1, char(0b01001000)));
}

TEST(BitCodec, NonZeroResidualsFold_OneMinusOneTwoMinusTwo) {
  EXPECT_EQ(quantized::foldNonZero(1), 0u);
  EXPECT_EQ(quantized::foldNonZero(-1), 1u);
  EXPECT_EQ(quantized::foldNonZero(2), 2u);
  EXPECT_EQ(quantized::foldNonZero(-2), 3u);
  for (std::int64_t r = 1; r <= 1000; ++r) {
    EXPECT_EQ(quantized::unfoldNonZero(quantized::foldNonZero(r)), r);
    EXPECT_EQ(quantized::unfoldNonZero(quantized::foldNonZero(-r)), -r);
  }
}

TEST(BitCodec, ReadingPastTheEndOrAnEndlessCode_Fails) {
  const std::string one(1, '\xff');
  BitReader shortReader(one);
  shortReader.readBits(8);
  EXPECT_FALSE(shortReader.failed());
  EXPECT_EQ(shortReader.readBits(1), 0u);
  EXPECT_TRUE(shortReader.failed());

  const std::string sixteenZeros(16, '\0');
  BitReader zeros(sixteenZeros);
  EXPECT_EQ(zeros.readExpGolomb(), 0u);
  EXPECT_TRUE(zeros.failed());
}

namespace q = quantized;

const q::Integration kIntegration = q::integrationOf(60, 4, Vec2(0, Real(-9.81)));

TEST(QuantizedPrediction, MatchesSemiImplicitEulerInClosedForm) {
  // v = 1.5 m/s, a = -9.8125 m/s^2 at 64 Hz with 4 substeps, over n ticks
  // (4n substeps of dt/4): x = dt * (n*v + a*dt*n*(4n+1)/8), v' = v + n*a*dt.
  const q::Integration integration{.tickHz = 64, .subSteps = 4};
  const double dt = 1.0 / 64;
  const double v = 1.5;
  const double a = -9.8125;
  q::State state;
  state.awake = true;
  state.velocity[1] = std::llround(v / q::kVelocityUnit);
  state.acceleration[1] = std::llround(a * dt / q::kVelocityUnit * q::kAccelerationScale);
  for (const std::int64_t n : {1, 2, 7, 30}) {
    const q::State next = q::predict(state, n, integration);
    const double x = dt * (double(n) * v + a * dt * double(n * (4 * n + 1)) / 8);
    EXPECT_NEAR(double(next.position[1]) * q::kPositionUnit, x, q::kPositionUnit) << n;
    EXPECT_NEAR(double(next.velocity[1]) * q::kVelocityUnit, v + double(n) * a * dt,
                q::kVelocityUnit)
        << n;
  }
  state.awake = false;
  EXPECT_EQ(q::predict(state, 10, integration), state);
}

TEST(QuantizedPrediction, DeadZone_SendsNothingWithinAQuantum_ElseTheNearestQuantum) {
  q::State predicted;
  q::State truth;
  truth.position[0] = q::kPositionQuantum - 1;
  truth.velocity[2] = -q::kVelocityQuantum;
  truth.position[1] = 5 * q::kPositionQuantum + 3;
  const q::Residuals residuals = q::residualsBetween(predicted, truth);
  EXPECT_EQ(residuals, (q::Residuals{0, 5, 0, 0, 0, -1}));
}

// A small world of falling circles for stream tests.
World fallingWorld() {
  World world;
  const std::array<Vec2, 4> ground = {Vec2(-20, -1), Vec2(20, -1), Vec2(20, 0), Vec2(-20, 0)};
  world.createPolygon(ground, {.properties = {.isStatic = true}});
  for (int i = 0; i < 30; ++i) {
    world.createCircle(Vec2(Real(-15 + i), Real(1 + (i % 5) * 0.7)), Real(0.3));
  }
  return world;
}

std::vector<std::uint32_t> idsOf(const World& world) {
  std::vector<std::uint32_t> ids;
  for (const BodyId id : world.bodyIds()) ids.push_back(id.value);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<std::uint32_t> stepAndCollectMoved(World& world, int ticks) {
  std::vector<std::uint32_t> moved;
  for (int i = 0; i < ticks; ++i) {
    world.step(Real(1) / 60);
    for (const BodyId id : world.movedBodies()) moved.push_back(id.value);
  }
  return moved;
}

TEST(QuantizedStream, SameWorldTwice_GivesTheSameBytes) {
  std::vector<std::string> streams[2];
  for (auto& stream : streams) {
    World world = fallingWorld();
    q::Encoder encoder;
    encoder.reset(world, 0);
    stream.push_back(encoder.keyFrame(world, {.tick = 0, .integration = kIntegration, .added = idsOf(world)}));
    for (std::uint64_t tick = 2; tick <= 120; tick += 2) {
      const auto moved = stepAndCollectMoved(world, 2);
      stream.push_back(encoder.delta(world, {.tick = tick, .integration = kIntegration, .changed = moved}));
    }
  }
  EXPECT_EQ(streams[0], streams[1]);
}

TEST(QuantizedStream, LateJoinerKeyFrame_ThenDeltas_MatchTheEarlyClient) {
  World world = fallingWorld();
  q::Encoder encoder;
  q::Decoder early;
  q::Decoder late;
  std::vector<BodyState> moved;
  encoder.reset(world, 0);
  const auto ids = idsOf(world);
  ASSERT_FALSE(early.decode(encoder.keyFrame(world, {.tick = 0, .integration = kIntegration, .added = ids}),
                            true, {}, ids, moved));
  std::uint64_t tick = 0;
  for (int snapshot = 0; snapshot < 80; ++snapshot) {
    tick += 2;
    const auto changed = stepAndCollectMoved(world, 2);
    if (snapshot == 20) {
      // A body spawned between broadcasts, seen by the joiner's key frame
      // (taken now, between broadcasts) and by everyone's next delta.
      world.createCircle(Vec2(0, 5), Real(0.4));
      const auto now = idsOf(world);
      ASSERT_FALSE(late.decode(encoder.keyFrame(world, {.tick = tick, .integration = kIntegration, .added = now}),
                               true, {}, now, moved));
    }
    std::vector<std::uint32_t> added;
    if (snapshot == 20) added.push_back(idsOf(world).back());
    const std::string delta =
        encoder.delta(world, {.tick = tick, .integration = kIntegration, .added = added, .changed = changed});
    ASSERT_FALSE(early.decode(delta, false, {}, added, moved));
    if (snapshot >= 20) {
      const auto error = late.decode(delta, false, {}, added, moved);
      ASSERT_FALSE(error) << *error;
      ASSERT_EQ(late.baseline().bodies, early.baseline().bodies) << "snapshot " << snapshot;
    }
  }
}

TEST(QuantizedStream, HostileBytes_GetAnErrorAndForgetTheBaseline) {
  World world = fallingWorld();
  q::Encoder encoder;
  encoder.reset(world, 0);
  const auto ids = idsOf(world);
  const std::string key = encoder.keyFrame(world, {.tick = 0, .integration = kIntegration, .added = ids});
  const auto changed = stepAndCollectMoved(world, 2);
  const std::string delta = encoder.delta(world, {.tick = 2, .integration = kIntegration, .changed = changed});
  std::vector<BodyState> moved;

  q::Decoder decoder;
  auto error = decoder.decode(delta, false, {}, {}, moved);
  ASSERT_TRUE(error);
  EXPECT_EQ(*error, "quantized_bodies: a delta before any key frame");
  ASSERT_FALSE(decoder.decode(key, true, {}, ids, moved));
  error = decoder.decode(delta.substr(0, delta.size() / 2), false, {}, {}, moved);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("cut short"), std::string::npos) << *error;
  EXPECT_TRUE(moved.empty());
  EXPECT_FALSE(decoder.baseline().valid);

  // Key frame, then the same delta twice: the second is against a stale tick.
  ASSERT_FALSE(decoder.decode(key, true, {}, ids, moved));
  ASSERT_FALSE(decoder.decode(delta, false, {}, {}, moved));
  error = decoder.decode(delta, false, {}, {}, moved);
  ASSERT_TRUE(error);
  EXPECT_EQ(*error, "quantized_bodies: coded against tick 0 but the last one decoded was tick 2");

  // Random bytes and bit flips: errors or states, never a crash.
  std::mt19937 random(11);
  for (int trial = 0; trial < 20000; ++trial) {
    std::string bytes = trial % 2 == 0 ? key : delta;
    if (trial % 4 < 2) {
      bytes[random() % bytes.size()] ^= char(1 << (random() % 8));
    } else {
      bytes.resize(1 + random() % 64);
      for (char& c : bytes) c = char(random());
    }
    q::Decoder fresh;
    if (trial % 2 == 1) {
      ASSERT_FALSE(fresh.decode(key, true, {}, ids, moved));
    }
    error = fresh.decode(bytes, trial % 2 == 0, {}, trial % 2 == 0 ? ids : std::vector<std::uint32_t>{}, moved);
    if (error) {
      EXPECT_EQ(error->rfind("quantized_bodies: ", 0), 0u) << *error;
    }
    for (const BodyState& state : moved) {
      EXPECT_TRUE(std::isfinite(state.position.x()) && std::isfinite(state.angle));
    }
  }
}

}  // namespace
}  // namespace impulse::wire
