// Stacks that must stand, overlaps that must resolve gently, a crowded scene
// that must stay finite and contained, and sleeping islands.

#include <gtest/gtest.h>

#include <cstdio>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "graph_coloring.h"
#include "impulse/scenes/stress.h"
#include "impulse/world.h"
#include "joint_test_support.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

// ---- Stacks ----

TEST(Stacking, TenBoxTowerStandsTenSeconds_AndFallsAsleep) {
  World world;
  std::vector<BodyId> boxes = buildTower(world, 10);
  const BodyState topStart = stateOf(world, boxes.back());
  simulate(world, 10);

  for (std::size_t i = 0; i < boxes.size(); ++i) {
    SCOPED_TRACE(i);
    BodyState s = stateOf(world, boxes[i]);
    // No box leaves the column or tips: 1 cm sideways, 0.01 rad (a 1 m box
    // tipped by 0.01 rad lifts a corner by 5 mm, the linear slop).
    EXPECT_NEAR(s.position.x(), 0, 0.01);
    EXPECT_NEAR(s.angle, 0, 0.01);
    EXPECT_FALSE(s.awake);
  }
  BodyState top = stateOf(world, boxes.back());
  // 1 cm sideways drift of the top; it may sink by the slop of each of its
  // 10 contacts (5 mm each).
  EXPECT_NEAR(top.position.x(), topStart.position.x(), 0.01);
  EXPECT_NEAR(top.position.y(), topStart.position.y(), 10 * 0.005);
  EXPECT_EQ(world.awakeBodyCount(), 0);
}

TEST(Stacking, TwentyRowPyramidStandsTenSeconds_AndFallsAsleep) {
  World world;
  Pyramid pyramid = buildPyramid(world, 20);
  std::vector<Vec2> starts;
  for (BodyId id : pyramid.boxes) starts.push_back(stateOf(world, id).position);
  simulate(world, 10);

  // Every box within 3 cm of where it was built, sideways (under one pixel at
  // the viewer's 32 px/m: the pyramid sways while its soft contacts compress
  // in the first 0.6 s, then stands still and sleeps); at most the slop
  // of its 20 supporting layers (5 mm each) lower.
  double worstSideways = 0;
  double worstSink = 0;
  for (std::size_t i = 0; i < pyramid.boxes.size(); ++i) {
    BodyState s = stateOf(world, pyramid.boxes[i]);
    worstSideways = std::max(worstSideways, double(std::abs(s.position.x() - starts[i].x())));
    worstSink = std::max(worstSink, double(starts[i].y() - s.position.y()));
    EXPECT_NEAR(s.angle, 0, 0.01) << "box " << i << " tipped";
  }
  EXPECT_LT(worstSideways, 0.03);
  EXPECT_LT(worstSink, 20 * 0.005);
  BodyState top = stateOf(world, pyramid.top);
  EXPECT_NEAR(top.position.x(), pyramid.topStart.x(), 0.03);
  EXPECT_EQ(world.awakeBodyCount(), 0) << "all " << pyramid.boxes.size() << " boxes asleep";
}

// A straight 15-box tower kept awake for 10 s must not lean: nothing in the
// scene prefers a side, so any lean is the solver's. Solving a manifold's two
// points always in the same order leaned it 0.21 m; alternating the order
// each sub-step keeps it at the float noise (measured 0.0000 m).
TEST(Stacking, StraightFifteenBoxTowerDoesNotLean_WhenKeptAwake) {
  World world(sleepless());
  std::vector<BodyId> boxes = buildTower(world, 15);
  simulate(world, 10);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    BodyState s = stateOf(world, boxes[i]);
    EXPECT_NEAR(s.position.x(), 0, 0.001) << "box " << i;
    EXPECT_NEAR(s.angle, 0, 0.001) << "box " << i;
  }
}

// The hard stacks, each kept awake for 10 s at the default settings.
// Soft contacts alone let them sink (a 60-row pyramid's top 0.28 m) or fall
// through (a 300:1 load on a light pyramid); the support pass holds each
// body up on what is under it.
Real sinkOf(const World& world, BodyId id, const Vec2& start) { return start.y() - stateOf(world, id).position.y(); }

TEST(Stacking, SixtyRowPyramidTopSinksUnderFiveCentimetres_AndStaysInColumn) {
  World world(sleepless());
  Pyramid pyramid = buildPyramid(world, 60);
  simulate(world, 10);
  BodyState top = stateOf(world, pyramid.top);
  EXPECT_LT(std::abs(sinkOf(world, pyramid.top, pyramid.topStart)), 0.05);
  EXPECT_NEAR(top.position.x(), pyramid.topStart.x(), 0.02);
  EXPECT_NEAR(top.angle, 0, 0.01);
}

