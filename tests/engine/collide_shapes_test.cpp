// Manifolds and separations of the shape types beyond sharp polygons and
// centred circles: capsules, segments, rounded polygons, offset circles and
// one-sided chain segments, and the table that dispatches every pair.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "impulse/manifold.h"
#include "impulse/shape.h"
#include "shape_pair.h"

namespace impulse {
namespace {

// Float round-off on unit-sized shapes near the origin.
constexpr Real kTolerance = Real(1e-5);
// Shapes tens of metres from the origin (ulp ~ 4e-6 at 32 m).
constexpr Real kFarTolerance = Real(1e-4);

Transform makeTransform(Real x, Real y, Real angle = 0) {
  return {Vec2(x, y), Rot::fromAngle(angle)};
}

void expectVecNear(const Vec2& actual, const Vec2& expected, Real tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

std::string describePair(const Shape& a, const Shape& b) {
  return std::to_string(int(a.type())) + "-" + std::to_string(int(b.type()));
}

// Invariants every manifold must satisfy.
void expectWellFormed(const Manifold& m, const Transform& xfA, const Transform& xfB,
                      Real tolerance = kTolerance) {
  ASSERT_LE(m.pointCount, 2);
  if (m.pointCount > 0) {
    EXPECT_NEAR(m.normal.norm(), 1, kTolerance);
  }
  for (int i = 0; i < m.pointCount; ++i) {
    const ManifoldPoint& mp = m.points[i];
    EXPECT_TRUE(isFinite(mp.point));
    EXPECT_LT(mp.separation, kSpeculativeDistance);
    expectVecNear(mp.anchorA, mp.point - xfA.p, tolerance);
    expectVecNear(mp.anchorB, mp.point - xfB.p, tolerance);
  }
}

Manifold collideChecked(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                        Real tolerance = kTolerance) {
  Manifold m = collide(a, xfA, b, xfB);
  expectWellFormed(m, xfA, xfB, tolerance);
  return m;
}

Real separationOf(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB) {
  return computeSeparation(refOf(a), xfA, refOf(b), xfB);
}

Shape roundedBox(Real halfWidth, Real halfHeight, Real radius) {
  Polygon box = makeBox(halfWidth, halfHeight);
  box.radius = radius;
  return Shape::makePolygon(box);
}

// A flat chain along y = 0 whose collision side is up: it runs from right to
// left (the right of its direction is up). Points every `spacing` metres.
ChainBuild flatChain(int segments, Real spacing) {
  std::vector<Vec2> points;
  for (int i = segments + 2; i >= 0; --i) points.push_back(Vec2(Real(i - 1) * spacing, 0));
  return buildChain(points, false);
}

// ---- The table ----

TEST(CollideTable, EveryUnorderedPairHasExactlyOneOrder) {
  for (int i = 0; i < kShapeTypeCount; ++i) {
    for (int j = 0; j < kShapeTypeCount; ++j) {
      const auto a = static_cast<ShapeType>(i), b = static_cast<ShapeType>(j);
      const bool forward = collideFunction(a, b) != nullptr;
      const bool backward = collideFunction(b, a) != nullptr;
      if (i == j) {
        EXPECT_TRUE(forward) << i;
      } else {
        EXPECT_NE(forward, backward) << i << "-" << j;
      }
    }
  }
  // As Box2D orders them: the richer shape first.
  EXPECT_NE(collideFunction(ShapeType::Capsule, ShapeType::Circle), nullptr);
  EXPECT_NE(collideFunction(ShapeType::Polygon, ShapeType::Capsule), nullptr);
  EXPECT_NE(collideFunction(ShapeType::Segment, ShapeType::Polygon), nullptr);
  EXPECT_NE(collideFunction(ShapeType::ChainSegment, ShapeType::Polygon), nullptr);
  EXPECT_EQ(collideFunction(ShapeType::Circle, ShapeType::ChainSegment), nullptr);
}

TEST(CollideTable, BoundariesNeverCollideWithEachOther) {
  const ShapeType boundaries[] = {ShapeType::Segment, ShapeType::ChainSegment};
  for (ShapeType a : boundaries) {
    for (ShapeType b : boundaries) EXPECT_FALSE(shapesCanCollide(a, b));
    EXPECT_TRUE(shapesCanCollide(a, ShapeType::Circle));
    EXPECT_TRUE(shapesCanCollide(ShapeType::Polygon, a));
  }
  EXPECT_TRUE(shapesCanCollide(ShapeType::Capsule, ShapeType::Capsule));
  // Two crossing segments: the table's entry gives no points.
  const Shape s1 = Shape::makeSegment(Vec2(-1, 0), Vec2(1, 0));
  const Shape s2 = Shape::makeSegment(Vec2(0, -1), Vec2(0, 1));
  EXPECT_EQ(collide(s1, {}, s2, {}).pointCount, 0);
}

TEST(CollideTable, ReversedOrder_NegatesTheNormalAndSwapsAnchorsAndIds) {
  const Shape box = Shape::makePolygon(makeBox(1, Real(0.5)));
  const Shape capsule = Shape::makeCapsule(Vec2(-Real(0.5), 0), Vec2(Real(0.5), 0), Real(0.25));
  const Transform xfBox = makeTransform(1, 2, Real(0.2));
  const Transform xfCapsule = {xfBox.apply(Vec2(Real(0.1), Real(0.74))), xfBox.q};
  const Manifold forward = collideChecked(box, xfBox, capsule, xfCapsule);
  const Manifold backward = collideChecked(capsule, xfCapsule, box, xfBox);
  ASSERT_EQ(forward.pointCount, 2);
  ASSERT_EQ(backward.pointCount, 2);
  expectVecNear(backward.normal, -forward.normal, 0);
  for (int i = 0; i < 2; ++i) {
    expectVecNear(backward.points[i].point, forward.points[i].point, 0);
    EXPECT_EQ(backward.points[i].separation, forward.points[i].separation);
    EXPECT_EQ(backward.points[i].id,
              makeFeatureId(forward.points[i].id & 0xFF, forward.points[i].id >> 8));
  }
}

// ---- Circles with centres ----

TEST(CollideCircles, OffsetCentres_MeasureBetweenTheCentresInWorld) {
  const Shape a = Shape::makeCircle(Real(0.5), Vec2(1, 0));
  const Shape b = Shape::makeCircle(Real(0.25), Vec2(0, -1));
  // A turned a quarter: its centre is at (2, 3) + (0, 1); B's at (2, 5).
  const Transform xfA = makeTransform(2, 3, std::numbers::pi_v<Real> / 2);
  const Transform xfB = makeTransform(2, 6);
  // 1 apart, radii 0.75: a gap of 0.25, beyond the speculative distance.
  EXPECT_EQ(collideChecked(a, xfA, b, xfB).pointCount, 0);
  EXPECT_NEAR(separationOf(a, xfA, b, xfB), Real(0.25), kTolerance);
  const Transform closer = makeTransform(2, Real(5.5));
  const Manifold touching = collideChecked(a, xfA, b, closer);
  ASSERT_EQ(touching.pointCount, 1);
  expectVecNear(touching.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(touching.points[0].separation, Real(-0.25), kTolerance);
  // Surfaces at y = 4.5 (A) and 4.25 (B): midway 4.375.
  expectVecNear(touching.points[0].point, Vec2(2, Real(4.375)), kTolerance);
}

// ---- Capsules ----

TEST(CollideCapsuleAndCircle, FaceAndEndRegions) {
  const Shape capsule = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.25));
  const Shape circle = Shape::makeCircle(Real(0.5));
  Manifold m = collideChecked(capsule, {}, circle, makeTransform(Real(0.3), Real(0.7)));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.05), kTolerance);
  expectVecNear(m.points[0].point, Vec2(Real(0.3), Real(0.225)), kTolerance);
  m = collideChecked(capsule, {}, circle, makeTransform(Real(1.6), 0));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(1, 0), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.15), kTolerance);
  m = collideChecked(capsule, {}, circle, makeTransform(0, Real(0.76) + kSpeculativeDistance));
  EXPECT_EQ(m.pointCount, 0);
}

