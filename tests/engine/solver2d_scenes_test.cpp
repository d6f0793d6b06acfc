// The two scenes of Solver2D's collection (erincatto/solver2d,
// samples/collection/sample_contact.cpp) that act on the world mid-run, so no
// bench description holds them: rush pulls every body towards the centre
// each step, warm-start energy removes a body. The rest of the collection is
// described once in bench/scenes/solver2d.cpp and tested in
// tests/bench/solver2d_scenes_test.cpp. Solver2D's gravity (10 m/s^2) and
// default shape values (density 1, friction 0.6) unless the scene sets its own.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "world_test_support.h"

namespace impulse::test {
namespace {

WorldSettings solver2DSettings(Vec2 gravity) {
  WorldSettings settings = sleepless();
  settings.gravity = gravity;
  return settings;
}

/// Solver2D's coefficients: one friction, no restitution, no rolling resistance.
MaterialOverride solver2DMaterial(Real density, Real friction) {
  return {.density = density,
          .restitution = 0,
          .staticFriction = friction,
          .dynamicFriction = friction,
          .rollingResistance = 0};
}

BodyId addSolver2DCircle(World& world, Vec2 center, Real radius, Real density, Real friction,
                         bool isStatic = false) {
  BodyDef def;
  def.shape = Shape::makeCircle(radius);
  def.position = center;
  def.properties.isStatic = isStatic;
  def.materialOverride = solver2DMaterial(density, friction);
  CreateResult result = world.createBody(def);
  EXPECT_TRUE(result.ok()) << result.error;
  return result.id;
}

Real speedOf(const World& world, BodyId id) { return stateOf(world, id).linearVelocity.norm(); }

// ---- warm-start energy -----------------------------------------------------

// Two 1 m circles stacked on the ground under a third of 100 times their
// density; the heavy one is removed after 2 s (Solver2D: step 120). The
// contact impulses warm-started from its weight must not launch the two
// below: the fastest of them stays under 0.5 m/s over the next 2 s.
TEST(Solver2D, WarmStartEnergy_RemovingTheHeavyCircleLaunchesNothing) {
  World world(solver2DSettings(Vec2(0, -10)));
  ASSERT_TRUE(
      world
          .createSegment(Vec2(-10, 0), Vec2(10, 0),
                         {.properties = {.isStatic = true}, .materialOverride = solver2DMaterial(1, Real(0.6))})
          .ok());
  const std::vector<BodyId> light = {
      addSolver2DCircle(world, Vec2(0, Real(0.5)), Real(0.5), 1, Real(0.6)),
      addSolver2DCircle(world, Vec2(0, Real(1.5)), Real(0.5), 1, Real(0.6))};
  const BodyId heavy = addSolver2DCircle(world, Vec2(0, Real(2.5)), Real(0.5), 100, Real(0.6));
  for (int step = 0; step < 120; ++step) world.step(kDt);
  ASSERT_TRUE(world.destroyBody(heavy));

  Real fastest = 0;
  simulateUntil(world, 2, [&] {
    for (BodyId id : light) fastest = std::max(fastest, speedOf(world, id));
    return false;
  });
  std::printf("measured: warm-start energy fastest %.4g m/s after the removal\n", double(fastest));
  EXPECT_LT(fastest, Real(0.5));
}

// ---- rush ------------------------------------------------------------------

constexpr int kRushCount = 400;
constexpr Real kRushForce = 1000;

// 400 circles (0.5 m, density 100, friction 0.2) on a spiral 5-25 m out,
// without gravity, each pulled towards a static circle at the origin by a
// constant 1000 N applied every step. With a force of constant size the
// pull's potential energy is 1000 N times the distance, so kinetic plus that
// potential is what the rush has: contacts and friction may only lose it.
// The largest gain over 7 s must stay within 1 % of the potential they
// start with (the integrator's own error), and the pile must settle: the
// last circles arrive and roll into place until about 6.5 s, faster than
// 1 m/s now and then (up to 5 m/s), so the fastest circle is held under
// 0.1 m/s at 7 s.
TEST(Solver2D, Rush_GainsNoEnergy) {
  World world(solver2DSettings(Vec2(0, 0)));
  world.setSettings([&] {
    WorldSettings settings = world.settings();
    settings.bounds = {Vec2(-40, -40), Vec2(40, 40)};
    return settings;
  }());
  addSolver2DCircle(world, Vec2::Zero(), Real(0.5), 100, Real(0.2), true);
  std::vector<BodyId> circles;
  double distance = 5, angle = 0;
  for (int i = 0; i < kRushCount; ++i) {
    const Vec2 at(Real(distance * std::cos(angle)), Real(distance * std::sin(angle)));
    circles.push_back(addSolver2DCircle(world, at, Real(0.5), 100, Real(0.2)));
    angle += 1 / distance;
    distance += 0.05;
  }
  ASSERT_EQ(static_cast<int>(circles.size()), kRushCount);

  auto energy = [&] {
    double total = 0;
    for (BodyId id : circles) {
      const BodyState s = stateOf(world, id);
      const double mass = world.bodyDescription(id)->mass.mass;
      const double inertia = world.bodyDescription(id)->mass.inertia;
      total += 0.5 * mass * s.linearVelocity.squaredNorm() +
               0.5 * inertia * s.angularVelocity * s.angularVelocity +
               kRushForce * s.position.norm();
    }
    return total;
  };
  const double start = energy();
  double worstGain = 0;
  for (int step = 0; step < stepsFor(7); ++step) {
    for (BodyId id : circles) {
      const Vec2 p = stateOf(world, id).position;
      const Real length = p.norm();
      if (length < Real(0.1)) continue;
      ASSERT_TRUE(world.applyForce(id, -kRushForce / length * p).ok());
    }
    world.step(kDt);
    worstGain = std::max(worstGain, energy() - start);
  }
  Real fastest = 0;
  for (BodyId id : circles) fastest = std::max(fastest, speedOf(world, id));
  std::printf("measured: rush worst gain %.4g J of %.4g J (%.3g %%), fastest at 7 s %.3g m/s\n",
              worstGain, start, 100 * worstGain / start, double(fastest));
  EXPECT_LT(worstGain, 0.01 * start);
  EXPECT_LT(fastest, Real(0.1));
}

}  // namespace
}  // namespace impulse::test