TEST(Stacking, HundredRowPyramidTopSinksUnderTenCentimetres) {
  World world(sleepless());
  Pyramid pyramid = buildPyramid(world, 100);
  simulate(world, 10);
  EXPECT_LT(std::abs(sinkOf(world, pyramid.top, pyramid.topStart)), 0.10);
  EXPECT_NEAR(stateOf(world, pyramid.top).position.x(), pyramid.topStart.x(), 0.05);
}

// 15 boxes alternately 1 cm left and right: every box within 1 cm of where
// it started.
TEST(Stacking, OffsetFifteenBoxTower_EveryBoxStaysWithinOneCentimetre) {
  World world(sleepless());
  std::vector<BodyId> boxes = buildTower(world, 15, Real(0.01));
  std::vector<Vec2> start;
  for (BodyId id : boxes) start.push_back(stateOf(world, id).position);
  simulate(world, 10);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_LT((stateOf(world, boxes[i]).position - start[i]).norm(), 0.01) << "box " << i;
  }
}

// A 1 m box `ratio` times the mass of each 1 m box under it.
BodyId addHeavyBox(World& world, const Vec2& center, Real ratio, Real lightDensity, Real lightArea) {
  BodyDef def;
  def.shape = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  def.position = center;
  def.materialOverride.density = ratio * lightDensity * lightArea;
  return world.createBody(def).id;
}

class HeavyLoad : public testing::TestWithParam<int> {};

// On the top of a base-10 pyramid: holds 10 s and sinks under 2 cm.
TEST_P(HeavyLoad, OnBaseTenPyramid_HoldsAndSinksUnderTwoCentimetres) {
  World world(sleepless());
  Pyramid pyramid = buildPyramid(world, 10);
  const Vec2 start = pyramid.topStart + Vec2(0, 1);
  BodyId heavy = addHeavyBox(world, start, Real(GetParam()), materialProperties(Material::Solid).density, 1);
  simulate(world, 10);
  EXPECT_LT(std::abs(sinkOf(world, heavy, start)), 0.02);
  // It creeps sideways a little (measured 3.0, 1.4 and 2.5 cm at 180, 300
  // and 1000:1, either way): on top still.
  EXPECT_NEAR(stateOf(world, heavy).position.x(), start.x(), 0.05);
  EXPECT_NEAR(stateOf(world, pyramid.top).position.y(), pyramid.topStart.y(), 0.02);
}

