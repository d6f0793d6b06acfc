// Force fields through the engine's field stage: closed-form motion under a
// constant field, removal, ordering, waking and the guard on bad output.

#include <gtest/gtest.h>

#include <limits>
#include <memory>

#include "world_test_support.h"

namespace impulse::test {
namespace {

/// Pulls every body with `acceleration` times its mass (a uniform field).
class UniformField : public ForceField {
 public:
  explicit UniformField(Vec2 acceleration) : acceleration_(acceleration) {}
  void apply(const FieldStep& step, std::span<FieldLoad> loads) const override {
    for (std::size_t i = 0; i < step.bodies.size(); ++i) loads[i].force += step.bodies[i].mass * acceleration_;
  }

 private:
  Vec2 acceleration_;
};

/// A broken field: NaN force and infinite torque on every body.
class BrokenField : public ForceField {
 public:
  void apply(const FieldStep&, std::span<FieldLoad> loads) const override {
    for (FieldLoad& load : loads) {
      load.force.x() = std::numeric_limits<Real>::quiet_NaN();
      load.torque = std::numeric_limits<Real>::infinity();
    }
  }
};

WorldSettings weightless() {
  WorldSettings settings;
  settings.gravity = Vec2::Zero();
  return settings;
}

TEST(Field, UniformField_MovesABodyAsConstantAcceleration) {
  World world(weightless());
  BodyId ball = addCircle(world, {.center = Vec2(0, 10)});
  world.addField(std::make_shared<UniformField>(Vec2(2, 0)));
  simulate(world, 2.0);
  // x = a t^2 / 2 = 4 m; the semi-implicit step is ahead by a t dt / 2.
  const double t = 2.0;
  EXPECT_NEAR(stateOf(world, ball).position.x(), 0.5 * 2 * t * t, 2 * t * kDt / 2 + 1e-3);
  EXPECT_NEAR(stateOf(world, ball).linearVelocity.x(), 2 * t, 1e-3);
  EXPECT_NEAR(stateOf(world, ball).position.y(), 10, 1e-6);
}

TEST(Field, FieldLikeGravity_MatchesGravity) {
  World withGravity;
  BodyId a = addBox(withGravity, {.center = Vec2(0, 10)});
  World withField(weightless());
  BodyId b = addBox(withField, {.center = Vec2(0, 10)});
  withField.addField(std::make_shared<UniformField>(kDefaultGravity));
  simulate(withGravity, 1.0);
  simulate(withField, 1.0);
  EXPECT_NEAR(stateOf(withField, b).position.y(), stateOf(withGravity, a).position.y(), 1e-4);
}

TEST(Field, FieldsAdd_AndRemovingOneLeavesTheOther) {
  World world(weightless());
  BodyId ball = addCircle(world, {.center = Vec2(0, 10)});
  FieldId right = world.addField(std::make_shared<UniformField>(Vec2(1, 0)));
  world.addField(std::make_shared<UniformField>(Vec2(0, 3)));
  EXPECT_EQ(world.fieldCount(), 2);
  simulate(world, 1.0);
  Vec2 velocity = stateOf(world, ball).linearVelocity;
  EXPECT_NEAR(velocity.x(), 1, 1e-3);
  EXPECT_NEAR(velocity.y(), 3, 1e-3);

  EXPECT_TRUE(world.removeField(right));
  EXPECT_FALSE(world.removeField(right)) << "a removed field's id is unknown";
  simulate(world, 1.0);
  velocity = stateOf(world, ball).linearVelocity;
  EXPECT_NEAR(velocity.x(), 1, 1e-3) << "no more push sideways once removed";
  EXPECT_NEAR(velocity.y(), 6, 1e-3);
}

TEST(Field, NullField_IsRefused) {
  World world;
  EXPECT_TRUE(world.addField(nullptr).isNull());
  EXPECT_EQ(world.fieldCount(), 0);
}

TEST(Field, AddingAField_WakesRestingBodies) {
  World world;
  addGround(world);
  BodyId box = addBox(world, {.center = Vec2(0, Real(0.5))});
  ASSERT_GE(simulateUntilAsleep(world, 5.0), 0);
  world.addField(std::make_shared<UniformField>(Vec2(0, 20)));
  simulate(world, 0.5);
  EXPECT_GT(stateOf(world, box).position.y(), 1.0) << "lifted by a field stronger than gravity";
}

TEST(Field, NonFiniteLoad_IsDropped) {
  World world;
  BodyId ball = addCircle(world, {.center = Vec2(0, 10)});
  world.addField(std::make_shared<BrokenField>());
  simulate(world, 1.0);
  BodyState state = stateOf(world, ball);
  EXPECT_TRUE(isFinite(state.position) && isFinite(state.linearVelocity) && isFinite(state.angularVelocity));
  EXPECT_NEAR(state.linearVelocity.y(), -kG, 1e-3) << "gravity alone acts";
}

}  // namespace
}  // namespace impulse::test
