// World queries against closed-form answers: ray casts on every shape type,
// shape casts onto a ground, overlaps, filters, sensors, result limits and
// the refusal of bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numbers>
#include <cmath>
#include <vector>

#include "impulse/dynamic_tree.h"
#include "impulse/world.h"

namespace impulse {
namespace {

constexpr Real kExact = Real(1e-5);
const Real kSqrt2 = std::sqrt(Real(2));

BodyOptions staticOptions() {
  BodyOptions options;
  options.properties.isStatic = true;
  return options;
}

BodyId createStatic(World& world, const Shape& shape, const Vec2& position, Real angle = 0,
                    const ShapeInteraction& interaction = {}) {
  BodyDef def;
  def.shape = shape;
  def.position = position;
  def.angle = angle;
  def.properties.isStatic = true;
  def.interaction = interaction;
  CreateResult created = world.createBody(def);
  EXPECT_TRUE(created.ok()) << created.error;
  return created.id;
}

ShapeId firstShape(const World& world, BodyId body) {
  return world.bodyDescription(body).value().shapes.at(0).id;
}

Polygon roundedBox(Real halfWidth, Real halfHeight, Real radius) {
  Polygon box = makeBox(halfWidth, halfHeight);
  box.radius = radius;
  return box;
}

void expectNear(const Vec2& actual, const Vec2& expected, Real tolerance = kExact) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

// A hit that must exist, checked against its closed form.
void expectHit(const CastResult& result, const Vec2& point, const Vec2& normal, Real fraction) {
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_TRUE(result.hit.has_value());
  expectNear(result.hit->point, point);
  expectNear(result.hit->normal, normal);
  EXPECT_NEAR(result.hit->fraction, fraction, kExact);
}

void expectMiss(const CastResult& result) {
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_FALSE(result.hit.has_value()) << "hit at fraction " << result.hit->fraction;
}

// ---- Rays against each shape type ----

TEST(RayCast, CircleHitAtAnAngle_MeetsTheNearSideOfTheCentreLine) {
  World world;
  const BodyId circle = createStatic(world, Shape::makeCircle(1), Vec2(4, 3));
  // Aimed at the centre, 5 m away: the surface is 4 m along (0.8, 0.6).
  const CastResult aimed = world.castRayClosest(Vec2(0, 0), Vec2(8, 6));
  expectHit(aimed, Vec2(Real(3.2), Real(2.4)), Vec2(Real(-0.8), Real(-0.6)), Real(0.4));
  EXPECT_EQ(aimed.hit->body, circle);
  EXPECT_EQ(aimed.hit->shape, firstShape(world, circle));
  // Half a radius off the centre line: enters sqrt(1 - 0.25) before the centre.
  const Real chord = std::sqrt(Real(0.75));
  expectHit(world.castRayClosest(Vec2(0, Real(3.5)), Vec2(10, 0)), Vec2(4 - chord, Real(3.5)),
            Vec2(-chord, Real(0.5)), (4 - chord) / 10);
}

TEST(RayCast, CapsuleHitOnItsSideAndOnItsRoundEnd) {
  World world;
  ASSERT_TRUE(world.createCapsule(Vec2(-1, 2), Vec2(1, 2), Real(0.5), staticOptions()).ok());
  expectHit(world.castRayClosest(Vec2(0, 5), Vec2(0, -10)), Vec2(0, Real(2.5)), Vec2(0, 1),
            Real(0.25));
  // Aimed at the right end's centre (1, 2) from 5 m along (0.6, 0.8).
  expectHit(world.castRayClosest(Vec2(4, 6), Vec2(-6, -8)), Vec2(Real(1.3), Real(2.4)),
            Vec2(Real(0.6), Real(0.8)), Real(0.45));
}

TEST(RayCast, SegmentIsHitFromEitherSide_NormalFacingTheRay) {
  World world;
  ASSERT_TRUE(world.createSegment(Vec2(-2, 0), Vec2(2, 0), staticOptions()).ok());
  expectHit(world.castRayClosest(Vec2(-1, 1), Vec2(2, -2)), Vec2(0, 0), Vec2(0, 1), Real(0.5));
  expectHit(world.castRayClosest(Vec2(Real(0.5), -1), Vec2(0, 4)), Vec2(Real(0.5), 0), Vec2(0, -1),
            Real(0.25));
  expectMiss(world.castRayClosest(Vec2(3, 1), Vec2(0, -2)));
}

TEST(RayCast, TurnedBoxHitOnTheFaceTheRayMeets) {
  World world;
  // A unit half-size box turned 45 degrees: a diamond with a corner at
  // (sqrt 2, 0) and a face on the line x + y = sqrt 2.
  createStatic(world, Shape::makePolygon(makeBox(1, 1)), Vec2(0, 0), Real(std::numbers::pi / 4));
  const Real hitX = kSqrt2 - Real(0.2);
  expectHit(world.castRayClosest(Vec2(5, Real(0.2)), Vec2(-10, 0)), Vec2(hitX, Real(0.2)),
            Vec2(1, 1) / kSqrt2, (5 - hitX) / 10);
}

TEST(RayCast, RoundedBoxHitOnItsPushedOutFaceAndItsRoundedCorner) {
  World world;
  createStatic(world, Shape::makePolygon(roundedBox(1, 1, Real(0.25))), Vec2(0, 0));
  expectHit(world.castRayClosest(Vec2(5, Real(0.3)), Vec2(-10, 0)), Vec2(Real(1.25), Real(0.3)),
            Vec2(1, 0), Real(0.375));
  // Along the diagonal: the corner circle around (1, 1), radius 0.25.
  const Vec2 diagonal = Vec2(1, 1) / kSqrt2;
  const Real travelled = 4 * kSqrt2 - Real(0.25);
  expectHit(world.castRayClosest(Vec2(5, 5), Vec2(-10, -10)), Vec2(1, 1) + Real(0.25) * diagonal,
            diagonal, travelled / (10 * kSqrt2));
}

TEST(RayCast, RayStartingInsideAShape_DoesNotHitIt) {
  World world;
  createStatic(world, Shape::makePolygon(roundedBox(1, 1, Real(0.25))), Vec2(0, 0));
  createStatic(world, Shape::makeCircle(1), Vec2(10, 0));
  // Inside the rounding band, inside the core, inside the circle.
  expectMiss(world.castRayClosest(Vec2(Real(1.1), 0), Vec2(-Real(0.05), 0)));
  expectMiss(world.castRayClosest(Vec2(0, 0), Vec2(0, 5)));
  expectMiss(world.castRayClosest(Vec2(10, 0), Vec2(0, 5)));
}

TEST(RayCast, ChainIsHitFromItsCollisionSideOnly) {
  World world;
  // Terrain runs right to left: its collision side is up.
  const std::array<Vec2, 4> points{Vec2(10, 0), Vec2(5, 0), Vec2(-5, 0), Vec2(-10, 0)};
  ASSERT_TRUE(world.createChain(points, false).ok());
  expectHit(world.castRayClosest(Vec2(1, 2), Vec2(0, -4)), Vec2(1, 0), Vec2(0, 1), Real(0.5));
  expectMiss(world.castRayClosest(Vec2(1, -2), Vec2(0, 4)));
}

// ---- Closest, all hits, filters and sensors ----

// Three circles of radius 0.5 on the x axis at x = 2, 4, 6.
std::vector<BodyId> circlesInARow(World& world) {
  std::vector<BodyId> bodies;
  for (Real x : {Real(2), Real(4), Real(6)}) bodies.push_back(createStatic(world, Shape::makeCircle(Real(0.5)), Vec2(x, 0)));
  return bodies;
}

TEST(RayCast, AllHitsComeNearestFirst_AndTheClosestIsTheFirstOfThem) {
  World world;
  const std::vector<BodyId> bodies = circlesInARow(world);
  const QueryResult<CastHit> all = world.castRay(Vec2(0, 0), Vec2(10, 0));
  ASSERT_TRUE(all.ok()) << all.error;
  ASSERT_EQ(all.results.size(), 3u);
  EXPECT_FALSE(all.truncated);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(all.results[i].body, bodies[i]);
    EXPECT_NEAR(all.results[i].fraction, Real(0.15) + Real(0.2) * Real(i), kExact);
  }
  const CastResult closest = world.castRayClosest(Vec2(0, 0), Vec2(10, 0));
  ASSERT_TRUE(closest.hit.has_value());
  EXPECT_EQ(closest.hit->body, bodies[0]);
}

TEST(RayCast, MoreHitsThanAskedFor_KeepsTheNearestAndSaysTruncated) {
  World world;
  const std::vector<BodyId> bodies = circlesInARow(world);
  const QueryResult<CastHit> two = world.castRay(Vec2(0, 0), Vec2(10, 0), {}, 2);
  ASSERT_TRUE(two.ok()) << two.error;
  ASSERT_EQ(two.results.size(), 2u);
  EXPECT_TRUE(two.truncated);
  EXPECT_EQ(two.results[0].body, bodies[0]);
  EXPECT_EQ(two.results[1].body, bodies[1]);
}

TEST(RayCast, EqualFractions_GoToTheLowerShapeFirst) {
  World world;
  const BodyId first = createStatic(world, Shape::makeCircle(1), Vec2(3, 0));
  const BodyId second = createStatic(world, Shape::makeCircle(1), Vec2(3, 0));
  const CastResult closest = world.castRayClosest(Vec2(0, 0), Vec2(10, 0));
  ASSERT_TRUE(closest.hit.has_value());
  EXPECT_EQ(closest.hit->body, first);
  const QueryResult<CastHit> all = world.castRay(Vec2(0, 0), Vec2(10, 0));
  ASSERT_EQ(all.results.size(), 2u);
  EXPECT_EQ(all.results[0].body, first);
  EXPECT_EQ(all.results[1].body, second);
}

TEST(RayCast, FilteredShapes_AreNotSeen) {
  World world;
  ShapeInteraction team;
  team.filter.categoryBits = 2;
  createStatic(world, Shape::makeCircle(Real(0.5)), Vec2(2, 0), 0, team);
  const BodyId wall = createStatic(world, Shape::makeCircle(Real(0.5)), Vec2(4, 0));
  QueryFilter skipTeam;
  skipTeam.maskBits = ~std::uint64_t{2};
  const CastResult hit = world.castRayClosest(Vec2(0, 0), Vec2(10, 0), skipTeam);
  ASSERT_TRUE(hit.hit.has_value());
  EXPECT_EQ(hit.hit->body, wall);
  EXPECT_EQ(world.castRay(Vec2(0, 0), Vec2(10, 0), skipTeam).results.size(), 1u);
  EXPECT_EQ(world.castRay(Vec2(0, 0), Vec2(10, 0)).results.size(), 2u);
}

TEST(Queries, SensorsAreNeverSeen) {
  World world;
  ShapeInteraction sensor;
  sensor.isSensor = true;
  createStatic(world, Shape::makeCircle(Real(0.5)), Vec2(2, 0), 0, sensor);
  const BodyId solid = createStatic(world, Shape::makeCircle(Real(0.5)), Vec2(4, 0));
  const CastResult hit = world.castRayClosest(Vec2(0, 0), Vec2(10, 0));
  ASSERT_TRUE(hit.hit.has_value());
  EXPECT_EQ(hit.hit->body, solid);
  EXPECT_EQ(world.castRay(Vec2(0, 0), Vec2(10, 0)).results.size(), 1u);
  EXPECT_EQ(world.overlapAABB(AABB{Vec2(-1, -1), Vec2(10, 1)}).results.size(), 1u);
  EXPECT_FALSE(world.queryPoint(Vec2(2, 0)).has_value());
  EXPECT_EQ(world.queryPoint(Vec2(4, 0)), solid);
}

TEST(Queries, PointQueryTakesAFilter) {
  World world;
  ShapeInteraction team;
  team.filter.categoryBits = 4;
  const BodyId body = createStatic(world, Shape::makeCircle(1), Vec2(0, 0), 0, team);
  QueryFilter others;
  others.maskBits = ~std::uint64_t{4};
  EXPECT_EQ(world.queryPoint(Vec2(Real(0.5), 0)), body);
  EXPECT_FALSE(world.queryPoint(Vec2(Real(0.5), 0), others).has_value());
}

// ---- Shape casts onto a ground whose top is y = 0 ----

World worldWithGround() {
  World world;
  createStatic(world, Shape::makePolygon(makeBox(10, Real(0.5))), Vec2(0, Real(-0.5)));
  return world;
}

// Conservative advancement stops short of the surface by up to the
// tolerance (measured along the normal); the closed form is where it touches.
void expectTouch(const CastResult& result, Real fraction, Real travel, Real pointX) {
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_TRUE(result.hit.has_value());
  EXPECT_LE(result.hit->fraction, fraction + kExact);
  EXPECT_GE(result.hit->fraction, fraction - kShapeCastTolerance / travel - kExact);
  expectNear(result.hit->normal, Vec2(0, 1));
  EXPECT_NEAR(result.hit->point.y(), 0, kShapeCastTolerance);
  EXPECT_NEAR(result.hit->point.x(), pointX, kShapeCastTolerance);
}

TEST(ShapeCast, CircleFallingOntoTheGround_TouchesWhereItsBottomMeetsIt) {
  World world = worldWithGround();
  // Centre from y = 5 to y = 0.5: 4.5 of 10 m down.
  expectTouch(world.castShape(Shape::makeCircle(Real(0.5)), {Vec2(1, 5), Rot{}}, Vec2(0, -10)),
              Real(0.45), 10, 1);
}

TEST(ShapeCast, UprightCapsuleFallingOntoTheGround_TouchesWithItsLowerEnd) {
  World world = worldWithGround();
  const Shape capsule = Shape::makeCapsule(Vec2(0, Real(-0.5)), Vec2(0, Real(0.5)), Real(0.25));
  // Its lowest point starts at 4 - 0.75 = 3.25 above the ground.
  expectTouch(world.castShape(capsule, {Vec2(2, 4), Rot{}}, Vec2(0, -8)), Real(3.25) / 8, 8, 2);
}

TEST(ShapeCast, BoxThrownDownAtAnAngle_LandsFlat) {
  World world = worldWithGround();
  // Bottom face from y = 2.5 to the ground: 2.5 of the 6 m drop, while x
  // moves 3 * 2.5 / 6 = 1.25 to -0.75.
  const CastResult landed =
      world.castShape(Shape::makePolygon(makeBox(Real(0.5), Real(0.5))), {Vec2(-2, 3), Rot{}}, Vec2(3, -6));
  expectTouch(landed, Real(2.5) / 6, 6, Real(-0.75));
}

TEST(ShapeCast, TurnedBoxFallingOntoTheGround_TouchesWithItsCorner) {
  World world = worldWithGround();
  const Real corner = Real(0.5) * kSqrt2;
  const Transform start{Vec2(0, 3), Rot::fromAngle(Real(std::numbers::pi / 4))};
  expectTouch(world.castShape(Shape::makePolygon(makeBox(Real(0.5), Real(0.5))), start, Vec2(0, -6)),
              (3 - corner) / 6, 6, 0);
}

TEST(ShapeCast, StartingOverlapping_HitsAtFractionZero) {
  World world = worldWithGround();
  const CastResult result = world.castShape(Shape::makeCircle(Real(0.5)), {Vec2(0, Real(0.2)), Rot{}}, Vec2(5, 0));
  ASSERT_TRUE(result.hit.has_value());
  EXPECT_EQ(result.hit->fraction, 0);
}

TEST(ShapeCast, PassesThroughAChainFromBehind_AndLandsOnItFromAbove) {
  World world;
  const std::array<Vec2, 4> points{Vec2(10, 0), Vec2(5, 0), Vec2(-5, 0), Vec2(-10, 0)};
  ASSERT_TRUE(world.createChain(points, false).ok());
  const Shape ball = Shape::makeCircle(Real(0.25));
  expectMiss(world.castShape(ball, {Vec2(0, -2), Rot{}}, Vec2(0, 4)));
  expectTouch(world.castShape(ball, {Vec2(0, 2), Rot{}}, Vec2(0, -4)), Real(1.75) / 4, 4, 0);
}

TEST(ShapeCast, PassingBesideAShape_MissesIt) {
  World world;
  createStatic(world, Shape::makeCircle(1), Vec2(0, 0));
  // Diagonally past it, the path 1.6 m from its centre: the swept box
  // covers the circle, the ball stays 0.1 m clear.
  const Real offset = Real(1.6) * kSqrt2;
  expectMiss(world.castShape(Shape::makeCircle(Real(0.5)), {Vec2(-5, offset - 5), Rot{}}, Vec2(10, 10)));
  // Passing 0.1 m closer, it touches.
  const Real closer = Real(1.4) * kSqrt2;
  const CastResult touched = world.castShape(Shape::makeCircle(Real(0.5)), {Vec2(-5, closer - 5), Rot{}}, Vec2(10, 10));
  ASSERT_TRUE(touched.hit.has_value());
  EXPECT_NEAR(touched.hit->point.norm(), 1, kShapeCastTolerance);
}

// ---- Overlaps ----

TEST(Overlap, AABBListsShapesWhoseTightBoxOverlaps_NotTheirFatBox) {
  World world;
  // Dynamic bodies: their broad-phase boxes are fattened (by up to kAabbMargin).
  const CreateResult inside = world.createCircle(Vec2(0, 0), Real(0.5));
  const CreateResult near = world.createCircle(Vec2(Real(1.55), 0), Real(0.5));
  ASSERT_TRUE(inside.ok() && near.ok());
  // The query box ends at x = 1: the near circle's tight box starts at 1.05.
  const QueryResult<ShapeId> found = world.overlapAABB(AABB{Vec2(-1, -1), Vec2(1, 1)});
  ASSERT_TRUE(found.ok()) << found.error;
  ASSERT_EQ(found.results.size(), 1u);
  EXPECT_EQ(found.results[0], firstShape(world, inside.id));
}

TEST(Overlap, AABBPastTheLimit_KeepsTheFirstInSlotOrderAndSaysTruncated) {
  World world;
  const std::vector<BodyId> bodies = circlesInARow(world);
  const QueryResult<ShapeId> two = world.overlapAABB(AABB{Vec2(0, -1), Vec2(10, 1)}, {}, 2);
  ASSERT_EQ(two.results.size(), 2u);
  EXPECT_TRUE(two.truncated);
  EXPECT_EQ(two.results[0], firstShape(world, bodies[0]));
  EXPECT_EQ(two.results[1], firstShape(world, bodies[1]));
  EXPECT_FALSE(world.overlapAABB(AABB{Vec2(0, -1), Vec2(10, 1)}, {}, 3).truncated);
}

TEST(Overlap, ShapeOverlapIsGeometric_NotByBoundingBox) {
  World world;
  const BodyId box = createStatic(world, Shape::makePolygon(makeBox(1, 1)), Vec2(0, 0));
  const Shape ball = Shape::makeCircle(Real(0.5));
  // Beside the corner (1, 1): 0.57 m from it (boxes overlap), then 0.42 m.
  const QueryResult<ShapeId> clear = world.overlapShape(ball, {Vec2(Real(1.4), Real(1.4)), Rot{}});
  ASSERT_TRUE(clear.ok()) << clear.error;
  EXPECT_TRUE(clear.results.empty());
  const QueryResult<ShapeId> touching = world.overlapShape(ball, {Vec2(Real(1.3), Real(1.3)), Rot{}});
  ASSERT_EQ(touching.results.size(), 1u);
  EXPECT_EQ(touching.results[0], firstShape(world, box));
}

// ---- The broad phase's ray traversal ----

TEST(TreeRayCast, ShortRayInALargeTree_VisitsOnlyTheLeavesOnItsWay) {
  DynamicTree tree;
  for (int x = 0; x < 100; ++x) {
    for (int y = 0; y < 100; ++y) {
      tree.createProxy(AABB{Vec2(Real(x), Real(y)), Vec2(x + Real(0.5), y + Real(0.5))}, x * 100 + y);
    }
  }
  // Along y = 50.25 from x = 10 to 12.9: it crosses the boxes of x = 10..12.
  std::vector<std::int32_t> visited;
  tree.rayCast({Vec2(10, Real(50.25)), Vec2(Real(2.9), 0), 1, Vec2::Zero()}, [&](std::int32_t node, Real maxFraction) {
    visited.push_back(tree.userValue(node));
    return maxFraction;
  });
  std::sort(visited.begin(), visited.end());
  EXPECT_EQ(visited, (std::vector<std::int32_t>{1050, 1150, 1250}));
}

TEST(TreeRayCast, ClippingAtTheFirstHit_SkipsEveryBoxBeyondIt) {
  DynamicTree tree;
  for (int x = 0; x < 50; ++x) tree.createProxy(AABB{Vec2(Real(x), 0), Vec2(x + Real(0.5), 1)}, x);
  std::vector<std::int32_t> visited;
  tree.rayCast({Vec2(-1, Real(0.5)), Vec2(100, 0), 1, Vec2::Zero()}, [&](std::int32_t node, Real) {
    visited.push_back(tree.userValue(node));
    // A hit on this box's near side: nothing beyond it can be nearer.
    return (tree.box(node).lower.x() + 1) / 100;
  });
  // The nearer child is searched first, so the nearest box comes first and
  // its hit leaves the other 49 boxes beyond the clipped ray.
  EXPECT_EQ(visited, std::vector<std::int32_t>{0});
}

// ---- Bad input ----

TEST(Queries, BadInputIsRefusedWithTheFieldNamed_AndChangesNothing) {
  World world = worldWithGround();
  const std::uint64_t before = world.stateHash();
  const Real nan = std::nan("");
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_NE(world.castRayClosest(Vec2(nan, 0), Vec2(1, 0)).error.find("origin"), std::string::npos);
  EXPECT_NE(world.castRayClosest(Vec2(0, 0), Vec2(inf, 0)).error.find("translation"), std::string::npos);
  EXPECT_NE(world.castRay(Vec2(0, 0), Vec2(0, 0)).error.find("zero length"), std::string::npos);
  EXPECT_NE(world.castRay(Vec2(0, 0), Vec2(1, 0), {}, 0).error.find("maxHits"), std::string::npos);
  EXPECT_NE(world.castRay(Vec2(0, 0), Vec2(1, 0), {}, kMaxQueryResults + 1).error.find("maxHits"),
            std::string::npos);
  EXPECT_NE(world.castRay(Vec2(0, 0), Vec2(1e30f, 1e30f)).error.find("translation"), std::string::npos);
  const Shape segment = Shape::makeSegment(Vec2(0, 0), Vec2(1, 0));
  EXPECT_NE(world.castShape(segment, {}, Vec2(1, 0)).error.find("shape"), std::string::npos);
  EXPECT_NE(world.castShape(Shape::makeCircle(-1), {}, Vec2(1, 0)).error.find("shape"), std::string::npos);
  EXPECT_NE(world.castShape(Shape::makeCircle(1), {Vec2(0, 0), Rot{2, 0}}, Vec2(1, 0)).error.find("start"),
            std::string::npos);
  EXPECT_NE(world.overlapAABB(AABB{Vec2(1, 1), Vec2(0, 0)}).error.find("box"), std::string::npos);
  EXPECT_NE(world.overlapAABB(AABB{Vec2(0, 0), Vec2(1, 1)}, {}, -3).error.find("maxResults"),
            std::string::npos);
  EXPECT_NE(world.overlapShape(Shape::makeCircle(1), {Vec2(nan, 0), Rot{}}).error.find("transform"),
            std::string::npos);
  EXPECT_FALSE(world.queryPoint(Vec2(nan, 0)).has_value());
  EXPECT_EQ(world.stateHash(), before);
}

}  // namespace
}  // namespace impulse