// On one 0.5 m box on the ground: sinks under 1 cm.
TEST_P(HeavyLoad, OnOneSmallBox_SinksUnderOneCentimetre) {
  World world(sleepless());
  addGround(world);
  BodyId small = addBox(world, {.center = Vec2(0, Real(0.25)), .halfWidth = Real(0.25), .halfHeight = Real(0.25)});
  const Vec2 start(0, 1);
  BodyId heavy = addHeavyBox(world, start, Real(GetParam()), materialProperties(Material::Solid).density, Real(0.25));
  ASSERT_NEAR(world.bodyDescription(heavy)->mass.mass / world.bodyDescription(small)->mass.mass, GetParam(), 1e-3);
  simulate(world, 10);
  EXPECT_LT(std::abs(sinkOf(world, heavy, start)), 0.01);
  EXPECT_NEAR(stateOf(world, heavy).position.x(), 0, 0.01);
  EXPECT_NEAR(stateOf(world, small).position.x(), 0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Stacking, HeavyLoad, testing::Values(180, 300, 1000),
                         [](const testing::TestParamInfo<int>& ratio) { return "Ratio" + std::to_string(ratio.param); });

TEST(Stacking, HeavyBoxHoldsOnLightBoxes_AtMassRatioOneToHundred) {
  // Two 1 m ICE boxes (100 kg each) carry a 2.5 m x 2 m METAL box
  // (10000 kg): 1:100 per supporting box.
  World world;
  addGround(world);
  std::array<BodyId, 2> light = {
      addBox(world, {.center = Vec2(Real(-0.75), Real(0.5)), .material = Material::Ice}),
      addBox(world, {.center = Vec2(Real(0.75), Real(0.5)), .material = Material::Ice})};
  BodyId heavy = addBox(world, {.center = Vec2(0, 2),
                                .halfWidth = Real(1.25),
                                .halfHeight = 1,
                                .material = Material::Metal});
  ASSERT_NEAR(world.bodyDescription(heavy)->mass.mass / world.bodyDescription(light[0])->mass.mass,
              100, 1e-3);
  simulate(world, 5);

  BodyState top = stateOf(world, heavy);
  // A soft contact of stiffness f behaves like a spring scaled by the
  // lighter body's mass: under a load 100 times that mass it settles about
  // 100 g / (2 pi 30 Hz)^2 = 2.8 cm deep, plus the 5 mm ground slop. 3 cm;
  // it must stay level and stop sinking (asleep below).
  EXPECT_NEAR(top.position.y(), 2, 0.03);
  EXPECT_NEAR(top.position.x(), 0, 0.005);
  EXPECT_NEAR(top.angle, 0, 0.005);
  for (std::size_t i = 0; i < light.size(); ++i) {
    BodyState s = stateOf(world, light[i]);
    // ICE has mu 0.03: the light boxes must not be squeezed out sideways.
    EXPECT_NEAR(s.position.x(), i == 0 ? -0.75 : 0.75, 0.005);
    EXPECT_NEAR(s.angle, 0, 0.005);
  }
  EXPECT_EQ(world.awakeBodyCount(), 0);
}

// A board carrying 80 boxes touches more bodies than there are colours
// (GraphColoring::kColorCount, 64): the contacts that find none are solved
// one by one after the coloured ones. They hold their boxes up as the
// coloured ones do, and the board lies level on the ground.
TEST(Stacking, BoardCarryingEightyBoxes_HoldsEveryOne_ThoughItsContactsOutnumberTheColours) {
  constexpr Real kPitch = Real(0.5);
  World world;
  addGround(world, 0, 24);
  const BodyId board = addBox(
      world, {.center = Vec2(0, Real(0.25)), .halfWidth = Real(20.5), .halfHeight = Real(0.25), .material = Material::Wood});
  std::vector<BodyId> boxes;
  for (int i = 0; i < 80; ++i) {
    boxes.push_back(addBox(world, {.center = Vec2(kPitch * (Real(i) - Real(39.5)), Real(0.7)),
                                   .halfWidth = Real(0.2),
                                   .halfHeight = Real(0.2)}));
  }
  simulate(world, 3);

  ASSERT_GT(world.contactCount(), GraphColoring::kColorCount);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    SCOPED_TRACE(i);
    const BodyState s = stateOf(world, boxes[i]);
    // Two contacts' slop (5 mm each) at most: on the board, the board on the ground.
    EXPECT_NEAR(s.position.y(), 0.7, 0.01);
    EXPECT_NEAR(s.position.x(), kPitch * (double(i) - 39.5), 0.005);
    EXPECT_NEAR(s.angle, 0, 0.005);
  }
  EXPECT_NEAR(stateOf(world, board).position.y(), 0.25, 0.005);
  EXPECT_NEAR(stateOf(world, board).angle, 0, 0.001);
}

// A FOAM box on a FOAM box sinks too little for the support pass to hold
// the upper one up (only the row on the ground is kept). Made GLASS, 83
// times heavier, with the same contacts between the same bodies, the upper
// box is held up from the step its mass changed: the pass works out the
// loads a stack carries at rest only when its contacts change, and a
// changed mass counts as such a change.
TEST(Stacking, BoxMadeHeavyOnAStack_IsHeldUpFromTheStepItsMassChanged) {
  World world(sleepless());
  addGround(world);
  addBox(world, {.center = Vec2(0, Real(0.5)), .material = Material::Foam});
  const BodyId upper = addBox(world, {.center = Vec2(0, Real(1.5)), .material = Material::Foam});
  simulate(world, 1);
  ASSERT_EQ(world.profile().passes.supportRows, 1) << "light: only the row on the ground";
  ASSERT_TRUE(world.setMaterial(upper, Material::Glass).ok());
  world.step(kDt);
  EXPECT_EQ(world.profile().passes.supportRows, 2);
}

