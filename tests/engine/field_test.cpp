// Force fields through the engine's field stage: closed-form motion under a
// constant field, removal, ordering, waking, the guard on bad output, and
// which loads are taken per sub-step.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

/// Pulls every body to the origin like a spring of angular frequency omega,
/// as an impulse; reports its gradient omega^2 or, when told to hide it, 0.
class SpringField : public ForceField {
 public:
  SpringField(Real omega, bool reportsGradient) : omega_(omega), reportsGradient_(reportsGradient) {}
  void apply(const FieldStep& step, std::span<FieldLoad> loads) const override {
    for (std::size_t i = 0; i < step.bodies.size(); ++i) {
      const FieldBody& body = step.bodies[i];
      loads[i].impulse -= step.dt * body.mass * omega_ * omega_ * body.transform.p;
      if (reportsGradient_) loads[i].gradient += omega_ * omega_;
    }
  }

 private:
  Real omega_;
  bool reportsGradient_;
};

/// A force along x that grows at `change` N/s over the step, counting the
/// times it is asked.
class RisingField : public ForceField {
 public:
  RisingField(Real force, Real change) : force_(force), change_(change) {}
  void apply(const FieldStep&, std::span<FieldLoad> loads) const override {
    ++calls;
    for (FieldLoad& load : loads) {
      load.force.x() += force_;
      load.forceChange.x() += change_;
    }
  }
  mutable int calls = 0;

 private:
  Real force_;
  Real change_;
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

// A uniform field (gradient 0) stays on the step's one call: a field of
// nothing leaves every step bit-identical to the world without it.
TEST(Field, FieldOfNothing_LeavesTheStepsBitIdentical) {
  auto pile = [](World& world) {
    addGround(world);
    for (int i = 0; i < 8; ++i) addBox(world, {.center = Vec2(Real(0.1 * (i % 3)), Real(0.5 + 1.05 * i))});
    addCircle(world, {.center = Vec2(3, 2), .velocity = Vec2(-2, 0)});
  };
  World plain;
  pile(plain);
  World withField;
  pile(withField);
  withField.addField(std::make_shared<UniformField>(Vec2::Zero()));
  for (int step = 0; step < 300; ++step) {
    plain.step(kDt);
    withField.step(kDt);
    ASSERT_EQ(plain.stateHash(), withField.stateHash()) << "step " << step;
  }
}

// A circular orbit in a spring field of 100 steps per period: reported, the
// gradient has the pull taken per sub-step and the radius holds within
// 1 % (symplectic Euler at h: 0.4 %); hidden, one kick per step swings it
// by 1.6 %.
TEST(Field, SteepFieldReportingItsGradient_IsTakenPerSubStep) {
  const Real omega = Real(2 * kPi / (100 * kDt));
  auto swing = [&](bool reportsGradient) {
    World world(weightless());
    BodyId ball = addCircle(world, {.center = Vec2(1, 0), .velocity = Vec2(0, omega)});
    world.addField(std::make_shared<SpringField>(omega, reportsGradient));
    double worst = 0;
    for (int step = 0; step < 500; ++step) {
      world.step(kDt);
      worst = std::max(worst, std::abs(double(stateOf(world, ball).position.norm()) - 1));
    }
    return worst;
  };
  const double perSubStep = swing(true), perStep = swing(false);
  std::printf("spring-field orbit of 100 steps per period: radius swing %.4f per sub-step, %.4f per step\n",
              perSubStep, perStep);
  EXPECT_LT(perSubStep, 0.01);
  EXPECT_GT(perStep, 0.012);
}

// Sub-step k of length h feels F + C k h: after one step of n sub-steps the
// velocity is (F dt + C h^2 n (n - 1) / 2) / m, from one call of the field.
TEST(Field, ChangingForce_IsCarriedForwardToEachSubStep_FromOneCallPerStep) {
  World world(weightless());
  BodyId ball = addCircle(world, {.center = Vec2(0, 10), .radius = Real(0.5)});
  const double mass = kPi * 0.25 * materialProperties(Material::Solid).density;
  auto field = std::make_shared<RisingField>(Real(3), Real(600));
  world.addField(field);
  world.step(kDt);
  const int n = WorldSettings{}.subSteps;
  const double h = double(kDt) / n;
  const double expected = (3 * double(kDt) + 600 * h * h * n * (n - 1) / 2) / mass;
  EXPECT_EQ(field->calls, 1);
  EXPECT_NEAR(stateOf(world, ball).linearVelocity.x(), expected, 1e-5 * expected);
}

}  // namespace
}  // namespace impulse::test
