// A stack standing on a body that only steep contacts hold (a keystone
// wedged between two posts): the support pass levels the keystone through
// its steep joints and holds the stack on it up storey by storey, so the
// stack's soft contacts do not give under its weight. Not through a round
// body's steep contacts: a circle in a hollow holds no rows up.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

#include "world_test_support.h"

namespace impulse::test {
namespace {

/// The area centroid of the convex polygon `corners` (shoelace).
Vec2 centroidOf(std::span<const Vec2> corners) {
  Real twiceArea = 0;
  Vec2 sum = Vec2::Zero();
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2& a = corners[i];
    const Vec2& b = corners[(i + 1) % corners.size()];
    const Real cross = a.x() * b.y() - b.x() * a.y();
    twiceArea += cross;
    sum += cross * (a + b);
  }
  return sum / (3 * twiceArea);
}

/// A dynamic STONE body of the convex polygon `corners` (world coordinates,
/// anticlockwise).
BodyId addStone(World& world, std::span<const Vec2> corners) {
  const PolygonBuild built = buildPolygon(corners);
  EXPECT_EQ(built.error, ShapeError::None);
  BodyDef def;
  def.shape = Shape::makePolygon(built.polygon);
  def.position = centroidOf(corners);
  def.material = Material::Stone;
  CreateResult result = world.createBody(def);
  EXPECT_TRUE(result.ok()) << result.error;
  return result.id;
}

// Two posts on the ground whose inner faces lean 5.7 degrees apart, a
// keystone wedged between them (its faces' normals 5.7 degrees off level:
// no level contact reaches it), and four 1 m x 0.5 m boxes stacked on it.
// After 2 s the top box stands on the lowest within 0.5 mm of where it was
// built: the three contacts above the lowest box are held up (on their soft
// contacts alone they gave 5.1 mm under the boxes' weight).
TEST(WedgedStack, StackOnAKeystoneIsHeldUp_ItsContactsDoNotGive) {
  World world;
  addGround(world);
  const std::array<Vec2, 4> leftPost = {Vec2(-2.5, 0), Vec2(-0.4, 0), Vec2(-0.6, 2), Vec2(-2.5, 2)};
  const std::array<Vec2, 4> rightPost = {Vec2(0.4, 0), Vec2(2.5, 0), Vec2(2.5, 2), Vec2(0.6, 2)};
  const std::array<Vec2, 4> keystone = {Vec2(-0.5, 1), Vec2(0.5, 1), Vec2(0.6, 2), Vec2(-0.6, 2)};
  addStone(world, leftPost);
  addStone(world, rightPost);
  const BodyId key = addStone(world, keystone);
  const Real keystoneStart = stateOf(world, key).position.y();
  std::array<BodyId, 4> boxes{};
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    boxes[i] = addBox(world, {.center = Vec2(0, Real(2.25 + 0.5 * double(i))), .halfWidth = Real(0.5),
                              .halfHeight = Real(0.25), .material = Material::Stone});
  }
  const Real built = stateOf(world, boxes.back()).position.y() - stateOf(world, boxes.front()).position.y();
  simulate(world, 2);
  const Real standing = stateOf(world, boxes.back()).position.y() - stateOf(world, boxes.front()).position.y();
  const Real keystoneDrop = keystoneStart - stateOf(world, key).position.y();
  std::printf("measured: stack above its lowest box shortened %.3g mm, keystone dropped %.3g mm\n",
              1000 * double(built - standing), 1000 * double(keystoneDrop));
  EXPECT_LT(built - standing, Real(0.0005));
  EXPECT_LT(keystoneDrop, Real(0.05)) << "the keystone stays wedged";
}