// A support row never lifts a body with joints: two pinned boxes on the
// ground take no row (the pass does not even level them). A GLASS box set
// on one of them, free and 83 times heavier, is held up all the same.
TEST(Stacking, FreeBoxOnAJointedOne_IsHeldUp_WhereJointedBoxesAloneTakeNoRow) {
  World world(sleepless());
  addGround(world);
  const BodyId lower = addBox(world, {.center = Vec2(0, Real(0.5)), .material = Material::Foam});
  const BodyId beside =
      addBox(world, {.center = Vec2(Real(1.02), Real(0.5)), .material = Material::Foam});
  const Vec2 pin(Real(0.51), Real(0.5));
  addJoint(world, lower, beside, pin, pin, RevoluteJointSettings{});
  simulate(world, 1);
  ASSERT_EQ(world.profile().passes.supportRows, 0) << "every moving body has a joint";
  addBox(world, {.center = Vec2(0, Real(1.5)), .material = Material::Glass});
  simulate(world, 1);
  EXPECT_EQ(world.profile().passes.supportRows, 1) << "the glass box's row on the jointed box";
}

TEST(Overlap, HalfOverlappingBoxesSeparate_WithoutLaunching) {
  World world;
  addGround(world);
  // Two 1 m boxes on the ground, spawned half inside each other.
  BodyId left = addBox(world, {.center = Vec2(0, Real(0.5))});
  BodyId right = addBox(world, {.center = Vec2(Real(0.5), Real(0.5))});
  double fastest = 0;
  simulateUntil(world, 3, [&] {
    for (BodyId id : {left, right}) {
      fastest = std::max(fastest, double(stateOf(world, id).linearVelocity.norm()));
    }
    return false;
  });
  // Overlap no load explains is pushed out through positions, not
  // velocities: what remains is the small soft push a fresh contact may use
  // (measured 0.03 m/s). The bound for overlap recovery: 1 m/s.
  EXPECT_LT(fastest, 1.0);
  BodyState a = stateOf(world, left);
  BodyState b = stateOf(world, right);
  // Separated: centres at least one box width apart, minus the 5 mm slop.
  EXPECT_GT(std::abs(b.position.x() - a.position.x()), 1 - 0.005);
  // Neither launched up nor tipped over: still on the ground.
  EXPECT_NEAR(a.position.y(), 0.5, 0.01);
  EXPECT_NEAR(b.position.y(), 0.5, 0.01);
}

// The bench's overlap-recovery scene: a base-4 pyramid built at 0.75 m pitch,
// every box a quarter inside its neighbours.
TEST(Overlap, PyramidBuiltAtQuarterOverlap_SeparatesWithoutThrowingBoxes) {
  World world;
  addGround(world);
  std::vector<BodyId> boxes;
  for (int row = 0; row < 4; ++row) {
    const int count = 4 - row;
    for (int i = 0; i < count; ++i) {
      Real x = Real(0.75) * (Real(i) - Real(0.5) * Real(count - 1));
      boxes.push_back(addBox(world, {.center = Vec2(x, Real(0.5) + Real(0.75) * Real(row))}));
    }
  }
  double fastest = 0;
  simulateUntil(world, 3, [&] {
    for (BodyId id : boxes) fastest = std::max(fastest, double(stateOf(world, id).linearVelocity.norm()));
    return false;
  });
  // Issue target: below 1 m/s (was 3.5 m/s with the push in velocities;
  // measured 0.04 m/s now).
  EXPECT_LT(fastest, 1.0);
  // Separated within 3 s: every box of the bottom row on the ground, and
  // the rows a full box height apart (5 mm slop).
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(stateOf(world, boxes[std::size_t(i)]).position.y(), 0.5, 0.005);
  EXPECT_GT(stateOf(world, boxes.back()).position.y(), 3.5 - 0.02);
}

// A closed static container with inner walls at |x| = halfSize and y in
// [0, 2 halfSize].
struct Container {
  Real halfSize;

  Container(World& world, Real half) : halfSize(half) {
    const Real t = 1;  // wall thickness
    addBox(world,
           {.center = Vec2(0, -t), .halfWidth = half + 2 * t, .halfHeight = t, .isStatic = true});
    addBox(world, {.center = Vec2(0, 2 * half + t),
                   .halfWidth = half + 2 * t,
                   .halfHeight = t,
                   .isStatic = true});
    addBox(world,
           {.center = Vec2(-half - t, half), .halfWidth = t, .halfHeight = half, .isStatic = true});
    addBox(world,
           {.center = Vec2(half + t, half), .halfWidth = t, .halfHeight = half, .isStatic = true});
  }
  bool contains(const Vec2& p) const {
    return std::abs(p.x()) < halfSize && p.y() > 0 && p.y() < 2 * halfSize;
  }
};