TEST(CollideCapsules, LyingAlongEachOther_GiveTwoPointsClippedToTheOverlap) {
  const Shape a = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.25));
  const Shape b = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.25));
  const Manifold m = collideChecked(a, {}, b, makeTransform(Real(0.5), Real(0.45)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, Real(-0.05), kTolerance);
    EXPECT_NEAR(m.points[i].point.y(), Real(0.225), kTolerance);
  }
  EXPECT_NEAR(std::min(m.points[0].point.x(), m.points[1].point.x()), Real(-0.5), kTolerance);
  EXPECT_NEAR(std::max(m.points[0].point.x(), m.points[1].point.x()), 1, kTolerance);
  EXPECT_NE(m.points[0].id, m.points[1].id);
}

TEST(CollideCapsules, CrossedAndEndToEnd_GiveOnePointAtTheClosestPoints) {
  const Shape a = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.25));
  const Shape upright = Shape::makeCapsule(Vec2(0, 0), Vec2(0, Real(1.7)), Real(0.25));
  Manifold m = collideChecked(a, {}, upright, makeTransform(Real(0.2), Real(0.3)));
  ASSERT_GE(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.2), kTolerance);
  expectVecNear(m.points[0].point, Vec2(Real(0.2), Real(0.15)), kTolerance);

  const Shape b = Shape::makeCapsule(Vec2(0, 0), Vec2(Real(1.6), 0), Real(0.25));
  m = collideChecked(a, {}, b, makeTransform(Real(1.4), 0));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(1, 0), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.1), kTolerance);
  EXPECT_EQ(m.points[0].id, makeFeatureId(1, 0));
  EXPECT_NEAR(separationOf(a, {}, b, makeTransform(Real(1.4), 0)), Real(-0.1), kTolerance);
}

