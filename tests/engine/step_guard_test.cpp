// The step guard's repair, tried directly: a body whose state has turned
// non-finite (which no accepted input can cause, so the private state is
// corrupted by hand) leaves the guard finite, where its step began, at rest.
#include <gtest/gtest.h>

#include <limits>

#include "body_shapes.h"
#include "step_guard.h"

namespace impulse {
namespace {

constexpr Real kInf = std::numeric_limits<Real>::infinity();
const Real kNaN = std::numeric_limits<Real>::quiet_NaN();

// One awake circle of radius 0.5 that began the step at `start`.
std::int32_t addMovedCircle(WorldData& world, const Vec2& start) {
  const auto slot = static_cast<std::int32_t>(world.bodies.size());
  world.bodies.emplace_back();
  Body& body = world.bodies.back();
  body.alive = true;
  body.awake = true;
  body.center0 = start;
  body.transform.p = start;
  ShapeDef circle;
  circle.shape = Shape::makeCircle(Real(0.5));
  createShapeProxy(world, attachShape(world, slot, circle));
  world.awakeBodies.push_back(slot);
  world.movedBodies.push_back(world.idOf(slot));
  return slot;
}

TEST(StepGuard, NonFiniteBody_IsPutBackWhereItsStepBegan_AtRest) {
  WorldData world;
  const std::int32_t broken = addMovedCircle(world, Vec2(5, 5));
  const std::int32_t healthy = addMovedCircle(world, Vec2(10, 5));
  world.bodies[broken].transform.p = Vec2(kNaN, 7);
  world.bodies[broken].transform.q = Rot{kNaN, kNaN};
  world.bodies[broken].linearVelocity = Vec2(kInf, 0);
  world.bodies[broken].angularVelocity = kNaN;
  world.bodies[healthy].linearVelocity = Vec2(3, 4);

  StepGuardReport report;
  guardStep(world, report);

  const Body& repaired = world.bodies[broken];
  EXPECT_EQ(repaired.transform.p, Vec2(5, 5));
  EXPECT_EQ(repaired.transform.q.c, 1);
  EXPECT_EQ(repaired.transform.q.s, 0);
  EXPECT_EQ(repaired.linearVelocity, Vec2::Zero());
  EXPECT_EQ(repaired.angularVelocity, 0);
  EXPECT_EQ(report.repairedBodies, 1u);
  // The broad phase holds the repaired box again.
  const std::int32_t shape = repaired.shapeHead;
  EXPECT_TRUE(world.broadPhase.fatAABB(world.shapes[shape].proxyKey).contains(shapeAABB(world, shape)));
  // Healthy bodies are left alone.
  EXPECT_EQ(world.bodies[healthy].linearVelocity, Vec2(3, 4));
  EXPECT_TRUE(report.escaped.empty());
}

TEST(StepGuard, StartOfStepAlsoBroken_FallsBackToTheOrigin) {
  WorldData world;
  const std::int32_t broken = addMovedCircle(world, Vec2(5, 5));
  world.bodies[broken].center0 = Vec2(kNaN, kNaN);
  world.bodies[broken].transform.p = Vec2(kNaN, kNaN);
  StepGuardReport report;
  guardStep(world, report);
  EXPECT_EQ(world.bodies[broken].transform.p, Vec2::Zero());
  EXPECT_EQ(report.repairedBodies, 1u);
}

}  // namespace
}  // namespace impulse
