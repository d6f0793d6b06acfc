// The step must not touch the heap once a scene has reached a steady state:
// scratch arrays keep their capacity from step to step.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "impulse/scenes/stress.h"
#include "impulse/world.h"

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

namespace impulse {
namespace {

TEST(SteadyStateStep, DoesNotAllocate_WhenPyramidRests) {
  WorldSettings settings;
  settings.enableSleep = false;  // keep every body in the step
  World world(settings);
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

}  // namespace
}  // namespace impulse