TEST(CollidePolygonAndCapsule, CapsuleLyingOnABox_TwoPointsAtTheRoundedSurface) {
  const Shape box = Shape::makePolygon(makeBox(1, Real(0.5)));
  const Shape capsule = Shape::makeCapsule(Vec2(-Real(0.5), 0), Vec2(Real(0.5), 0), Real(0.25));
  const Transform xfBox = makeTransform(10, -20, Real(0.6));
  const Transform xfCapsule{xfBox.apply(Vec2(0, Real(0.7))), xfBox.q};
  const Manifold m = collideChecked(box, xfBox, capsule, xfCapsule, kFarTolerance);
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, xfBox.q.apply(Vec2(0, 1)), kTolerance);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, Real(-0.05), kFarTolerance);
    const Vec2 local = xfBox.applyInverse(m.points[i].point);
    EXPECT_NEAR(std::abs(local.x()), Real(0.5), kFarTolerance);
    EXPECT_NEAR(local.y(), Real(0.475), kFarTolerance);
  }
  // Standing on its end: one point under the lower cap.
  const Shape upright = Shape::makeCapsule(Vec2(0, 0), Vec2(0, Real(1.2)), Real(0.25));
  const Manifold end = collideChecked(box, {}, upright, makeTransform(Real(0.3), Real(0.76)));
  ASSERT_EQ(end.pointCount, 1);
  EXPECT_NEAR(end.points[0].separation, Real(0.01), kTolerance);
  expectVecNear(end.points[0].point, Vec2(Real(0.3), Real(0.505)), kTolerance);
}

TEST(CollidePolygonAndCapsule, RestingCapsuleIds_StableUnderTinyPerturbation) {
  const Shape box = Shape::makePolygon(makeBox(2, Real(0.5)));
  const Shape capsule = Shape::makeCapsule(Vec2(-Real(0.5), 0), Vec2(Real(0.5), 0), Real(0.25));
  const Manifold before = collideChecked(box, {}, capsule, makeTransform(Real(0.3), Real(0.746)));
  const Manifold after =
      collideChecked(box, {}, capsule, makeTransform(Real(0.3002), Real(0.7462), Real(1e-4)));
  ASSERT_EQ(before.pointCount, 2);
  ASSERT_EQ(after.pointCount, 2);
  EXPECT_EQ(before.points[0].id, after.points[0].id);
  EXPECT_EQ(before.points[1].id, after.points[1].id);
  EXPECT_NE(before.points[0].id, before.points[1].id);
  const Manifold lying =
      collideChecked(capsule, {}, capsule, makeTransform(Real(0.3), Real(0.496)));
  const Manifold moved =
      collideChecked(capsule, {}, capsule, makeTransform(Real(0.3002), Real(0.4962), Real(1e-4)));
  ASSERT_EQ(lying.pointCount, 2);
  ASSERT_EQ(moved.pointCount, 2);
  EXPECT_EQ(lying.points[0].id, moved.points[0].id);
  EXPECT_EQ(lying.points[1].id, moved.points[1].id);
}

// ---- Rounded polygons ----

TEST(CollideRoundedPolygons, RoundedBoxRestingOnABox_TwoPointsAtTheRoundedBottom) {
  const Shape ground = Shape::makePolygon(makeBox(5, Real(0.5)));
  const Shape box = roundedBox(Real(0.4), Real(0.4), Real(0.1));
  // Bottom of the rounded box at 0.5 - 0.005: centre at 0.495 + 0.5.
  const Manifold m = collideChecked(ground, {}, box, makeTransform(Real(0.7), Real(0.995)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, -kLinearSlop, kTolerance);
    EXPECT_NEAR(m.points[i].point.y(), Real(0.4975), kTolerance);
    EXPECT_NEAR(std::abs(m.points[i].point.x() - Real(0.7)), Real(0.4), kTolerance);
  }
  EXPECT_NEAR(separationOf(ground, {}, box, makeTransform(Real(0.7), Real(0.995))), -kLinearSlop,
              kTolerance);
}

TEST(CollideRoundedPolygons, CircleAtARoundedCorner_UsesTheCornerDirection) {
  const Shape box = roundedBox(1, 1, Real(0.2));
  const Shape circle = Shape::makeCircle(Real(0.3));
  const Vec2 diagonal = Vec2(1, 1).normalized();
  const Vec2 center = Vec2(1, 1) + Real(0.45) * diagonal;
  const Manifold m = collideChecked(box, {}, circle, makeTransform(center.x(), center.y()));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, diagonal, kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.05), kTolerance);
  // Box surface 0.2 and circle surface 0.15 out from the corner: midway 0.175.
  expectVecNear(m.points[0].point, Vec2(1, 1) + Real(0.175) * diagonal, kTolerance);
  EXPECT_NEAR(separationOf(circle, makeTransform(center.x(), center.y()), box, {}), Real(-0.05),
              kTolerance);
}

