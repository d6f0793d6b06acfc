// The one-lane type (simd::F1), which solves a support row alone, gives the
// bits a lane of the vector types gives: the support pass then moves the
// same bodies the same way whether its row came alone or in a bundle.

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "simd.h"

namespace impulse::test {
namespace {

using simd::F1;
using simd::F4;

// Values where lanes and scalar code could part: signed zeros, NaN,
// infinities, subnormals, and ordinary numbers of both signs.
std::vector<float> edgeValues() {
  return {0.0f,
          -0.0f,
          1.0f,
          -1.5f,
          3.0e-3f,
          -7.25e5f,
          std::numeric_limits<float>::denorm_min(),
          -std::numeric_limits<float>::denorm_min(),
          std::numeric_limits<float>::max(),
          std::numeric_limits<float>::infinity(),
          -std::numeric_limits<float>::infinity(),
          std::numeric_limits<float>::quiet_NaN()};
}

std::uint32_t laneBits(F1 a) {
  float lane = 0;
  simd::store(&lane, a);
  return std::bit_cast<std::uint32_t>(lane);
}

std::uint32_t firstLaneBits(F4 a) {
  float lanes[4];
  simd::store(lanes, a);
  return std::bit_cast<std::uint32_t>(lanes[0]);
}

F1 one(float x) { return simd::broadcast<F1>(x); }
F4 four(float x) { return simd::broadcast<F4>(x); }

// Every binary operation the support pass uses, on every pair of values.
TEST(SimdLane, BinaryOperations_GiveTheBitsOfAVectorLane) {
  for (float x : edgeValues()) {
    for (float y : edgeValues()) {
      SCOPED_TRACE(testing::Message() << x << " and " << y);
      const F1 a = one(x), b = one(y);
      const F4 c = four(x), d = four(y);
      EXPECT_EQ(laneBits(a + b), firstLaneBits(c + d));
      EXPECT_EQ(laneBits(a - b), firstLaneBits(c - d));
      EXPECT_EQ(laneBits(a * b), firstLaneBits(c * d));
      EXPECT_EQ(laneBits(a / b), firstLaneBits(c / d));
      EXPECT_EQ(laneBits(simd::max(a, b)), firstLaneBits(simd::max(c, d)));
      EXPECT_EQ(laneBits(simd::min(a, b)), firstLaneBits(simd::min(c, d)));
      EXPECT_EQ(laneBits(simd::clamp(a, -b, b)), firstLaneBits(simd::clamp(c, -d, d)));
      EXPECT_EQ(laneBits(simd::greater(a, b)), firstLaneBits(simd::greater(c, d)));
      EXPECT_EQ(laneBits(simd::less(a, b)), firstLaneBits(simd::less(c, d)));
      EXPECT_EQ(laneBits(simd::atLeast(a, b)), firstLaneBits(simd::atLeast(c, d)));
      EXPECT_EQ(laneBits(simd::notEqual(a, b)), firstLaneBits(simd::notEqual(c, d)));
      EXPECT_EQ(laneBits(simd::select(simd::greater(a, b), a, b)), firstLaneBits(simd::select(simd::greater(c, d), c, d)));
      EXPECT_EQ(laneBits(simd::both(simd::less(a, b), a)), firstLaneBits(simd::both(simd::less(c, d), c)));
      EXPECT_EQ(laneBits(simd::either(simd::less(a, b), a)), firstLaneBits(simd::either(simd::less(c, d), c)));
      EXPECT_EQ(simd::any(simd::greater(a, b)), simd::any(simd::greater(c, d)));
    }
  }
}

TEST(SimdLane, UnaryOperations_GiveTheBitsOfAVectorLane) {
  for (float x : edgeValues()) {
    SCOPED_TRACE(x);
    EXPECT_EQ(laneBits(-one(x)), firstLaneBits(-four(x)));
    EXPECT_EQ(laneBits(simd::negated(one(x))), firstLaneBits(simd::negated(four(x))));
    EXPECT_EQ(laneBits(simd::abs(one(x))), firstLaneBits(simd::abs(four(x))));
    EXPECT_EQ(laneBits(simd::sqrt(one(x))), firstLaneBits(simd::sqrt(four(x))));
  }
}

// An index column and a lane mask read and written as the vector types do.
TEST(SimdLane, IndicesAndMasks_RoundTrip) {
  const std::int32_t index = 4711;
  std::int32_t written = 0;
  simd::storeInts(&written, simd::loadInts<F1>(&index));
  EXPECT_EQ(written, index);
  EXPECT_TRUE(simd::any(simd::intGreater(simd::loadInts<F1>(&index), 4710)));
  EXPECT_FALSE(simd::any(simd::intGreater(simd::loadInts<F1>(&index), 4711)));
  EXPECT_EQ(simd::bitsOf(simd::maskOfBits<F1>(1)), 1);
  EXPECT_EQ(simd::bitsOf(simd::maskOfBits<F1>(2)), 0);
  EXPECT_EQ(laneBits(simd::maskOfBits<F1>(1)), firstLaneBits(simd::maskOfBits<F4>(1)));
}

// A row's columns are its floats, in order, and back.
TEST(SimdLane, ColumnsOfOneRow_AreItsFloats) {
  const float row[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  const float* rows[1] = {row};
  F1 columns[8];
  simd::loadColumns(rows, columns);
  float back[8] = {};
  float* backRows[1] = {back};
  simd::storeColumns(columns, backRows);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(laneBits(columns[i]), std::bit_cast<std::uint32_t>(row[i]));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(back[i], row[i]);
  for (int i = 4; i < 8; ++i) EXPECT_EQ(back[i], 0) << "only the first four are written back";
}

}  // namespace
}  // namespace impulse::test