/// `count` of the keystones above side by side, 6 m apart, each with its four
/// boxes and its own 6 m of ground: the keystones hang on their posts, and
/// their joints hold on the hanging bodies' ramp (kHangingHold,
/// contact_solver.h).
void buildWedgedStacks(World& world, int count) {
  for (int k = 0; k < count; ++k) {
    const Real x = Real(6 * k - 3 * (count - 1));
    addBox(world, {.center = Vec2(x, -1), .halfWidth = 3, .halfHeight = 1, .isStatic = true});
    const std::array<Vec2, 4> leftPost = {Vec2(x - 2.5f, 0), Vec2(x - 0.4f, 0), Vec2(x - 0.6f, 2), Vec2(x - 2.5f, 2)};
    const std::array<Vec2, 4> rightPost = {Vec2(x + 0.4f, 0), Vec2(x + 2.5f, 0), Vec2(x + 2.5f, 2), Vec2(x + 0.6f, 2)};
    const std::array<Vec2, 4> keystone = {Vec2(x - 0.5f, 1), Vec2(x + 0.5f, 1), Vec2(x + 0.6f, 2), Vec2(x - 0.6f, 2)};
    addStone(world, leftPost);
    addStone(world, rightPost);
    addStone(world, keystone);
    for (int i = 0; i < 4; ++i) {
      addBox(world, {.center = Vec2(x, Real(2.25 + 0.5 * i)), .halfWidth = Real(0.5), .halfHeight = Real(0.25),
                     .material = Material::Stone});
    }
  }
}

/// The state hash after each of `steps` steps of 150 wedged stacks (enough
/// contacts for a colour's bundles to be split between threads).
std::vector<std::uint64_t> wedgedStacksHashes(SimdWidth width, int workers, int steps) {
  WorldSettings settings;
  settings.bounds = {Vec2(-500, -10), Vec2(500, 20)};
  settings.simdWidth = width;
  settings.tasks = {.workerCount = workers};
  World world(settings);
  buildWedgedStacks(world, 150);
  std::vector<std::uint64_t> hashes;
  for (int i = 0; i < steps; ++i) {
    world.step(kDt);
    hashes.push_back(world.stateHash());
  }
  return hashes;
}

// A bundle takes each lane's ramp from its own contact (whether a body of
// it hangs): the bits do not depend on which contacts share a bundle (four
// lanes on SSE2, eight on AVX2) nor on how many threads share a colour's
// bundles.
TEST(WedgedStack, HangingWedgesGiveTheSameBitsAtEveryLaneWidthAndOnTwoThreads) {
  const int steps = 40;
  const std::vector<std::uint64_t> widest = wedgedStacksHashes(SimdWidth::Best, 1, steps);
  EXPECT_NE(widest.front(), widest.back()) << "the stacks settle";
  EXPECT_EQ(wedgedStacksHashes(SimdWidth::Sse2, 1, steps), widest);
  EXPECT_EQ(wedgedStacksHashes(SimdWidth::Best, 2, steps), widest);
}

// A circle resting in the hollow between two circles on the ground (its
// contacts 30 degrees off level), walls keeping those apart, and four boxes
// stacked on it. The pass does not level bodies through a round shape's
// steep contacts (rows between circles found standing on such circles kept
// a pile of them stirring): over the first half second it holds up only
// the two circles on the ground, not the boxes (five rows when it did).
TEST(WedgedStack, StackOnACircleInAHollow_IsNotHeldUp) {
  World world;
  addGround(world);
  addBox(world, {.center = Vec2(-1.5, 1), .halfWidth = Real(0.5), .halfHeight = 1, .isStatic = true});
  addBox(world, {.center = Vec2(1.5, 1), .halfWidth = Real(0.5), .halfHeight = 1, .isStatic = true});
  addCircle(world, {.center = Vec2(-0.5, 0.5), .radius = Real(0.5)});
  addCircle(world, {.center = Vec2(0.5, 0.5), .radius = Real(0.5)});
  const Real hollowTop = Real(0.5 + std::sqrt(0.75) + 0.5);
  addCircle(world, {.center = Vec2(0, hollowTop - Real(0.5)), .radius = Real(0.5)});
  for (int i = 0; i < 4; ++i) {
    addBox(world, {.center = Vec2(0, hollowTop + Real(0.25 + 0.5 * i)), .halfWidth = Real(0.5),
                   .halfHeight = Real(0.25)});
  }
  int mostRows = 0;
  for (int i = 0; i < stepsFor(0.5); ++i) {
    world.step(kDt);
    mostRows = std::max(mostRows, world.profile().passes.supportRows);
  }
  std::printf("measured: at most %d support rows a step\n", mostRows);
  EXPECT_EQ(mostRows, 2);
}

}  // namespace
}  // namespace impulse::test