TEST(CollideRoundedPolygons, CornerToCorner_TrueGapBetweenTheRoundings) {
  const Shape a = roundedBox(Real(0.5), Real(0.5), Real(0.1));
  const Shape b = roundedBox(Real(0.5), Real(0.5), Real(0.05));
  // Core corners (0.5, 0.5) and B's (-0.5, -0.5) + (1.1, 1.1): 0.1 * sqrt(2) apart.
  const Transform xfB = makeTransform(Real(1.1), Real(1.1));
  const Real gap = Real(0.1 * std::sqrt(2.0)) - Real(0.15);
  const Manifold m = collideChecked(a, {}, b, xfB);
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(1, 1).normalized(), kTolerance);
  EXPECT_NEAR(m.points[0].separation, gap, kTolerance);
  EXPECT_NEAR(separationOf(a, {}, b, xfB), gap, kTolerance);
}

// ---- Segments (two-sided) ----

TEST(CollideSegment, CircleCapsuleAndBoxOnEitherSide) {
  const Shape segment = Shape::makeSegment(Vec2(-2, 0), Vec2(2, 0));
  const Shape circle = Shape::makeCircle(Real(0.5));
  Manifold m = collideChecked(segment, {}, circle, makeTransform(Real(0.5), Real(-0.49)));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, -1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.01), kTolerance);

  const Shape capsule = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.2));
  m = collideChecked(segment, {}, capsule, makeTransform(0, Real(0.19)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.01), kTolerance);
  EXPECT_NEAR(m.points[1].separation, Real(-0.01), kTolerance);

  const Shape box = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  m = collideChecked(segment, {}, box, makeTransform(Real(1.9), Real(0.495)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(std::max(m.points[0].point.x(), m.points[1].point.x()), 2, kTolerance);
  EXPECT_NEAR(m.points[0].separation, -kLinearSlop, kTolerance);
  m = collideChecked(segment, {}, box, makeTransform(0, Real(-0.495)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, -1), kTolerance);
}

// ---- Chain segments (one-sided, ghost vertices) ----

TEST(CollideChainSegment, CircleFromBehindOrOverTheNeighbour_HasNoContact) {
  const ChainBuild chain = flatChain(3, 1);
  ASSERT_EQ(chain.error, ShapeError::None);
  // Segments run right to left: segment 1 spans x in [1, 2].
  const Shape middle{chain.segments[1]};
  ASSERT_NEAR(middle.chainSegment().segment.point1.x(), 2, 0);
  const Shape circle = Shape::makeCircle(Real(0.5));
  Manifold m = collideChecked(middle, {}, circle, makeTransform(Real(1.5), Real(0.49)));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.01), kTolerance);
  // Centre below the line: one-sided, nothing.
  EXPECT_EQ(collideChecked(middle, {}, circle, makeTransform(Real(1.5), Real(-0.3))).pointCount, 0);
  // Over the next segment (x < 1): its contact, not this one's.
  EXPECT_EQ(collideChecked(middle, {}, circle, makeTransform(Real(0.9), Real(0.49))).pointCount, 0);
  // Exactly over the join at x = 1: one of the two segments only.
  const Shape next{chain.segments[2]};
  const int atJoin = collideChecked(middle, {}, circle, makeTransform(1, Real(0.49))).pointCount +
                     collideChecked(next, {}, circle, makeTransform(1, Real(0.49))).pointCount;
  EXPECT_EQ(atJoin, 1);
}

TEST(CollideChainSegment, BoxBelowTheChain_HasNoContact) {
  const ChainBuild chain = flatChain(3, 1);
  const Shape box = Shape::makePolygon(makeBox(Real(0.4), Real(0.4)));
  for (const ChainSegment& segment : chain.segments) {
    EXPECT_EQ(
        collideChecked(Shape{segment}, {}, box, makeTransform(Real(1.5), Real(-0.39))).pointCount,
        0);
    EXPECT_EQ(
        collideChecked(Shape{segment}, {}, box, makeTransform(Real(1.5), Real(-0.41))).pointCount,
        0);
  }
}