TEST(Crowd, ThousandRandomBodiesStayFiniteAndInsideClosedBox_ForSixtySeconds) {
  World world;
  Container box(world, 12);
  std::mt19937 random(20240601);
  std::uniform_real_distribution<Real> position(-11, 11);
  std::uniform_real_distribution<Real> size(Real(0.15), Real(0.35));
  std::uniform_real_distribution<Real> speed(-5, 5);
  std::uniform_real_distribution<Real> angle(0, Real(kPi));
  std::uniform_int_distribution<int> material(0, kMaterialCount - 1);
  // Spawned anywhere inside, overlapping freely, with random velocities.
  for (int i = 0; i < 1000; ++i) {
    Vec2 centre(position(random), position(random) + 12);
    Vec2 velocity(speed(random), speed(random));
    Material m = *materialFromIndex(material(random));
    if (i % 2 == 0) {
      addCircle(world,
                {.center = centre, .radius = size(random), .material = m, .velocity = velocity});
    } else {
      addBox(world, {.center = centre,
                     .halfWidth = size(random),
                     .halfHeight = size(random),
                     .angle = angle(random),
                     .material = m,
                     .velocity = velocity});
    }
  }
  const std::vector<BodyId> bodies = dynamicBodies(world);
  ASSERT_EQ(bodies.size(), 1000u);

  int escapedAtStep = -1;
  int nonFiniteAtStep = -1;
  simulateUntil(world, 60, [&] {
    const int step = static_cast<int>(world.stepCount());
    for (BodyId id : bodies) {
      BodyState s = stateOf(world, id);
      if (!isFinite(s.position) || !isFinite(s.linearVelocity) || !isFinite(s.angularVelocity)) {
        nonFiniteAtStep = step;
        return true;
      }
      if (!box.contains(s.position)) {
        escapedAtStep = step;
        return true;
      }
    }
    return false;
  });
  EXPECT_EQ(nonFiniteAtStep, -1) << "a state became NaN or infinite";
  EXPECT_EQ(escapedAtStep, -1) << "a body's centre left the container";
  EXPECT_EQ(world.stepCount(), static_cast<std::uint64_t>(stepsFor(60)));
  // The pile settles in about 10 s; after 60 s every body sleeps.
  EXPECT_EQ(world.awakeBodyCount(), 0);
}

// Box2D v3's "confined" benchmark: 625 unit circles at 0.72 m pitch (28 %
// overlap) in a closed 20 m box without gravity. They cannot all fit, so
// the overlap stays; what matters is that pushing it does not throw them
// (no circle faster than 0.5 m/s; measured 0.14) and that no two circles
// end squeezed most of the way through each other (the deepest pair is
// 0.68 m in; Box2D 2.4.1 and Chipmunk end at 0.39-0.67 in the bench).
TEST(Crowd, ConfinedOverlappingCircles_AreNotThrownApart) {
  WorldSettings settings = sleepless();
  settings.gravity = Vec2::Zero();
  World world(settings);
  Container box(world, 10);
  std::vector<BodyId> circles;
  for (int row = 0; row < 25; ++row) {
    for (int column = 0; column < 25; ++column) {
      Vec2 centre(Real(-8.75 + 0.72 * column), Real(1.25 + 0.72 * row));
      circles.push_back(addCircle(world, {.center = centre, .radius = Real(0.5), .material = Material::Metal}));
    }
  }
  double fastest = 0;
  simulateUntil(world, 5, [&] {
    for (BodyId id : circles) fastest = std::max(fastest, double(stateOf(world, id).linearVelocity.norm()));
    return false;
  });
  double deepest = 0;
  for (std::size_t i = 0; i < circles.size(); ++i) {
    const Vec2 p = stateOf(world, circles[i]).position;
    for (std::size_t j = i + 1; j < circles.size(); ++j) {
      deepest = std::max(deepest, 1 - double((stateOf(world, circles[j]).position - p).norm()));
    }
  }
  std::printf("measured: confined crowd fastest body %.3g m/s, deepest pair at the end %.3g m\n", fastest,
              deepest);
  EXPECT_LT(fastest, 0.5);
  EXPECT_LT(deepest, 0.75);
}

