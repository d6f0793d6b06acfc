// Input limits at the engine API: the attacks of issue 12 are refused with an
// error naming the field and the range, the world unchanged; the largest
// accepted inputs keep every state finite and within the limits.
#include "world_test_support.h"

namespace impulse::test {
namespace {

const InputLimits kLimits;

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The sandbox of the server: floor and two walls inside the default bounds.
World sandbox() {
  World world;
  addBox(world, {.center = Vec2(12.5, -0.5), .halfWidth = 12.5, .halfHeight = 0.5, .isStatic = true});
  addBox(world, {.center = Vec2(-0.5, 9), .halfWidth = 0.5, .halfHeight = 10, .isStatic = true});
  addBox(world, {.center = Vec2(25.5, 9), .halfWidth = 0.5, .halfHeight = 10, .isStatic = true});
  return world;
}

/// Every live body finite and within the speed limits.
void expectSaneStates(const World& world) {
  ASSERT_TRUE(allStatesFinite(world));
  for (BodyId id : world.bodyIds()) {
    const BodyState s = stateOf(world, id);
    EXPECT_LE(s.linearVelocity.norm(), kLimits.maxSpeed) << "body " << id.value;
    EXPECT_LE(std::abs(s.angularVelocity), kLimits.maxAngularSpeed) << "body " << id.value;
  }
}

TEST(InputLimits, HugeImpulseOnTinyCircle_IsRefusedWithFieldAndRange) {
  World world = sandbox();
  const CreateResult ball = world.createCircle(Vec2(5, 0.02f), Real(0.02));
  ASSERT_TRUE(ball.ok()) << ball.error;
  const std::uint64_t before = world.stateHash();
  const InputResult result = world.applyImpulse(ball.id, Vec2(3.4e38f, 0));
  EXPECT_FALSE(result.ok());
  EXPECT_TRUE(mentions(result.error, "impulse")) << result.error;
  EXPECT_TRUE(mentions(result.error, "0..500 m/s")) << result.error;
  EXPECT_EQ(world.stateHash(), before);
}

TEST(InputLimits, HugeImpulseAtFarPoint_IsRefused) {
  World world = sandbox();
  const BodyId ball = addCircle(world, {.center = Vec2(5, 1), .radius = 0.5f});
  const std::uint64_t before = world.stateHash();
  const InputResult far = world.applyImpulse(ball, Vec2(3e38f, 3e38f), Vec2(3e38f, 3e38f));
  EXPECT_FALSE(far.ok());
  EXPECT_TRUE(mentions(far.error, "impulse point")) << far.error;
  // A point inside the bounds but a lever that spins too fast.
  const InputResult spin = world.applyImpulse(ball, Vec2(0, 2000), Vec2(40, 1));
  EXPECT_FALSE(spin.ok());
  EXPECT_TRUE(mentions(spin.error, "0..1000 rad/s")) << spin.error;
  EXPECT_EQ(world.stateHash(), before);
}

TEST(InputLimits, ImpulseWithinLimits_IsApplied) {
  World world = sandbox();
  const BodyId ball = addCircle(world, {.center = Vec2(5, 1), .radius = 0.5f});
  const Real mass = world.bodyDescription(ball)->mass.mass;
  ASSERT_TRUE(world.applyImpulse(ball, Vec2(10 * mass, 0)));
  EXPECT_NEAR(stateOf(world, ball).linearVelocity.x(), 10, 1e-4);
}

TEST(InputLimits, SpawnVelocityAndSpinPastTheLimits_AreRefused) {
  World world = sandbox();
  const int bodies = world.bodyCount();
  BodyOptions falling;
  falling.linearVelocity = Vec2(0, -1e38f);
  const CreateResult fast = world.createCircle(Vec2(5, 0.5f), Real(0.5), falling);
  EXPECT_FALSE(fast.ok());
  EXPECT_TRUE(mentions(fast.error, "speeds must lie within 0..500 m/s")) << fast.error;
  BodyOptions spinning;
  spinning.angularVelocity = Real(3.4e38);
  const CreateResult spun = world.createCircle(Vec2(5, 0.5f), Real(0.5), spinning);
  EXPECT_FALSE(spun.ok());
  EXPECT_TRUE(mentions(spun.error, "angular speeds must lie within 0..1000 rad/s")) << spun.error;
  EXPECT_EQ(world.bodyCount(), bodies);
}

TEST(InputLimits, GravityForceAndVelocityPastTheLimits_AreRefused) {
  World world = sandbox();
  const BodyId ball = addCircle(world, {.center = Vec2(5, 1), .radius = 0.5f});
  const std::uint64_t before = world.stateHash();

  const InputResult gravity = world.setGravity(Vec2(0, -5000));
  EXPECT_TRUE(mentions(gravity.error, "within +-1000 m/s^2")) << gravity.error;
  EXPECT_EQ(world.gravity(), kDefaultGravity);

  const InputResult force = world.applyForce(ball, Vec2(1e30f, 0));
  EXPECT_TRUE(mentions(force.error, "force / mass must lie within")) << force.error;
  const InputResult torque = world.applyForce(ball, Vec2(0, 1e6f), Vec2(60, 1));
  EXPECT_TRUE(mentions(torque.error, "torque / inertia must lie within")) << torque.error;

  const InputResult velocity = world.setVelocity(ball, Vec2(501, 0), 0);
  EXPECT_TRUE(mentions(velocity.error, "0..500 m/s")) << velocity.error;
  const InputResult nan = world.setVelocity(ball, Vec2(std::nanf(""), 0), 0);
  EXPECT_TRUE(mentions(nan.error, "not a finite number")) << nan.error;
  EXPECT_EQ(world.stateHash(), before);
}

TEST(InputLimits, ForcesPendingForOneStepAddUp) {
  World world = sandbox();
  const BodyId ball = addCircle(world, {.center = Vec2(5, 1), .radius = 0.5f});
  const Real mass = world.bodyDescription(ball)->mass.mass;
  const Vec2 largest(kLimits.maxForceAcceleration * mass * 0.6f, 0);
  EXPECT_TRUE(world.applyForce(ball, largest));
  // Together the two would pass the acceleration limit.
  EXPECT_FALSE(world.applyForce(ball, largest));
}

// The largest accepted inputs on the scenes: a fast tiny circle into
// a pile of twenty, a box spinning on the floor, a body spinning inside a
// static circle, a body thrown down onto the floor. Nothing turns non-finite
// or passes the limits, and nothing needed the guard's repair.
TEST(InputLimits, LargestAcceptedInputs_KeepEveryStateFiniteAndBounded) {
  World world = sandbox();
  for (int i = 0; i < 20; ++i) {
    addCircle(world, {.center = Vec2(Real(10 + (i % 5) * 0.5), Real(0.25 + (i / 5) * 0.5)),
                      .radius = 0.24f});
  }
  addCircle(world, {.center = Vec2(2, 0.3f), .radius = 0.02f,
                    .velocity = Vec2(kLimits.maxSpeed, 0)});
  addBox(world, {.center = Vec2(18, 0.5f), .angularVelocity = kLimits.maxAngularSpeed});
  addCircle(world, {.center = Vec2(22, 5), .radius = 2, .isStatic = true});
  addCircle(world, {.center = Vec2(22, 5), .radius = 0.3f,
                    .angularVelocity = -kLimits.maxAngularSpeed});
  addCircle(world, {.center = Vec2(7, 0.6f), .radius = 0.5f,
                    .velocity = Vec2(0, -kLimits.maxSpeed)});
  ASSERT_TRUE(world.setGravity(Vec2(0, -kLimits.maxGravity)));
  for (int i = 0; i < stepsFor(3); ++i) {
    world.step(kDt);
    expectSaneStates(world);
  }
  EXPECT_EQ(world.guardReport().repairedBodies, 0u);
}

TEST(StepGuard, BodyFarOutsideTheBounds_IsRemovedAndReportedOnce) {
  World world = sandbox();
  const BodyId rocket = addCircle(world, {.center = Vec2(5, 40), .radius = 0.2f,
                                          .ignoreGravity = true,
                                          .velocity = Vec2(0, kLimits.maxSpeed)});
  const int bodies = world.bodyCount();
  // It must cover the margin beyond the upper bound, 1000 m, at 500 m/s.
  const double expectedSeconds = (kLimits.escapeMargin + 45 - 40) / kLimits.maxSpeed;
  int reports = 0;
  int stepOfRemoval = -1;
  for (int i = 1; i <= stepsFor(expectedSeconds + 0.5); ++i) {
    world.step(kDt);
    for (BodyId id : world.escapedBodies()) {
      EXPECT_EQ(id, rocket);
      ++reports;
      stepOfRemoval = i;
    }
  }
  EXPECT_EQ(reports, 1);
  EXPECT_NEAR(stepOfRemoval * kDt, expectedSeconds, 2 * kDt);
  EXPECT_FALSE(world.isValid(rocket));
  EXPECT_EQ(world.bodyCount(), bodies - 1);
  for (BodyId id : world.movedBodies()) EXPECT_NE(id, rocket);
}

TEST(StepGuard, FreeFallUnderMaximumGravity_IsSlowedToTheSpeedLimit) {
  World world;
  ASSERT_TRUE(world.setGravity(Vec2(0, -kLimits.maxGravity)));
  const BodyId ball = addCircle(world, {.center = Vec2(5, 40), .radius = 0.5f});
  simulate(world, 1.0);  // unlimited, it would reach 1000 m/s
  EXPECT_NEAR(stateOf(world, ball).linearVelocity.norm(), kLimits.maxSpeed, 1e-3);
  EXPECT_GT(world.guardReport().clampedBodies, 0u);
}

}  // namespace
}  // namespace impulse::test