// The ghost-collision test: a box (a capsule, a rounded box) sliding along 100 segments
// of 0.5 m, resting 5 mm into them, tilted slightly either way. At every
// position, every segment either gives nothing or gives points whose normal
// is the face normal and whose separation is the resting depth, and the
// segments together always hold it up. Tolerance 1e-4 on both: the tilt
// moves the corners by 6e-5 m, and float positions up to 50 m resolve 4e-6 m,
// which over the capsule's 0.2 m radius turns a vertex normal by 2e-5.
TEST(CollideChainSegment, BoxAndCapsuleSlidingAlong100Segments_NeverCatchOnAJoin) {
  const Real spacing = Real(0.5);
  const ChainBuild chain = flatChain(100, spacing);
  ASSERT_EQ(chain.error, ShapeError::None);
  ASSERT_EQ(chain.segments.size(), 100u);
  const Real halfWidth = Real(0.3), halfHeight = Real(0.2), capsuleRadius = Real(0.2);
  const Shape box = Shape::makePolygon(makeBox(halfWidth, halfHeight));
  const Shape capsule = Shape::makeCapsule(Vec2(-halfWidth, 0), Vec2(halfWidth, 0), capsuleRadius);
  // Rounded: the same outline as the box, its core smaller by the radius.
  const Shape rounded = roundedBox(halfWidth - Real(0.05), halfHeight - Real(0.05), Real(0.05));
  int manifolds = 0;
  for (const Shape* body : {&box, &capsule, &rounded}) {
    for (Real tilt : {Real(0), Real(2e-4), Real(-2e-4)}) {
      for (int step = 0; step <= 4900; ++step) {
        const Real x = Real(0.3) + Real(0.01) * Real(step);  // across every join
        const Transform xf = makeTransform(x, halfHeight - kLinearSlop, tilt);
        int points = 0;
        Real deepest = 1;
        for (const ChainSegment& segment : chain.segments) {
          const Manifold m = collideChecked(Shape{segment}, {}, *body, xf);
          if (m.pointCount == 0) continue;
          ++manifolds;
          expectVecNear(m.normal, Vec2(0, 1), Real(1e-4));
          for (int i = 0; i < m.pointCount; ++i) {
            EXPECT_NEAR(m.points[i].separation, -kLinearSlop, Real(1e-4)) << "x = " << x;
            deepest = std::min(deepest, m.points[i].separation);
          }
          points += m.pointCount;
        }
        ASSERT_GE(points, 2) << "x = " << x;
        EXPECT_NEAR(deepest, -kLinearSlop, Real(1e-4)) << "x = " << x;
      }
    }
  }
  EXPECT_GT(manifolds, 9 * 4900);
}

// A circle rolling along the same chain, 5 mm into it: at every position
// exactly one segment gives one point (a join's vertex region belongs to
// one side only), straight up within 1e-4, 5 mm deep within 1e-4.
TEST(CollideChainSegment, CircleRollingAlong100Segments_AlwaysOnePointStraightUp) {
  const ChainBuild chain = flatChain(100, Real(0.5));
  const Shape circle = Shape::makeCircle(Real(0.25));
  for (int step = 0; step <= 4950; ++step) {
    const Real x = Real(0.25) + Real(0.01) * Real(step);
    const Transform xf = makeTransform(x, Real(0.25) - kLinearSlop);
    int points = 0;
    for (const ChainSegment& segment : chain.segments) {
      const Manifold m = collideChecked(Shape{segment}, {}, circle, xf);
      if (m.pointCount == 0) continue;
      points += m.pointCount;
      expectVecNear(m.normal, Vec2(0, 1), Real(1e-4));
      EXPECT_NEAR(m.points[0].separation, -kLinearSlop, Real(1e-4));
    }
    EXPECT_EQ(points, 1) << "x = " << x;
  }
}

// Chains along arcs of radius 20 m, 0.6 degrees per segment (convex joins
// on a hill, concave in a bowl): a box sliding along, sunk 5 mm at its
// middle (hill) or corners (bowl), only ever gets normals within 0.03 rad
// of the radial direction under it (it spans 1.7 degrees of arc), never a
// side push from a join, and is always held.
TEST(CollideChainSegment, BoxSlidingOverAHillAndThroughABowl_NormalsStayRadial) {
  constexpr double kRadius = 20, kStep = 0.6 * std::numbers::pi / 180;
  const Real halfWidth = Real(0.3), halfHeight = Real(0.2);
  const Shape box = Shape::makePolygon(makeBox(halfWidth, halfHeight));
  for (const bool hill : {true, false}) {
    SCOPED_TRACE(hill ? "hill" : "bowl");
    // Hill: centre below, points from 60 to 120 degrees (right to left on
    // top: the right side is outwards). Bowl: centre above, from -60 to
    // -120 degrees (right to left along the bottom: the right side is in).
    const Vec2 center(0, Real(hill ? -kRadius : kRadius));
    std::vector<Vec2> points;
    for (int i = 0; i <= 100; ++i) {
      const double angle =
          hill ? std::numbers::pi / 3 + i * kStep : -std::numbers::pi / 3 - i * kStep;
      points.push_back(center +
                       Vec2(Real(kRadius * std::cos(angle)), Real(kRadius * std::sin(angle))));
    }
    const ChainBuild chain = buildChain(points, false);
    ASSERT_EQ(chain.error, ShapeError::None);
    for (int k = 10; k <= 90; ++k) {
      const double angle = hill ? std::numbers::pi / 3 + (k + 0.37) * kStep
                                : -std::numbers::pi / 3 - (k + 0.37) * kStep;
      const Vec2 radial(Real(std::cos(angle)), Real(std::sin(angle)));
      const Vec2 inward = hill ? radial : Vec2(-radial);  // the chain's normal under the box
      // Corners of the flat bottom rise off a hill by w^2 / 2R and dip into a bowl.
      const double sag = double(halfWidth) * halfWidth / (2 * kRadius);
      const double bottom = hill ? kRadius - kLinearSlop : kRadius - sag - kLinearSlop;
      const double distance = hill ? bottom + halfHeight : bottom - halfHeight;
      const Vec2 position = center + Real(distance) * radial;
      const Transform xf{position, Rot::fromAngle(Real(std::atan2(inward.y(), inward.x()) -
                                                       std::numbers::pi / 2))};
      int held = 0;
      for (const ChainSegment& segment : chain.segments) {
        const Manifold m = collideChecked(Shape{segment}, {}, box, xf, kFarTolerance);
        if (m.pointCount == 0) continue;
        held += m.pointCount;
        EXPECT_GT(m.normal.dot(inward), std::cos(0.03)) << "k = " << k;
      }
      EXPECT_GE(held, 1) << "k = " << k;
    }
  }
}

