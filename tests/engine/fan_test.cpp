// Fans: the air's speed and direction against their closed form, drag stronger near the
// fan, none outside the cone or range, shadows, refusals.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "impulse/fan.h"
#include "world_test_support.h"

namespace impulse::test {
namespace {

World weightlessWorld() {
  WorldSettings settings;
  settings.gravity = Vec2::Zero();
  return World(settings);
}

const FanDef kFan{.position = Vec2(0, 0), .direction = Vec2(1, 0), .speed = 40, .range = 20, .spread = Real(0.5)};

TEST(Fan, AirSpeed_FallsLinearlyToNothingAtRange) {
  Fan fan(kFan);
  EXPECT_NEAR(fan.airVelocity(Vec2(5, 0)).x(), 40 * (1 - 5.0 / 20), 1e-4);
  EXPECT_EQ(fan.airVelocity(Vec2(21, 0)), Vec2::Zero()) << "past the range";
  EXPECT_EQ(fan.airVelocity(Vec2(5 * std::cos(0.6f), 5 * std::sin(0.6f))), Vec2::Zero()) << "outside the cone";
  EXPECT_EQ(fan.airVelocity(Vec2(-5, 0)), Vec2::Zero()) << "behind the fan";
}

TEST(Fan, OffTheAxis_AirBlowsAlongItSlowerAndDrawsTowardsIt) {
  Fan fan(kFan);
  for (double angle : {0.4, -0.2}) {
    const Vec2 point(Real(8 * std::cos(angle)), Real(8 * std::sin(angle)));
    // Along the axis: S (1 - x / R) (1 - f^2), f = angle / spread; across:
    // the entrainment's share of that, towards the axis.
    const double f = angle / 0.5;
    const double jet = 40 * (1 - point.x() / 20) * (1 - f * f);
    const Vec2 air = fan.airVelocity(point);
    EXPECT_NEAR(air.x(), jet, 1e-4) << angle;
    EXPECT_NEAR(air.y(), -Fan::kEntrainment * f * jet, 1e-4) << angle;
    EXPECT_LT(air.y() * point.y(), 0) << "towards the axis";
  }
  EXPECT_NEAR(fan.airVelocity(Vec2(Real(8 * std::cos(0.5)), Real(8 * std::sin(0.5)) - Real(1e-4))).norm(), 0, 0.01)
      << "nothing at the cone's edge";
}

/// Speed a ball at rest at `center` has after one step in the fan.
double speedAfterOneStep(const Vec2& center) {
  World world = weightlessWorld();
  BodyId ball = addCircle(world, {.center = center, .radius = Real(0.25)});
  world.addField(makeFan(kFan).field);
  world.step(kDt);
  return stateOf(world, ball).linearVelocity.norm();
}

TEST(Fan, Drag_IsStrongerNearTheFanAndMatchesTheClosedForm) {
  const double mass = kPi * 0.25 * 0.25 * materialProperties(Material::Solid).density;
  for (double distance : {3.0, 10.0, 16.0}) {
    const double air = 40 * (1 - distance / 20);
    // F = 1/2 rho Cd w u^2 on a body at rest; one step adds F dt / m.
    const double expected = 0.5 * Fan::kAirDensity * Fan::kDragCoefficient * 0.5 * air * air * kDt / mass;
    const double measured = speedAfterOneStep(Vec2(Real(distance), 0));
    std::printf("fan at %.0f m: dv %.6f m/s (closed form %.6f)\n", distance, measured, expected);
    EXPECT_NEAR(measured, expected, 1e-3 * expected);
  }
  EXPECT_GT(speedAfterOneStep(Vec2(3, 0)), speedAfterOneStep(Vec2(10, 0)));
}

TEST(Fan, NoAir_OutsideTheConeOrRange) {
  EXPECT_EQ(speedAfterOneStep(Vec2(21, 0)), 0);
  EXPECT_EQ(speedAfterOneStep(Vec2(5, 4)), 0) << "atan(4/5) = 0.67 rad > spread 0.5";
  EXPECT_EQ(speedAfterOneStep(Vec2(-5, 0)), 0);
}

TEST(Fan, BodyBehindAnother_IsInItsShadow) {
  World world = weightlessWorld();
  BodyId front = addCircle(world, {.center = Vec2(4, 0), .radius = Real(0.5)});
  BodyId behind = addCircle(world, {.center = Vec2(8, 0), .radius = Real(0.25)});
  BodyId aside = addCircle(world, {.center = Vec2(8, 2), .radius = Real(0.25)});
  world.addField(makeFan(kFan).field);
  world.step(kDt);
  EXPECT_GT(stateOf(world, front).linearVelocity.x(), 0);
  EXPECT_EQ(stateOf(world, behind).linearVelocity.norm(), 0) << "hidden behind the front ball";
  EXPECT_GT(stateOf(world, aside).linearVelocity.norm(), 0) << "in clear air";
}

TEST(Fan, BadNumbers_AreRefusedNamingTheField) {
  auto refused = [](FanDef def, const char* name) {
    FieldBuild build = makeFan(def);
    EXPECT_FALSE(build.ok());
    EXPECT_NE(build.error.find(name), std::string::npos) << build.error;
  };
  FanDef def = kFan;
  def.direction = Vec2::Zero();
  refused(def, "fan direction");
  def = kFan;
  def.speed = 0;
  refused(def, "fan speed");
  def = kFan;
  def.range = std::nanf("");
  refused(def, "fan range");
  def = kFan;
  def.spread = 2;
  refused(def, "fan spread");
  def = kFan;
  def.position = Vec2(1e5, 0);
  refused(def, "fan position");
}

}  // namespace
}  // namespace impulse::test
