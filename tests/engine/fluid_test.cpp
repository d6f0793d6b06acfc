// Liquid regions: the exact submerged part against circle-segment and
// clipped-box closed forms, Archimedes' floating depths (WOOD 70 %, ICE
// 10 %), METAL's terminal speed, a box at rest without jitter, a plank
// righting itself, bodies of every density dropped in coming to rest at
// their depth without gaining energy, a current's exponential pull, and
// refusals.

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
  World world(sleepless());
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
  const Real drag = 4;  // METAL displaces half its mass: its speed settles at rate 2/s
  world.addField(makeFluidRegion(water(drag)).field);
  simulate(world, 4);
  // Weight less buoyancy against the drag on the displaced liquid,
  // rho_f A k v: v = g (1 - rho_f / rho_b) / (k rho_f / rho_b).
  const double ratio = 1000.0 / materialProperties(Material::Metal).density;
  const double terminal = kG * (1 - ratio) / (drag * ratio);
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

/// A body dropped into a liquid of `densityRatio` times its own density.
struct DropCase {
  const char* name;
  Shape shape;
  double densityRatio;  ///< the body's density over the liquid's
};

/// Area of the part of a circle of `radius` below a line `depth` above its
/// lowest point (the circular segment).
double circularSegmentArea(double radius, double depth) {
  const double d = radius - depth;
  return radius * radius * std::acos(d / radius) - d * std::sqrt(radius * radius - d * d);
}

/// Archimedes: where the centre rests, relative to the surface, when the
/// submerged area is `densityRatio` of the body's. Upright for a box (the
/// wide ones and the light square are stable so), any way for a circle.
double restingCenterHeight(const DropCase& drop) {
  if (drop.shape.type() == ShapeType::Circle) {
    const double radius = drop.shape.circle().radius;
    const double wanted = drop.densityRatio * kPi * radius * radius;
    double low = 0, high = 2 * radius;  // the segment's area grows with its depth
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (low + high);
      (circularSegmentArea(radius, mid) < wanted ? low : high) = mid;
    }
    return radius - 0.5 * (low + high);
  }
  const double halfHeight = drop.shape.polygon().vertices[2].y();
  return halfHeight - drop.densityRatio * 2 * halfHeight;
}

/// Kinetic, gravitational and buoyant energy of a body in `liquid` (surface
/// at y = 0): the liquid's share is rho g A_sub times the submerged
/// centroid's depth, whose gradient is the buoyancy and its torque.
double floatingEnergy(const World& world, BodyId id, const Shape& shape, const FluidDef& liquid) {
  const BodyState state = stateOf(world, id);
  const MassProperties mass = world.bodyDescription(id)->mass;
  Transform at;
  at.p = state.position;
  at.q = Rot::fromAngle(state.angle);
  const SubmergedPart part = submergedPart(shape, at, liquid.polygon);
  const double buoyant = part.area > 0 ? liquid.density * kG * part.area * -double(part.centroid.y()) : 0;
  return 0.5 * mass.mass * state.linearVelocity.squaredNorm() + 0.5 * mass.inertia * state.angularVelocity *
         state.angularVelocity + mass.mass * kG * state.position.y() + buoyant;
}

/// Drops the body with its bottom 1 m above the surface into a liquid of
/// drag 5 (the Floating scene's); returns the worst energy gain over the
/// start (J, asserted per step by the caller), when it came to rest within
/// 2 cm of its depth and stayed, and the worst depth error after 5 s.
struct DropOutcome {
  double worstEnergyGain = 0;
  double settledAfter = -1;   ///< s; -1: not within 2 cm and still by the end
  double worstMissAfter5s = 0;
  int timesOut = 0;           ///< how often it left the liquid after going in
};

DropOutcome dropIntoLiquid(const DropCase& drop) {
  World world;
  const double lowest = drop.shape.type() == ShapeType::Circle ? drop.shape.circle().radius
                                                                : drop.shape.polygon().vertices[2].y();
  BodyDef def = makeBodyDef(drop.shape, Vec2(0, Real(1 + lowest)), {});
  const BodyId body = world.createBody(def).id;
  FluidDef liquid = water(5, 5);
  liquid.density = Real(world.bodyDescription(body)->density / drop.densityRatio);
  world.addField(makeFluidRegion(liquid).field);
  const double rest = restingCenterHeight(drop);
  const double start = floatingEnergy(world, body, drop.shape, liquid);
  DropOutcome out;
  bool wasIn = false;
  for (int step = 1; step <= stepsFor(8); ++step) {
    world.step(kDt);
    const BodyState state = stateOf(world, body);
    out.worstEnergyGain = std::max(out.worstEnergyGain, floatingEnergy(world, body, drop.shape, liquid) - start);
    const bool in = state.position.y() < lowest;  // some of it below the surface
    if (wasIn && !in) ++out.timesOut;
    wasIn = in;
    const double miss = std::abs(state.position.y() - rest);
    const bool still = miss < 0.02 && state.linearVelocity.norm() < 0.05;
    if (!still) out.settledAfter = -1;
    else if (out.settledAfter < 0) out.settledAfter = step * kDt;
    if (step * kDt >= 5) out.worstMissAfter5s = std::max(out.worstMissAfter5s, miss);
  }
  return out;
}

TEST(Fluid, DroppedBodies_RestAtArchimedesDepthWithin5s_GainingNoEnergy) {
  const Shape square = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  const Shape plank = Shape::makePolygon(makeBox(1, Real(0.25)));
  const Shape ball = Shape::makeCircle(Real(0.5));
  const DropCase cases[] = {{"square 0.1", square, 0.1}, {"plank 0.3", plank, 0.3}, {"plank 0.5", plank, 0.5},
                            {"plank 0.9", plank, 0.9},   {"circle 0.1", ball, 0.1},  {"circle 0.3", ball, 0.3},
                            {"circle 0.5", ball, 0.5},   {"circle 0.9", ball, 0.9}};
  for (const DropCase& drop : cases) {
    const DropOutcome out = dropIntoLiquid(drop);
    std::printf("dropped %-10s: at rest after %.2f s, worst depth error after 5 s %.4f m, worst energy gain %.3f J, "
                "left the liquid %d times\n",
                drop.name, out.settledAfter, out.worstMissAfter5s, out.worstEnergyGain, out.timesOut);
    EXPECT_GE(out.settledAfter, 0) << drop.name;
    EXPECT_LE(out.settledAfter, 5) << drop.name;
    EXPECT_LT(out.worstMissAfter5s, 0.02) << drop.name;
    EXPECT_LE(out.worstEnergyGain, 0) << drop.name;
  }
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