// A box pushed sideways into a join while sunk 5 mm: the next segment's
// normal is still up, never the box's side face (which a two-sided segment
// would report, stopping the box).
TEST(CollideChainSegment, BoxLeadingFaceAtAJoin_IsSnappedToTheFaceNormal) {
  const ChainBuild chain = flatChain(3, 1);
  const Shape box = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  // Segment 1 spans [1, 2]; the box's right face is 1 mm past x = 1.
  const Shape middle{chain.segments[1]};
  const Transform xf = makeTransform(Real(0.501), Real(0.495));
  const Manifold m = collideChecked(middle, {}, box, xf);
  ASSERT_GE(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  // A plain segment there picks the box's side: the ghost collision.
  const Shape plain = Shape::makeSegment(Vec2(2, 0), Vec2(1, 0));
  const Manifold ghost = collideChecked(plain, {}, box, xf);
  ASSERT_GE(ghost.pointCount, 1);
  EXPECT_LT(ghost.normal.y(), Real(0.5));
}

// A hill: the chain turns away at the top (convex join at (0, 1)). A box
// corner 1 cm from the top vertex, 80 degrees up (between the two slopes'
// normals, at 63.4 and 116.6 degrees), gets exactly one vertex contact,
// along the true direction.
TEST(CollideChainSegment, ConvexJoin_VertexContactFromExactlyOneSegment) {
  const std::vector<Vec2> points = {Vec2(4, -1), Vec2(2, 0), Vec2(0, 1), Vec2(-2, 0), Vec2(-4, -1)};
  const ChainBuild chain = buildChain(points, false);
  ASSERT_EQ(chain.error, ShapeError::None);
  ASSERT_EQ(chain.segments.size(), 2u);
  const Shape box = Shape::makePolygon(makeBox(Real(0.3), Real(0.3)));
  // The box's bottom-left corner (its lowest, turned 0.5 rad) at the spot.
  const Rot q = Rot::fromAngle(Real(0.5));
  const Vec2 direction = Rot::fromAngle(Real(80 * std::numbers::pi / 180)).apply(Vec2(1, 0));
  const Vec2 spot = Vec2(0, 1) + Real(0.01) * direction;
  const Transform xf{spot - q.apply(Vec2(-Real(0.3), -Real(0.3))), q};
  int count = 0;
  for (const ChainSegment& segment : chain.segments) {
    const Manifold m = collideChecked(Shape{segment}, {}, box, xf);
    if (m.pointCount == 0) continue;
    ++count;
    ASSERT_EQ(m.pointCount, 1);
    expectVecNear(m.normal, direction, Real(1e-3));
    EXPECT_NEAR(m.points[0].separation, Real(0.01), Real(1e-5));
  }
  EXPECT_EQ(count, 1);
}

// A valley: a box resting in a V of two 45-degree slopes touches both faces
// with their own normals and never the bottom vertex.
TEST(CollideChainSegment, ConcaveJoin_BothFacesAndNoVertexContact) {
  const std::vector<Vec2> points = {Vec2(3, 3), Vec2(2, 2), Vec2(0, 0), Vec2(-2, 2), Vec2(-3, 3)};
  const ChainBuild chain = buildChain(points, false);
  ASSERT_EQ(chain.error, ShapeError::None);
  const Shape box = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  // Turned 45 degrees: its sides lie on the slopes, sunk 5 mm into each.
  const Real half = Real(0.5);
  const Transform xf =
      makeTransform(0, (half - kLinearSlop) * std::sqrt(Real(2)), std::numbers::pi_v<Real> / 4);
  for (const ChainSegment& segment : chain.segments) {
    const Manifold m = collideChecked(Shape{segment}, {}, box, xf);
    ASSERT_EQ(m.pointCount, 2);
    const Vec2 faceNormal = rightPerp(segment.segment.point2 - segment.segment.point1).normalized();
    expectVecNear(m.normal, faceNormal, kTolerance);
    EXPECT_NEAR(m.points[0].separation, -kLinearSlop, kTolerance);
    EXPECT_NEAR(m.points[1].separation, -kLinearSlop, kTolerance);
  }
}

// An anticlockwise loop collides on its outside, a clockwise one (a
// container) on its inside: a box 5 mm into the bottom edge from either side.
TEST(CollideChainSegment, Loops_AnticlockwiseHoldsOutsideClockwiseHoldsInside) {
  const std::vector<Vec2> square = {Vec2(0, 0), Vec2(4, 0), Vec2(4, 4), Vec2(0, 4)};
  const std::vector<Vec2> reversed(square.rbegin(), square.rend());
  const Shape box = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  const Transform inside = makeTransform(2, Real(0.495));
  const Transform outside = makeTransform(2, Real(-0.495));
  for (const bool anticlockwise : {true, false}) {
    SCOPED_TRACE(anticlockwise ? "anticlockwise" : "clockwise");
    const ChainBuild loop = buildChain(anticlockwise ? square : reversed, true);
    ASSERT_EQ(loop.error, ShapeError::None);
    int insidePoints = 0, outsidePoints = 0;
    for (const ChainSegment& segment : loop.segments) {
      const Manifold in = collideChecked(Shape{segment}, {}, box, inside);
      const Manifold out = collideChecked(Shape{segment}, {}, box, outside);
      insidePoints += in.pointCount;
      outsidePoints += out.pointCount;
      if (in.pointCount > 0) expectVecNear(in.normal, Vec2(0, 1), kTolerance);
      if (out.pointCount > 0) expectVecNear(out.normal, Vec2(0, -1), kTolerance);
    }
    EXPECT_EQ(insidePoints, anticlockwise ? 0 : 2);
    EXPECT_EQ(outsidePoints, anticlockwise ? 2 : 0);
  }
}

TEST(CollideChainSegment, CapsuleFromBehind_HasNoContactAndFromTheFrontTwoPoints) {
  const ChainBuild chain = flatChain(3, 1);
  const Shape middle{chain.segments[1]};
  const Shape capsule = Shape::makeCapsule(Vec2(-Real(0.3), 0), Vec2(Real(0.3), 0), Real(0.2));
  EXPECT_EQ(collideChecked(middle, {}, capsule, makeTransform(Real(1.5), Real(-0.19))).pointCount,
            0);
  const Manifold m = collideChecked(middle, {}, capsule, makeTransform(Real(1.5), Real(0.19)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.01), kTolerance);
}

TEST(CollideChainSegment, RestingBoxIds_StableUnderTinyPerturbation) {
  const ChainBuild chain = flatChain(3, 1);
  const Shape middle{chain.segments[1]};
  const Shape box = Shape::makePolygon(makeBox(Real(0.3), Real(0.3)));
  const Manifold before = collideChecked(middle, {}, box, makeTransform(Real(1.5), Real(0.296)));
  const Manifold after =
      collideChecked(middle, {}, box, makeTransform(Real(1.5002), Real(0.2962), Real(1e-4)));
  ASSERT_EQ(before.pointCount, 2);
  ASSERT_EQ(after.pointCount, 2);
  EXPECT_EQ(before.points[0].id, after.points[0].id);
  EXPECT_EQ(before.points[1].id, after.points[1].id);
}

// ---- Separation ----

TEST(ComputeSeparation, EveryPairMatchesItsClosedForm) {
  const Shape capsule = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.25));
  const Shape circle = Shape::makeCircle(Real(0.5), Vec2(Real(0.5), 0));
  const Shape segment = Shape::makeSegment(Vec2(-1, 0), Vec2(1, 0));
  const Shape box = Shape::makePolygon(makeBox(1, 1));
  const Shape rounded = roundedBox(1, 1, Real(0.1));
  const ChainSegment chainSegment{Vec2(2, 0), Segment{Vec2(1, 0), Vec2(-1, 0)}, Vec2(-2, 0), 0};
  const Shape chain{chainSegment};
  struct Case {
    const Shape* a;
    Transform xfA;
    const Shape* b;
    Transform xfB;
    Real expected;
  };
  const Case cases[] = {
      // Parallel capsules 1 apart: 1 - 0.5; crossed: depth 0.5 + 0.25 minus the gap 0.
      {&capsule, {}, &capsule, makeTransform(Real(0.5), 1), Real(0.5)},
      // Crossed: the SAT depth of the cores, 0.7 along y, minus 0.5.
      {&capsule, {}, &capsule, makeTransform(0, Real(0.3), Real(1.5707964)), Real(-1.2)},
      // End to end along one line.
      {&capsule, {}, &capsule, makeTransform(3, 0), Real(0.5)},
      {&capsule, {}, &circle, makeTransform(0, 2), Real(2) - Real(0.75)},
      {&circle, makeTransform(0, 2), &capsule, {}, Real(2) - Real(0.75)},
      {&segment, {}, &circle, makeTransform(Real(2.5), 0), Real(1.5)},
      {&segment, {}, &segment, makeTransform(3, 0), Real(1)},
      {&segment, {}, &segment, makeTransform(0, 2), Real(2)},
      {&box, {}, &capsule, makeTransform(0, Real(1.5)), Real(0.25)},
      {&box, {}, &capsule, makeTransform(0, Real(1.1)), Real(-0.15)},
      {&rounded, {}, &box, makeTransform(Real(2.5), 0), Real(0.4)},
      {&rounded,
       {},
       &rounded,
       makeTransform(Real(2.3), Real(2.3)),
       Real(0.3 * std::sqrt(2.0)) - Real(0.2)},
      {&chain, {}, &circle, makeTransform(0, 1), Real(0.5)},
      // Two-sided for continuous collision: the same from behind.
      {&chain, {}, &circle, makeTransform(0, -1), Real(0.5)},
      {&chain, {}, &box, makeTransform(0, Real(-1.2)), Real(0.2)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(describePair(*c.a, *c.b));
    EXPECT_NEAR(separationOf(*c.a, c.xfA, *c.b, c.xfB), c.expected, kTolerance);
    EXPECT_NEAR(separationOf(*c.b, c.xfB, *c.a, c.xfA), c.expected, kTolerance);
  }
}

