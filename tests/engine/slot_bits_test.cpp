// The set of active contacts: members walked highest slot first, each once,
// across word boundaries; a walk can leave out another set's members; and
// the world keeps it equal to "contacts with an awake body" as bodies sleep
// and wake.

#include "slot_bits.h"

#include <gtest/gtest.h>

#include <vector>

#include "world_test_support.h"

namespace impulse {
namespace {

std::vector<std::int32_t> walk(const SlotBits& bits) {
  std::vector<std::int32_t> slots;
  bits.forEachDescending([&](std::int32_t slot) { slots.push_back(slot); });
  return slots;
}

TEST(SlotBits, WalksMembersHighestFirst_AcrossWords) {
  SlotBits bits;
  for (std::int32_t slot : {0, 63, 64, 5, 200, 127}) bits.insert(slot);
  bits.insert(64);  // twice: still one member
  bits.erase(5);
  bits.erase(1000);  // beyond the words: nothing
  EXPECT_EQ(walk(bits), (std::vector<std::int32_t>{200, 127, 64, 63, 0}));
}

TEST(SlotBits, WalkExcept_LeavesOutTheOtherSetsMembers) {
  SlotBits all;
  SlotBits seen;
  for (std::int32_t slot : {1, 2, 70, 130}) all.insert(slot);
  seen.assign(all);
  all.insert(3);
  all.insert(300);  // beyond `seen`'s words
  seen.erase(70);
  std::vector<std::int32_t> fresh;
  all.forEachDescendingExcept(seen, [&](std::int32_t slot) { fresh.push_back(slot); });
  EXPECT_EQ(fresh, (std::vector<std::int32_t>{300, 70, 3}));
}

// A box resting on the floor sleeps, another falls onto it and wakes it:
// the narrow phase must see the woken contact again (the box settles back
// and sleeps, and the falling box never sinks into it).
TEST(SlotBits, SleepingContactsLeaveAndWokenOnesReturn_PileStaysApart) {
  World world;
  test::addBox(world, {.center = Vec2(0, -0.5f), .halfWidth = 10, .halfHeight = 0.5f, .isStatic = true});
  const BodyId lower = test::addBox(world, {.center = Vec2(0, 0.5f)});
  test::simulate(world, 3);
  ASSERT_EQ(world.awakeBodyCount(), 0) << "the box should sleep";
  const BodyId upper = test::addBox(world, {.center = Vec2(0, 3)});
  test::simulate(world, 3);
  EXPECT_NEAR(test::stateOf(world, lower).position.y(), 0.5, 0.01);
  EXPECT_NEAR(test::stateOf(world, upper).position.y(), 1.5, 0.01);
  test::simulate(world, 3);
  EXPECT_EQ(world.awakeBodyCount(), 0) << "both boxes should sleep again";
}

}  // namespace
}  // namespace impulse