// A squeezed crowd (the bench's squeeze-900): a 30x30 square lattice of
// touching unit circles in an open box exactly 30 m wide, under gravity.
// Every row is held at full width by the walls, so the right answer is that
// nothing moves. The columns against the walls touch the static world at
// every storey; the support pass must still stand them on the ground
// storey by storey (it once took them for storey 1 and left the top of
// each falling: 0.91 m/s).
TEST(Crowd, SqueezedLatticeOfCircles_HoldsStill) {
  World world(sleepless());
  const Real half = 15;
  addBox(world, {.center = Vec2(0, -1), .halfWidth = half + 2, .halfHeight = 1, .isStatic = true});
  for (Real side : {Real(-1), Real(1)}) {
    addBox(world, {.center = Vec2(side * (half + 1), 16), .halfWidth = 1, .halfHeight = 16, .isStatic = true});
  }
  std::vector<BodyId> circles;
  for (int row = 0; row < 30; ++row) {
    for (int column = 0; column < 30; ++column) {
      const Vec2 centre(-half + Real(0.5) + Real(column), Real(0.5) + Real(row));
      circles.push_back(addCircle(world, {.center = centre, .radius = Real(0.5), .material = Material::Metal}));
    }
  }
  double fastest = 0;
  simulateUntil(world, 10, [&] {
    for (BodyId id : circles) fastest = std::max(fastest, double(stateOf(world, id).linearVelocity.norm()));
    return false;
  });
  std::printf("measured: squeezed lattice fastest body %.4g m/s\n", fastest);
  EXPECT_LT(fastest, 0.01);
}

// ---- Sleeping ----

// Ground and a two-box stack, run until asleep.
struct SleepingStack {
  World world;
  BodyId lower;
  BodyId upper;

  SleepingStack() {
    addGround(world);
    lower = addBox(world, {.center = Vec2(0, Real(0.5))});
    upper = addBox(world, {.center = Vec2(0, Real(1.5))});
    // timeToSleep is 0.5 s; 2 s leaves ample time for the stack to settle.
    EXPECT_GT(simulateUntilAsleep(world, 2), 0);
  }
};

TEST(Sleeping, RestingIslandCostsNothing_OnceAsleep) {
  SleepingStack stack;
  World& world = stack.world;
  ASSERT_EQ(world.awakeBodyCount(), 0);
  const std::uint64_t hash = world.stateHash();
  simulate(world, 1);
  EXPECT_EQ(world.awakeBodyCount(), 0);
  EXPECT_TRUE(world.movedBodies().empty()) << "sleeping bodies are not reported as moved";
  EXPECT_EQ(world.stateHash(), hash) << "sleeping bodies do not move by a single bit";
}

TEST(Sleeping, ApplyImpulseWakesTheIsland) {
  SleepingStack stack;
  World& world = stack.world;
  ASSERT_TRUE(world.applyImpulse(stack.upper, Vec2(50, 0)));
  // The whole island wakes at once, not only the pushed body.
  EXPECT_TRUE(stateOf(world, stack.upper).awake);
  EXPECT_TRUE(stateOf(world, stack.lower).awake);
  EXPECT_EQ(world.awakeBodyCount(), 2);
  world.step(kDt);
  // 50 N s on 500 kg: 0.1 m/s, minus what friction took in one step.
  EXPECT_GT(stateOf(world, stack.upper).linearVelocity.x(), 0.05);
}

TEST(Sleeping, BodyDroppedOnSleepingIslandWakesIt) {
  SleepingStack stack;
  World& world = stack.world;
  BodyId ball = addCircle(world, {.center = Vec2(0, 4), .radius = Real(0.3)});
  bool lowerWoke = false;
  simulateUntil(world, 2, [&] {
    lowerWoke = lowerWoke || stateOf(world, stack.lower).awake;
    return lowerWoke;
  });
  EXPECT_TRUE(lowerWoke) << "the impact reaches the bottom of the island";
  EXPECT_GT(simulateUntilAsleep(world, 10), 0) << "and the island sleeps again";
  // The ball rolled off or came to rest on top; the stack still stands.
  EXPECT_NEAR(stateOf(world, stack.upper).position.x(), 0, 0.05);
  EXPECT_TRUE(world.isValid(ball));
}

TEST(Sleeping, DestroyingSupportingBodyWakesWhatRestedOnIt) {
  SleepingStack stack;
  World& world = stack.world;
  ASSERT_TRUE(world.destroyBody(stack.lower));
  EXPECT_TRUE(stateOf(world, stack.upper).awake);
  EXPECT_EQ(world.awakeBodyCount(), 1);
  // It falls 1 m onto the ground and rests there (centre 0.5 m up, within
  // the 5 mm slop).
  EXPECT_GT(simulateUntilAsleep(world, 5), 0);
  EXPECT_NEAR(stateOf(world, stack.upper).position.y(), 0.5, 0.005);
}

}  // namespace
}  // namespace impulse