TEST(ComputeSeparation, CrossingSegmentsAndCapsules_AreNegative) {
  const Shape segment = Shape::makeSegment(Vec2(-1, 0), Vec2(1, 0));
  const Transform across = makeTransform(Real(0.2), Real(0.1), std::numbers::pi_v<Real> / 2);
  // The upright one spans y in [-0.9, 1.1] at x = 0.2: the least push apart
  // is 0.8 along x (1 - 0.2, the first one's right end past the second).
  EXPECT_NEAR(separationOf(segment, {}, segment, across), Real(-0.8), kTolerance);
  const Shape capsule = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.25));
  EXPECT_LT(separationOf(capsule, {}, capsule, across), Real(-0.8));
}

// ---- Every pair, swept ----

// B circles A at growing distance, turning. For every pair the manifold is
// well formed; where the shapes are apart by less than the speculative
// distance (two solids) there are points, and no point claims a larger gap
// than the true one by more than a linear slop (the capsules' two-point
// clip allows that much).
TEST(CollideEveryPair, SweptAround_AgreesWithComputeSeparation) {
  const Shape circle = Shape::makeCircle(Real(0.3), Vec2(Real(0.1), 0));
  const Shape capsule =
      Shape::makeCapsule(Vec2(-Real(0.4), 0), Vec2(Real(0.3), Real(0.1)), Real(0.2));
  const Shape segment = Shape::makeSegment(Vec2(-Real(0.5), 0), Vec2(Real(0.5), Real(0.2)));
  const Shape box = Shape::makePolygon(makeBox(Real(0.5), Real(0.3)));
  const Shape rounded = roundedBox(Real(0.3), Real(0.2), Real(0.1));
  const Shape hexagon = Shape::makePolygon(makeRegularPolygon(6, Real(0.4)));
  const ChainSegment chainSegment{Vec2(2, -1), Segment{Vec2(1, 0), Vec2(-1, 0)}, Vec2(-2, -1), 0};
  const Shape chain{chainSegment};
  const Shape* shapes[] = {&circle, &capsule, &segment, &box, &rounded, &hexagon, &chain};
  int checked = 0;
  for (const Shape* a : shapes) {
    for (const Shape* b : shapes) {
      if (!shapesCanCollide(a->type(), b->type())) continue;
      SCOPED_TRACE(describePair(*a, *b));
      for (int step = 0; step < 600; ++step) {
        const Real angle = Real(0.173) * Real(step);
        const Real distance = Real(0.0025) * Real(step);
        const Transform xfA = makeTransform(-3, 4, Real(0.31) * Real(step));
        const Transform xfB =
            makeTransform(Real(-3) + distance * std::cos(angle), 4 + distance * std::sin(angle),
                          Real(-0.17) * Real(step));
        const Manifold m = collideChecked(*a, xfA, *b, xfB);
        const Real separation = separationOf(*a, xfA, *b, xfB);
        const bool oneSided =
            a->type() == ShapeType::ChainSegment || b->type() == ShapeType::ChainSegment;
        if (!oneSided && separation < kSpeculativeDistance - Real(1e-3)) {
          EXPECT_GT(m.pointCount, 0) << "step " << step << " separation " << separation;
        }
        if (m.pointCount > 0 && separation > 0) {
          Real least = std::min(m.points[0].separation,
                                m.pointCount > 1 ? m.points[1].separation : m.points[0].separation);
          EXPECT_LE(least, separation + kLinearSlop + Real(1e-4)) << "step " << step;
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 20000);
}

}  // namespace
}  // namespace impulse
