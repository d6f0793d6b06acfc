// Newton's gravitation field: Kepler's circular orbit (radius and period),
// a two-body eccentric orbit's energy and angular momentum over 20 orbits,
// Barnes-Hut against the exact sum with its stated bound, and refusals.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "impulse/gravitation.h"
#include "world_test_support.h"

namespace impulse::test {
namespace {

World weightlessWorld() {
  WorldSettings settings;
  settings.gravity = Vec2::Zero();
  return World(settings);
}

double massOf(Real radius, Material material) {
  return kPi * radius * radius * materialProperties(material).density;
}

TEST(Gravitation, PullOfOneMass_IsNewtons) {
  const Vec2d pull = pullPerUnitG({Vec2d(0, 0), 1, 0.1}, {Vec2d(3, 4), 50, 0.1}).acceleration;
  EXPECT_NEAR(pull.norm(), 50.0 / 25.0, 1e-12);
  EXPECT_NEAR(pull.x() / pull.norm(), 0.6, 1e-12) << "towards the source";
}

// The change reported is the pull's time derivative as both masses move on:
// against central differences, apart and within their reaches.
TEST(Gravitation, PullChange_IsThePullsTimeDerivative) {
  auto movedBy = [](PointMass mass, double t) {
    mass.position += t * mass.velocity;
    return mass;
  };
  for (const Vec2d& start : {Vec2d(3, 4), Vec2d(0.3, 0.1)}) {
    const PointMass target{Vec2d(0, 0), 1, 0.2, Vec2d(1, -2)};
    const PointMass source{start, 50, 0.2, Vec2d(-3, 0.5)};
    const double t = 1e-6;
    const Vec2d numeric = (pullPerUnitG(movedBy(target, t), movedBy(source, t)).acceleration -
                           pullPerUnitG(movedBy(target, -t), movedBy(source, -t)).acceleration) /
                          (2 * t);
    const Vec2d change = pullPerUnitG(target, source).change;
    EXPECT_NEAR((change - numeric).norm(), 0, 1e-5 * numeric.norm()) << "source at " << start.transpose();
  }
}

/// A light planet on a circular orbit of radius 10 m around a static sun,
/// with G chosen for `period`, followed for five orbits.
struct OrbitFigures {
  double lowest = 0;   ///< radius, m
  double highest = 0;
  double period = 0;   ///< s, mean between crossings of +x
};

OrbitFigures circularOrbit(double period) {
  World world = weightlessWorld();
  const double sunRadius = 1, orbitRadius = 10;
  addCircle(world, {.center = Vec2(0, 0), .radius = Real(sunRadius), .isStatic = true});
  // G M = 4 pi^2 R^3 / T^2 for the period we want.
  const double constant = 4 * kPi * kPi * std::pow(orbitRadius, 3) / (period * period) /
                          massOf(Real(sunRadius), Material::Solid);
  const double speed = std::sqrt(constant * massOf(Real(sunRadius), Material::Solid) / orbitRadius);
  BodyId planet = addCircle(world, {.center = Vec2(Real(orbitRadius), 0), .radius = Real(0.2),
                                    .velocity = Vec2(0, Real(speed))});
  EXPECT_TRUE(world.addField(makeGravitation({constant}).field).value != 0);

  OrbitFigures out{orbitRadius, orbitRadius, 0};
  std::vector<double> crossings;  // times the planet crosses +x going up
  Vec2 previous = stateOf(world, planet).position;
  for (int step = 1; step <= stepsFor(5 * period); ++step) {
    world.step(kDt);
    const Vec2 position = stateOf(world, planet).position;
    out.lowest = std::min<double>(out.lowest, position.norm());
    out.highest = std::max<double>(out.highest, position.norm());
    if (previous.y() < 0 && position.y() >= 0 && position.x() > 0) {
      const double fraction = -previous.y() / (position.y() - previous.y());
      crossings.push_back((step - 1 + fraction) * kDt);
    }
    previous = position;
  }
  EXPECT_GE(crossings.size(), 4u);
  if (crossings.size() >= 2) out.period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  std::printf("circular orbit of %.0f steps per period: radius %.5f..%.5f (R = %.1f), period %.5f s (Kepler %.4f)\n",
              period / kDt, out.lowest, out.highest, orbitRadius, out.period, period);
  return out;
}

TEST(Gravitation, CircularOrbit_KeepsItsRadiusAndKeplersPeriod) {
  const OrbitFigures orbit = circularOrbit(10);
  RecordProperty("radius_low", std::to_string(orbit.lowest));
  RecordProperty("radius_high", std::to_string(orbit.highest));
  RecordProperty("period", std::to_string(orbit.period));
  EXPECT_NEAR(orbit.lowest, 10, 0.01 * 10);
  EXPECT_NEAR(orbit.highest, 10, 0.01 * 10);
  EXPECT_NEAR(orbit.period, 10, 0.01 * 10);
}

// 100 steps per period: one kick per step swung the radius +-3 %; the pull
// carried forward to each sub-step keeps it within 1 %.
TEST(Gravitation, FastOrbitOf100StepsPerPeriod_KeepsItsRadiusWithin1Percent) {
  const double period = 100 * double(kDt);
  const OrbitFigures orbit = circularOrbit(period);
  RecordProperty("radius_low", std::to_string(orbit.lowest));
  RecordProperty("radius_high", std::to_string(orbit.highest));
  EXPECT_NEAR(orbit.lowest, 10, 0.01 * 10);
  EXPECT_NEAR(orbit.highest, 10, 0.01 * 10);
  EXPECT_NEAR(orbit.period, period, 0.01 * period);
}

struct TwoBodyTotals {
  double energy = 0;
  double angularMomentum = 0;
};

TwoBodyTotals totals(const World& world, BodyId a, BodyId b, double ma, double mb, double constant) {
  const BodyState sa = stateOf(world, a), sb = stateOf(world, b);
  const double kinetic = 0.5 * ma * sa.linearVelocity.squaredNorm() + 0.5 * mb * sb.linearVelocity.squaredNorm();
  const double potential = -constant * ma * mb / double((sa.position - sb.position).norm());
  const double angular = ma * cross(sa.position, sa.linearVelocity) + mb * cross(sb.position, sb.linearVelocity);
  return {kinetic + potential, angular};
}

TEST(Gravitation, EccentricTwoBodyOrbit_KeepsEnergyAndAngularMomentum) {
  World world = weightlessWorld();
  const Real radius = Real(0.3);
  const double ma = massOf(radius, Material::Metal), mb = massOf(radius, Material::Wood);
  // Start at apoapsis of a relative orbit with semi-major axis a, e = 0.5,
  // G chosen for a period of 20 s.
  const double total = ma + mb, a = 6, e = 0.5, apoapsis = a * (1 + e);
  const double constant = 4 * kPi * kPi * a * a * a / (20.0 * 20.0 * total);
  const double relativeSpeed = std::sqrt(constant * total * (1 - e) / apoapsis);
  const Vec2 offsetA(Real(-apoapsis * mb / total), 0), offsetB(Real(apoapsis * ma / total), 0);
  BodyId bodyA = addCircle(world, {.center = Vec2(0, 10) + offsetA, .radius = radius, .material = Material::Metal,
                                   .velocity = Vec2(0, Real(-relativeSpeed * mb / total))});
  BodyId bodyB = addCircle(world, {.center = Vec2(0, 10) + offsetB, .radius = radius, .material = Material::Wood,
                                   .velocity = Vec2(0, Real(relativeSpeed * ma / total))});
  world.addField(makeGravitation({constant}).field);

  const double period = 2 * kPi * std::sqrt(a * a * a / (constant * total));
  const TwoBodyTotals start = totals(world, bodyA, bodyB, ma, mb, constant);
  double energyError = 0, angularError = 0;
  for (int step = 0; step < stepsFor(20 * period); ++step) {
    world.step(kDt);
    const TwoBodyTotals now = totals(world, bodyA, bodyB, ma, mb, constant);
    energyError = std::max(energyError, std::abs(now.energy - start.energy) / std::abs(start.energy));
    angularError = std::max(angularError, std::abs(now.angularMomentum - start.angularMomentum) /
                                              std::abs(start.angularMomentum));
  }
  const TwoBodyTotals end = totals(world, bodyA, bodyB, ma, mb, constant);
  std::printf("eccentric orbit (e = 0.5, T = %.2f s, 20 orbits): max energy error %.3e, final %.3e; "
              "max angular momentum error %.3e\n",
              period, energyError, std::abs(end.energy - start.energy) / std::abs(start.energy), angularError);
  // Measured: 0.73 % at most (near periapsis), 2e-5 after 20 orbits.
  EXPECT_LT(energyError, 0.01) << "energy oscillates within 1 % near periapsis";
  EXPECT_LT(std::abs(end.energy - start.energy) / std::abs(start.energy), 1e-3) << "and does not drift";
  EXPECT_LT(angularError, 1e-4) << "symplectic Euler keeps it exactly but for float rounding";
}

TEST(Gravitation, StaticBodiesPull_ButDoNotMove) {
  World world = weightlessWorld();
  BodyId sun = addCircle(world, {.center = Vec2(0, 0), .radius = 1, .isStatic = true});
  BodyId stone = addCircle(world, {.center = Vec2(5, 0), .radius = Real(0.2)});
  world.addField(makeGravitation({1}).field);
  world.step(kDt);
  // One step's pull: v = G M / r^2 * dt, towards the sun (taken per
  // sub-step this close, as the stone falls a few mm nearer: within 1 %).
  const double expected = massOf(1, Material::Solid) / 25.0 * kDt;
  EXPECT_NEAR(stateOf(world, stone).linearVelocity.x(), -expected, 1e-2 * expected);
  EXPECT_EQ(stateOf(world, sun).position, Vec2(0, 0));
}

TEST(Gravitation, BarnesHut_StaysWithinItsBoundOfTheExactSum) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-50, 50), mass(1, 10);
  std::vector<PointMass> masses(3000);
  for (PointMass& m : masses) m = {Vec2d(coordinate(random), coordinate(random)), mass(random), 0.05};
  std::vector<Pull> exact(masses.size());
  exactPull(masses, 1, exact);
  PullTree tree(Gravitation::kTheta);
  tree.build(masses);
  std::vector<double> relative;
  int outsideBound = 0;
  for (std::size_t i = 0; i < masses.size(); ++i) {
    double bound = 0;
    const Vec2d approximate = tree.pull(i, &bound).acceleration;
    const Vec2d& exactAcceleration = exact[i].acceleration;
    const double error = (approximate - exactAcceleration).norm();
    if (error > bound * (1 + 1e-9) + 1e-12 * exactAcceleration.norm()) ++outsideBound;
    relative.push_back(error / exactAcceleration.norm());
  }
  std::ranges::sort(relative);
  std::printf("Barnes-Hut theta %.2f, %zu masses: relative error median %.2e, 99th percentile %.2e, max %.2e\n",
              Gravitation::kTheta, masses.size(), relative[relative.size() / 2],
              relative[relative.size() * 99 / 100], relative.back());
  EXPECT_EQ(outsideBound, 0) << "every body's error within 3 G sum(m |x - com|^2) / (d - b)^4 over the far cells";
  EXPECT_LT(relative[relative.size() / 2], 1e-2);
}

TEST(Gravitation, ConstantOutOfRange_IsRefusedNamingIt) {
  for (double constant : {0.0, -1.0, 1001.0, std::nan("")}) {
    FieldBuild build = makeGravitation({constant});
    EXPECT_FALSE(build.ok());
    EXPECT_EQ(build.field, nullptr);
    EXPECT_NE(build.error.find("gravitation constant"), std::string::npos) << build.error;
    EXPECT_NE(build.error.find("(0, 1000]"), std::string::npos) << build.error;
  }
}

}  // namespace
}  // namespace impulse::test
