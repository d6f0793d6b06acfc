// Liquid regions: the exact submerged part against circle-segment and
// clipped-box closed forms, Archimedes' floating depths (WOOD 70 %, ICE
// 10 %), METAL's terminal speed, a box at rest without jitter, a plank
// righting itself, a current's exponential pull, and refusals.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "impulse/fluid_region.h"
#include "impulse/submerged.h"
#include "world_test_support.h"

namespace impulse::test {
namespace {

// Water below y = surface, wide and deep enough to hold every test body.
std::vector<Vec2> pool(Real surface = 0) {
  return {Vec2(-20, -20), Vec2(20, -20), Vec2(20, surface), Vec2(-20, surface)};
}

FluidDef water(Real linearDrag = 2, Real angularDrag = 2) {
  return {.polygon = pool(), .density = 1000, .linearDrag = linearDrag, .angularDrag = angularDrag};
}

TEST(Submerged, CircleCutByTheSurface_IsTheCircularSegment) {
  const double radius = 0.8;
  for (double depth : {0.1, 0.5, 0.8, 1.3, 1.6}) {
    Transform at;
    at.p = Vec2(Real(0.3), Real(-depth + radius));  // bottom `depth` below the surface
    const SubmergedPart part = submergedPart(Shape::makeCircle(Real(radius)), at, pool());
    // Segment of height h: area r^2 acos((r-h)/r) - (r-h) sqrt(2rh - h^2),
    // centroid 2 c^3 / (3 A) below the centre, c the half chord.
    const double d = radius - depth;  // centre height above the surface
    const double halfChord = std::sqrt(radius * radius - d * d);
    const double area = radius * radius * std::acos(d / radius) - d * halfChord;
    const double centroidBelow = 2 * halfChord * halfChord * halfChord / (3 * area);
    EXPECT_NEAR(part.area, area, 1e-6 * area) << "depth " << depth;
    EXPECT_NEAR(part.centroid.y(), at.p.y() - centroidBelow, 1e-5) << "depth " << depth;
    EXPECT_NEAR(part.centroid.x(), 0.3, 1e-5);
  }
}

TEST(Submerged, TiltedBoxHalfIn_IsTheClippedPolygon) {
  // A unit square turned 45 degrees, centre on the surface: the lower half
  // is a right triangle of area 1/2 whose centroid is sqrt(2)/2 / 3 deep.
  Transform at;
  at.q = Rot::fromAngle(Real(kPi / 4));
  const SubmergedPart part = submergedPart(Shape::makePolygon(makeBox(Real(0.5), Real(0.5))), at, pool());
  EXPECT_NEAR(part.area, 0.5, 1e-6);
  EXPECT_NEAR(part.centroid.y(), -std::sqrt(2.0) / 2 / 3, 1e-6);
  EXPECT_NEAR(part.centroid.x(), 0, 1e-6);
}

TEST(Submerged, CircleInsideACorner_CountsOnlyTheOverlap) {
  // A circle centred on a corner of a square region overlaps a quarter disc.
  const std::vector<Vec2> square = {Vec2(0, 0), Vec2(5, 0), Vec2(5, 5), Vec2(0, 5)};
  const SubmergedPart part = submergedPart(Shape::makeCircle(1), Transform{}, square);
  EXPECT_NEAR(part.area, kPi / 4, 1e-6);
  EXPECT_NEAR(part.centroid.x(), 4 / (3 * kPi), 1e-6);
  EXPECT_NEAR(part.centroid.y(), 4 / (3 * kPi), 1e-6);
}

/// Share of a unit box's area under water once it has floated for
/// `seconds` (whatever way up it settled: a square of WOOD floats corner
/// down). Dropped from 10 cm above its rest depth; sleep off, since a body
/// put to sleep below 0.05 m/s may rest up to 0.05 / omega (1.3 cm for WOOD)
/// off its depth.
double floatingFraction(Material material, double seconds) {
  WorldSettings settings;
  settings.enableSleep = false;
  World world(settings);
  const Real share = materialProperties(material).density / 1000;
  BodyId box = addBox(world, {.center = Vec2(0, Real(0.6) - share), .material = material});
  world.addField(makeFluidRegion(water(5, 5)).field);
  simulate(world, seconds);
  const BodyState state = stateOf(world, box);
  Transform at;
  at.p = state.position;
  at.q = Rot::fromAngle(state.angle);
  return submergedPart(Shape::makePolygon(makeBox(Real(0.5), Real(0.5))), at, pool()).area;
}

TEST(Fluid, WoodAndIce_FloatAsDeepAsArchimedesSays) {
  const double wood = floatingFraction(Material::Wood, 30);
  const double ice = floatingFraction(Material::Ice, 30);
  std::printf("floating: WOOD %.4f submerged (700/1000 = 0.7), ICE %.4f (100/1000 = 0.1)\n", wood, ice);
  // Measured: 0.70000 and 0.10000.
  EXPECT_NEAR(wood, 0.7, 1e-3);
  EXPECT_NEAR(ice, 0.1, 1e-3);
}

TEST(Fluid, Metal_SinksAtItsTerminalSpeed) {
  World world;
  BodyId box = addBox(world, {.center = Vec2(0, -1), .material = Material::Metal});
  const Real drag = 2;
  world.addField(makeFluidRegion(water(drag)).field);
  simulate(world, 4);
  // Weight less buoyancy against drag m k v: v = g (1 - rho_f / rho_b) / k.
  const double terminal = kG * (1 - 1000.0 / 2000.0) / drag;
  const double measured = -stateOf(world, box).linearVelocity.y();
  std::printf("METAL sinking at %.4f m/s (closed form %.4f)\n", measured, terminal);
  EXPECT_NEAR(measured, terminal, 0.01 * terminal);
}

TEST(Fluid, FloatingBox_SettlesWithoutJitter) {
  World world;
  BodyId box = addBox(world, {.center = Vec2(0, 1), .material = Material::Wood});
  world.addField(makeFluidRegion(water()).field);
  simulate(world, 10);
  double low = 1e9, high = -1e9, fastest = 0;
  for (int step = 0; step < stepsFor(2); ++step) {
    world.step(kDt);
    const BodyState state = stateOf(world, box);
    low = std::min<double>(low, state.position.y());
    high = std::max<double>(high, state.position.y());
    fastest = std::max<double>(fastest, state.linearVelocity.norm() + std::abs(state.angularVelocity));
  }
  std::printf("settled box over 2 s: height range %.2e m, fastest %.2e\n", high - low, fastest);
  EXPECT_LT(high - low, 1e-4);
  EXPECT_LT(fastest, 1e-3);
}

TEST(Fluid, TiltedPlank_RightsItself) {
  World world;
  // A 2 x 0.5 wood plank: metacentric height B^2/(12 s H) + s H/2 - H/2 > 0.
  BodyId plank = addBox(world, {.center = Vec2(0, 0), .halfWidth = 1, .halfHeight = Real(0.25),
                                .angle = Real(0.4), .material = Material::Wood});
  world.addField(makeFluidRegion(water()).field);
  simulate(world, 15);
  EXPECT_NEAR(stateOf(world, plank).angle, 0, 0.01);
}

TEST(Fluid, Current_CarriesASubmergedBodyExponentially) {
  World world;
  // SOLID (500) in a liquid of 500: no net weight, only the current's drag.
  FluidDef def = water(1);
  def.density = 500;
  def.current = Vec2(2, 0);
  BodyId ball = addCircle(world, {.center = Vec2(0, -5), .radius = Real(0.5)});
  world.addField(makeFluidRegion(def).field);
  simulate(world, 1);
  // v = c (1 - exp(-k t)).
  const double expected = 2 * (1 - std::exp(-1.0));
  EXPECT_NEAR(stateOf(world, ball).linearVelocity.x(), expected, 0.01 * expected);
  EXPECT_NEAR(stateOf(world, ball).linearVelocity.y(), 0, 1e-3);
}

TEST(Fluid, BadNumbers_AreRefusedNamingTheField) {
  struct Case {
    FluidDef def;
    const char* names;
  };
  FluidDef concave = water();
  concave.polygon = {Vec2(0, 0), Vec2(4, 0), Vec2(1, 1), Vec2(0, 4)};
  FluidDef tooFew = water();
  tooFew.polygon.resize(2);
  FluidDef nanDensity = water();
  nanDensity.density = std::nanf("");
  FluidDef negativeDrag = water(-1);
  FluidDef fastCurrent = water();
  fastCurrent.current = Vec2(0, 101);
  for (const Case& c : {Case{concave, "fluid polygon"}, Case{tooFew, "fluid polygon"}, Case{nanDensity, "fluid density"},
                        Case{negativeDrag, "fluid linear_drag"}, Case{fastCurrent, "fluid current.y"}}) {
    FieldBuild build = makeFluidRegion(c.def);
    EXPECT_FALSE(build.ok());
    EXPECT_NE(build.error.find(c.names), std::string::npos) << build.error;
  }
}

}  // namespace
}  // namespace impulse::test
