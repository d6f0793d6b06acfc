// The step must not touch the heap once a scene has reached a steady state:
// scratch arrays keep their capacity from step to step.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "impulse/scenes/stress.h"
#include "impulse/world.h"
#include "world_test_support.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// Counting replacements of the global allocation functions (this test binary only).
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
// The nothrow pair too (std::stable_sort's buffer): left to a sanitizer's
// runtime, its blocks would come from there and go back through free above.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace impulse {
namespace {

TEST(SteadyStateStep, DoesNotAllocate_WhenPyramidRests) {
  World world(test::sleepless());  // every body kept in the step
  buildPyramid(world, 20);
  for (int i = 0; i < 120; ++i) world.step(Real(1.0 / 60.0));

  long before = g_allocations.load();
  ASSERT_GT(before, 0) << "the counter must see the scene being built";
  for (int i = 0; i < 60; ++i) world.step(Real(1.0 / 60.0));
  EXPECT_EQ(g_allocations.load() - before, 0) << "heap allocations during 60 steady steps";
}

TEST(SteadyStateStep, DoesNotAllocate_WhenRainSettles) {
  World world;
  buildRain(world, 300);
  for (int i = 0; i < 600; ++i) world.step(Real(1.0 / 60.0));

  long before = g_allocations.load();
  for (int i = 0; i < 60; ++i) world.step(Real(1.0 / 60.0));
  EXPECT_EQ(g_allocations.load() - before, 0) << "heap allocations during 60 steps of a settled pile";
}

// A swinging chain of pinned boxes: joints reuse their step arrays too.
TEST(SteadyStateStep, DoesNotAllocate_WhenAChainSwings) {
  World world;
  BodyId previous{};
  for (int i = 0; i < 10; ++i) {
    Vec2 pin(Real(i), 10);
    BodyOptions options;
    BodyId link = world.createPolygon(std::vector<Vec2>{{pin.x(), 9.9f}, {pin.x() + 1, 9.9f}, {pin.x() + 1, 10.1f}, {pin.x(), 10.1f}}, options).id;
    ASSERT_TRUE(world.createJoint({link, previous, pin, pin, false, RevoluteJointSettings{}}).ok());
    previous = link;
  }
  for (int i = 0; i < 60; ++i) world.step(Real(1.0 / 60.0));
  long before = g_allocations.load();
  for (int i = 0; i < 60; ++i) world.step(Real(1.0 / 60.0));
  EXPECT_EQ(g_allocations.load() - before, 0) << "heap allocations during 60 steps of a swinging chain";
}

// A column of circles squeezed into a shaft shorter than it, without
// gravity: the push pass runs step after step on the same contacts (a crowd
// that moves would also make and break contacts, which is not the solver).
TEST(SteadyStateStep, DoesNotAllocate_WhileOverlapIsPushedOut) {
  WorldSettings settings = test::sleepless();
  settings.gravity = Vec2::Zero();
  World world(settings);
  for (Real side : {Real(-1), Real(1)}) {
    test::addBox(world, {.center = Vec2(side * Real(1.01), 2.5), .halfWidth = 0.5, .halfHeight = 3.5, .isStatic = true});
    test::addBox(world, {.center = Vec2(0, Real(2.5) + side * 3), .halfWidth = 1.5, .halfHeight = 0.5, .isStatic = true});
  }
  for (int k = 0; k < 6; ++k) test::addCircle(world, {.center = Vec2(0, Real(0.5 + 0.8 * k)), .radius = 0.5});
  for (int i = 0; i < 10; ++i) world.step(Real(1.0 / 60.0));

  long before = g_allocations.load();
  int pushedSteps = 0;
  for (int i = 0; i < 20; ++i) {
    world.step(Real(1.0 / 60.0));
    pushedSteps += world.profile().passes.pushedContacts > 0 ? 1 : 0;
  }
  EXPECT_EQ(g_allocations.load() - before, 0) << "heap allocations during 20 steps of pushing";
  EXPECT_EQ(pushedSteps, 20) << "the push pass must run in every step measured";
}

}  // namespace
}  // namespace impulse
