// The contact pair set: the same answers as std::set under a long random mix
// of inserts and erases (which exercises growth and backward-shift deletion
// over wrapped probe runs), and duplicates refused.

#include "pair_set.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>

namespace impulse {
namespace {

TEST(PairSet, AgreesWithAnOrderedSetUnderRandomInsertsAndErases) {
  PairSet set;
  std::set<std::uint64_t> reference;
  std::mt19937_64 random(7);
  // Few distinct keys, so erases hit and probe runs collide and wrap.
  std::uniform_int_distribution<std::uint64_t> keys(1, 3000);
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t key = keys(random);
    if (random() % 3 == 0) {
      set.erase(key);
      reference.erase(key);
    } else {
      EXPECT_EQ(set.insert(key), reference.insert(key).second);
    }
    const std::uint64_t probe = keys(random);
    ASSERT_EQ(set.contains(probe), reference.count(probe) == 1) << "after operation " << i;
  }
  EXPECT_EQ(set.size(), reference.size());
  for (std::uint64_t key = 1; key <= 3000; ++key) EXPECT_EQ(set.contains(key), reference.count(key) == 1);
}

TEST(PairSet, EmptySetHoldsNothingAndErasingAbsentKeysChangesNothing) {
  PairSet set;
  EXPECT_FALSE(set.contains(42));
  set.erase(42);
  EXPECT_TRUE(set.insert(42));
  EXPECT_FALSE(set.insert(42));
  set.erase(41);
  EXPECT_TRUE(set.contains(42));
  EXPECT_EQ(set.size(), 1u);
  set.erase(42);
  EXPECT_FALSE(set.contains(42));
  EXPECT_EQ(set.size(), 0u);
}

}  // namespace
}  // namespace impulse
