#include "impulse/manifold.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "impulse/constants.h"
#include "impulse/shape.h"
#include "shape_pair.h"

namespace impulse {
namespace {

// Float round-off on unit-sized shapes near the origin.
constexpr Real kTolerance = Real(1e-5);
// Float round-off on shapes tens of metres from the origin (ulp ~ 4e-6 at 32 m).
constexpr Real kFarTolerance = Real(1e-4);
constexpr Real kQuarterTurn = std::numbers::pi_v<Real> / 4;

Transform makeTransform(Real x, Real y, Real angle = 0) {
  return {Vec2(x, y), Rot::fromAngle(angle)};
}

// g applied after xf: the same configuration seen from another frame.
Transform compose(const Transform& g, const Transform& xf) {
  return {g.apply(xf.p), {g.q.c * xf.q.c - g.q.s * xf.q.s, g.q.s * xf.q.c + g.q.c * xf.q.s}};
}

void expectVecNear(const Vec2& actual, const Vec2& expected, Real tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

// Invariants every manifold must satisfy whatever the configuration.
void expectWellFormed(const Manifold& m, const Transform& xfA, const Transform& xfB,
                      Real tolerance = kTolerance,
                      Real speculativeDistance = kSpeculativeDistance) {
  ASSERT_GE(m.pointCount, 0);
  ASSERT_LE(m.pointCount, 2);
  if (m.pointCount > 0) {
    EXPECT_TRUE(isFinite(m.normal));
    EXPECT_NEAR(m.normal.norm(), 1, kTolerance);
  }
  for (int i = 0; i < m.pointCount; ++i) {
    const ManifoldPoint& mp = m.points[i];
    EXPECT_TRUE(isFinite(mp.point));
    EXPECT_TRUE(isFinite(mp.separation));
    EXPECT_LT(mp.separation, speculativeDistance);
    expectVecNear(mp.anchorA, mp.point - xfA.p, tolerance);
    expectVecNear(mp.anchorB, mp.point - xfB.p, tolerance);
    EXPECT_EQ(mp.normalImpulse, 0);
    EXPECT_EQ(mp.tangentImpulse, 0);
  }
}

// The table's function for the pair in this order, checked well formed.
Manifold collideChecked(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                        Real speculativeDistance = kSpeculativeDistance) {
  CollideFunction function = collideFunction(a.type(), b.type());
  if (function == nullptr) {
    ADD_FAILURE() << "no collide function for this pair";
    return {};
  }
  Manifold m = function(refOf(a).geometry, xfA, refOf(b).geometry, xfB, speculativeDistance);
  expectWellFormed(m, xfA, xfB, kTolerance, speculativeDistance);
  return m;
}

Real separationOf(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB) {
  return computeSeparation(refOf(a), xfA, refOf(b), xfB);
}

const Shape kGround = Shape::makePolygon(makeBox(5, Real(0.5)));
const Shape kUnitBox = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));

// ---- Circles ----

TEST(CollideCircles, SeparatedBeyondSpeculativeDistance_HasNoPoints) {
  Shape a = Shape::makeCircle(Real(0.5));
  Shape b = Shape::makeCircle(Real(0.5));
  Manifold m =
      collideChecked(a, makeTransform(0, 0), b, makeTransform(1 + 2 * kSpeculativeDistance, 0));
  EXPECT_EQ(m.pointCount, 0);
}

TEST(CollideCircles, WithinSpeculativeDistance_GivesOnePointWithThePositiveGap) {
  Shape a = Shape::makeCircle(Real(0.5));
  Shape b = Shape::makeCircle(Real(0.5));
  Real gap = Real(0.5) * kSpeculativeDistance;
  Manifold m = collideChecked(a, makeTransform(0, 0), b, makeTransform(0, 1 + gap));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, gap, kTolerance);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  expectVecNear(m.points[0].point, Vec2(0, Real(0.5) + gap / 2), kTolerance);
}

TEST(CollideCircles, Touching_GivesZeroSeparation) {
  Shape a = Shape::makeCircle(1);
  Shape b = Shape::makeCircle(Real(0.25));
  Manifold m = collideChecked(a, makeTransform(0, 0), b, makeTransform(Real(-1.25), 0));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, 0, kTolerance);
  expectVecNear(m.normal, Vec2(-1, 0), kTolerance);
  expectVecNear(m.points[0].point, Vec2(-1, 0), kTolerance);
}

TEST(CollideCircles, Overlapping_GivesNormalFromAToBDepthAndMidpoint) {
  Shape a = Shape::makeCircle(1);
  Shape b = Shape::makeCircle(Real(0.5));
  Vec2 direction(Real(0.6), Real(0.8));
  Transform xfA = makeTransform(2, 3, Real(0.4));
  Transform xfB = makeTransform(2 + Real(1.2) * direction.x(), 3 + Real(1.2) * direction.y(), -1);
  Manifold m = collideChecked(a, xfA, b, xfB);
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, direction, kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.3), kTolerance);
  // Surfaces at 1.0 (A) and 0.7 (B) from A's centre: midway at 0.85.
  expectVecNear(m.points[0].point, xfA.p + Real(0.85) * direction, kTolerance);
}

TEST(CollideCircles, Concentric_GivesFiniteUnitNormalAndFullDepth) {
  Shape a = Shape::makeCircle(Real(0.5));
  Shape b = Shape::makeCircle(Real(0.3));
  Manifold m = collideChecked(a, makeTransform(1, 1), b, makeTransform(1, 1));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, Real(-0.8), kTolerance);
}

// ---- Polygon and circle ----

TEST(CollidePolygonAndCircle, SeparatedBeyondSpeculativeDistance_HasNoPoints) {
  Shape box = Shape::makePolygon(makeBox(1, 1));
  Shape circle = Shape::makeCircle(Real(0.5));
  Manifold m = collideChecked(box, makeTransform(0, 0), circle,
                              makeTransform(0, Real(1.5) + 2 * kSpeculativeDistance));
  EXPECT_EQ(m.pointCount, 0);
  // Beyond a vertex too: the centre is 0.5 from vertex (1, 1), a gap of 0.05,
  // although the top face alone would report an overlap of 0.05.
  Shape smaller = Shape::makeCircle(Real(0.45));
  m = collideChecked(box, makeTransform(0, 0), smaller, makeTransform(Real(1.3), Real(1.4)));
  EXPECT_EQ(m.pointCount, 0);
}

TEST(CollidePolygonAndCircle, WithinSpeculativeDistanceOfFace_GivesPositiveSeparation) {
  Shape box = Shape::makePolygon(makeBox(1, 1));
  Shape circle = Shape::makeCircle(Real(0.5));
  Manifold m =
      collideChecked(box, makeTransform(0, 0), circle, makeTransform(Real(0.2), Real(1.51)));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, Real(0.01), kTolerance);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  expectVecNear(m.points[0].point, Vec2(Real(0.2), Real(1.005)), kTolerance);
}

TEST(CollidePolygonAndCircle, TouchingFace_GivesZeroSeparation) {
  Shape box = Shape::makePolygon(makeBox(1, 1));
  Shape circle = Shape::makeCircle(Real(0.5));
  Manifold m =
      collideChecked(box, makeTransform(0, 0), circle, makeTransform(Real(1.5), Real(-0.4)));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, 0, kTolerance);
  expectVecNear(m.normal, Vec2(1, 0), kTolerance);
  expectVecNear(m.points[0].point, Vec2(1, Real(-0.4)), kTolerance);
}

TEST(CollidePolygonAndCircle, OverlappingFace_UsesFaceNormal) {
  Shape box = Shape::makePolygon(makeBox(1, 1));
  Shape circle = Shape::makeCircle(Real(0.5));
  Manifold m =
      collideChecked(box, makeTransform(0, 0), circle, makeTransform(Real(0.3), Real(1.4)));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.1), kTolerance);
  // Face at y = 1, deepest circle point at y = 0.9.
  expectVecNear(m.points[0].point, Vec2(Real(0.3), Real(0.95)), kTolerance);
}

TEST(CollidePolygonAndCircle, NearVertex_UsesDirectionFromVertexToCentre) {
  Shape box = Shape::makePolygon(makeBox(1, 1));
  Shape circle = Shape::makeCircle(Real(0.6));
  // The centre is 0.5 from vertex (1, 1), beyond the end of the top face and
  // then of the right face. The midpoint lies between the vertex and the
  // deepest circle point, 0.1 inside the box.
  for (const Vec2& direction : {Vec2(Real(0.6), Real(0.8)), Vec2(Real(0.8), Real(0.6))}) {
    Vec2 centre = Vec2(1, 1) + Real(0.5) * direction;
    Manifold m =
        collideChecked(box, makeTransform(0, 0), circle, makeTransform(centre.x(), centre.y()));
    ASSERT_EQ(m.pointCount, 1);
    expectVecNear(m.normal, direction, kTolerance);
    EXPECT_NEAR(m.points[0].separation, Real(-0.1), kTolerance);
    expectVecNear(m.points[0].point, Vec2(1, 1) - Real(0.05) * direction, kTolerance);
  }
}

TEST(CollidePolygonAndCircle, CentreInside_PushesOutThroughNearestFace) {
  Shape box = Shape::makePolygon(makeBox(2, 1));
  Shape circle = Shape::makeCircle(Real(0.25));
  Manifold m =
      collideChecked(box, makeTransform(0, 0), circle, makeTransform(Real(0.5), Real(0.8)));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.45), kTolerance);
  // Face at y = 1, deepest circle point at y = 0.55.
  expectVecNear(m.points[0].point, Vec2(Real(0.5), Real(0.775)), kTolerance);
}

TEST(CollidePolygonAndCircle, CentreOnVertexOrCentroid_GivesFiniteFaceNormal) {
  Shape box = Shape::makePolygon(makeBox(1, 1));
  Shape circle = Shape::makeCircle(Real(0.5));
  for (const Vec2& centre : {Vec2(1, 1), Vec2(-1, 1), Vec2(0, 0)}) {
    Manifold m =
        collideChecked(box, makeTransform(0, 0), circle, makeTransform(centre.x(), centre.y()));
    ASSERT_EQ(m.pointCount, 1);
    Real faceDepth = centre.isZero() ? 1 : 0;
    EXPECT_NEAR(m.points[0].separation, -faceDepth - Real(0.5), kTolerance);
  }
}

// ---- Polygons ----

TEST(CollidePolygons, SeparatedBeyondSpeculativeDistance_HasNoPoints) {
  Manifold m = collideChecked(kGround, makeTransform(0, 0), kUnitBox,
                              makeTransform(0, 1 + 2 * kSpeculativeDistance));
  EXPECT_EQ(m.pointCount, 0);
}

TEST(CollidePolygons, WithinSpeculativeDistance_GivesTwoPointsWithPositiveGap) {
  Manifold m = collideChecked(kGround, makeTransform(0, 0), kUnitBox, makeTransform(1, Real(1.01)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, Real(0.01), kTolerance);
  }
}

TEST(CollidePolygons, BoxRestingFlatOnBox_GivesTwoPointsUnderItsCorners) {
  Manifold m = collideChecked(kGround, makeTransform(0, 0), kUnitBox, makeTransform(1, Real(0.99)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  std::vector<Real> xs;
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, Real(-0.01), kTolerance);
    // Ground top at 0.5, box bottom at 0.49.
    EXPECT_NEAR(m.points[i].point.y(), Real(0.495), kTolerance);
    xs.push_back(m.points[i].point.x());
  }
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], Real(0.5), kTolerance);
  EXPECT_NEAR(xs[1], Real(1.5), kTolerance);
  EXPECT_NE(m.points[0].id, m.points[1].id);
}

TEST(CollidePolygons, HexagonRestingOnBox_GivesTwoPointsAtItsBottomVertices) {
  Shape hexagon = Shape::makePolygon(makeRegularPolygon(6, 1));
  Real apothem = std::sqrt(Real(3)) / 2;
  Manifold m = collideChecked(kGround, makeTransform(0, 0), hexagon,
                              makeTransform(Real(-2), Real(0.5) + apothem - Real(0.02)));
  ASSERT_EQ(m.pointCount, 2);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  Real xMin = std::min(m.points[0].point.x(), m.points[1].point.x());
  Real xMax = std::max(m.points[0].point.x(), m.points[1].point.x());
  EXPECT_NEAR(xMin, Real(-2.5), kTolerance);
  EXPECT_NEAR(xMax, Real(-1.5), kTolerance);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, Real(-0.02), kTolerance);
  }
}

TEST(CollidePolygons, BoxCornerDownAt45Degrees_GivesOnePointUnderTheCorner) {
  Real halfDiagonal = Real(0.5) * std::sqrt(Real(2));
  Manifold m =
      collideChecked(kGround, makeTransform(0, 0), kUnitBox,
                     makeTransform(Real(0.3), Real(0.5) + halfDiagonal - Real(0.01), kQuarterTurn));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, 1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.01), kTolerance);
  expectVecNear(m.points[0].point, Vec2(Real(0.3), Real(0.495)), kTolerance);
}

TEST(CollidePolygons, CornerOfAOnFaceOfB_FlipsNormalToPointFromAToB) {
  // A's corner (vertex 0 once turned 45 degrees) pokes into B's top face, so
  // B's face is the reference.
  Real halfDiagonal = Real(0.5) * std::sqrt(Real(2));
  Manifold m = collideChecked(kUnitBox,
                              makeTransform(0, Real(0.5) + halfDiagonal - Real(0.01), kQuarterTurn),
                              kGround, makeTransform(0, 0));
  ASSERT_EQ(m.pointCount, 1);
  expectVecNear(m.normal, Vec2(0, -1), kTolerance);
  EXPECT_NEAR(m.points[0].separation, Real(-0.01), kTolerance);
  expectVecNear(m.points[0].point, Vec2(0, Real(0.495)), kTolerance);
  EXPECT_EQ(m.points[0].id >> 8, 0) << "A's feature is its corner vertex";
}

TEST(CollidePolygons, SmallBoxOverhangingEdge_ClipsToTheFaceEndInEitherOrder) {
  Shape big = Shape::makePolygon(makeBox(1, Real(0.5)));
  Shape small = Shape::makePolygon(makeBox(Real(0.25), Real(0.25)));
  Transform xfBig = makeTransform(0, 0);
  Transform xfSmall = makeTransform(1, Real(0.74));

  Manifold below = collideChecked(big, xfBig, small, xfSmall);
  Manifold above = collideChecked(small, xfSmall, big, xfBig);
  ASSERT_EQ(below.pointCount, 2);
  ASSERT_EQ(above.pointCount, 2);
  expectVecNear(below.normal, Vec2(0, 1), kTolerance);
  expectVecNear(above.normal, Vec2(0, -1), kTolerance);
  for (const Manifold& m : {below, above}) {
    Real xMin = std::min(m.points[0].point.x(), m.points[1].point.x());
    Real xMax = std::max(m.points[0].point.x(), m.points[1].point.x());
    // The small box spans [0.75, 1.25]; the big box's face ends at x = 1.
    EXPECT_NEAR(xMin, Real(0.75), kTolerance);
    EXPECT_NEAR(xMax, 1, kTolerance);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(m.points[i].separation, Real(-0.01), kTolerance);
      EXPECT_NEAR(m.points[i].point.y(), Real(0.495), kTolerance);
    }
  }
}

TEST(CollidePolygons, CornerPassingCornerWithinSpeculativeDistance_UsesTrueGapDirection) {
  // B's lower corner is (+-0.006, 0.008) from A's upper corner, beside either
  // end of A's top face.
  for (Real side : {Real(1), Real(-1)}) {
    Manifold m = collideChecked(kUnitBox, makeTransform(0, 0), kUnitBox,
                                makeTransform(side * Real(1.006), Real(1.008)));
    ASSERT_EQ(m.pointCount, 1);
    expectVecNear(m.normal, Vec2(side * Real(0.6), Real(0.8)), kTolerance);
    EXPECT_NEAR(m.points[0].separation, Real(0.01), kTolerance);
    expectVecNear(m.points[0].point, Vec2(side * Real(0.503), Real(0.504)), kTolerance);
  }
}

TEST(CollidePolygons, CornerTouchingCornerWithinRoundOff_GivesFiniteNormalAndZeroGap) {
  Manifold m = collideChecked(kUnitBox, makeTransform(0, 0), kUnitBox,
                              makeTransform(1 + Real(5e-7), 1 + Real(2e-7)));
  ASSERT_EQ(m.pointCount, 1);
  EXPECT_NEAR(m.points[0].separation, 0, kTolerance);
  expectVecNear(m.points[0].point, Vec2(Real(0.5), Real(0.5)), kTolerance);
}

TEST(CollidePolygons, IdenticalCoincidentBoxes_GiveFiniteNormalAndFullDepth) {
  Manifold m = collideChecked(kUnitBox, makeTransform(2, 2), kUnitBox, makeTransform(2, 2));
  ASSERT_EQ(m.pointCount, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].separation, -1, kTolerance);
  }
}

TEST(CollidePolygons, RestingBoxIds_StableUnderTinyPerturbation) {
  Manifold reference =
      collideChecked(kUnitBox, makeTransform(0, 0), kUnitBox, makeTransform(Real(0.2), Real(0.99)));
  ASSERT_EQ(reference.pointCount, 2);
  // Rotations this small shift the two faces' separations by less than the
  // reference face tolerance, so A's face must stay the reference.
  const Transform perturbed[] = {makeTransform(Real(0.2001), Real(0.9899)),
                                 makeTransform(Real(0.1999), Real(0.9901), Real(2e-4)),
                                 makeTransform(Real(0.2), Real(0.99), Real(-2e-4))};
  for (const Transform& xfB : perturbed) {
    Manifold m = collideChecked(kUnitBox, makeTransform(0, 0), kUnitBox, xfB);
    ASSERT_EQ(m.pointCount, 2);
    expectVecNear(m.normal, Vec2(0, 1), Real(1e-6));
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(m.points[i].id, reference.points[i].id);
    }
  }
}

// ---- Frames ----

TEST(CollideFunctions, RotatedTranslatedFrames_GiveTheAxisAlignedManifoldTransformed) {
  Shape circle = Shape::makeCircle(Real(0.4));
  Shape hexagon = Shape::makePolygon(makeRegularPolygon(6, Real(0.6)));
  struct Pair {
    const Shape& a;
    const Shape& b;
    Transform xfB;
  };
  const Pair pairs[] = {
      {circle, circle, makeTransform(Real(0.7), Real(0.2))},
      {kGround, circle, makeTransform(Real(1.3), Real(0.85))},
      {kUnitBox, circle, makeTransform(Real(0.8), Real(0.7))},
      {kGround, kUnitBox, makeTransform(Real(-0.4), Real(0.98), Real(0.1))},
      {kUnitBox, hexagon, makeTransform(Real(0.3), Real(0.95), Real(0.3))},
  };
  Transform frame = makeTransform(30, -12, Real(0.7));
  for (const Pair& pair : pairs) {
    Transform xfA = makeTransform(0, 0);
    Manifold aligned = collideChecked(pair.a, xfA, pair.b, pair.xfB);
    Transform movedA = compose(frame, xfA);
    Transform movedB = compose(frame, pair.xfB);
    CollideFunction function = collideFunction(pair.a.type(), pair.b.type());
    Manifold moved = function(refOf(pair.a).geometry, movedA, refOf(pair.b).geometry, movedB,
                              kSpeculativeDistance);
    expectWellFormed(moved, movedA, movedB, kFarTolerance);

    ASSERT_GT(aligned.pointCount, 0);
    ASSERT_EQ(moved.pointCount, aligned.pointCount);
    expectVecNear(moved.normal, frame.q.apply(aligned.normal), kTolerance);
    for (int i = 0; i < aligned.pointCount; ++i) {
      expectVecNear(moved.points[i].point, frame.apply(aligned.points[i].point), kFarTolerance);
      EXPECT_NEAR(moved.points[i].separation, aligned.points[i].separation, kFarTolerance);
      EXPECT_EQ(moved.points[i].id, aligned.points[i].id);
    }
  }
}

TEST(CollideFunctions, SweepAroundShapes_NeverGivesNaNAndNormalPointsFromAToB) {
  Shape circle = Shape::makeCircle(Real(0.3));
  Shape triangle = Shape::makePolygon(makeRegularPolygon(3, Real(0.5)));
  const Shape* shapes[] = {&circle, &kUnitBox, &triangle};
  for (const Shape* a : shapes) {
    for (const Shape* b : shapes) {
      if (a->type() == ShapeType::Circle && b->type() == ShapeType::Polygon) {
        continue;
      }
      for (int step = 0; step < 400; ++step) {
        Real angle = Real(0.173) * step;
        Real distance = Real(0.004) * step;
        Transform xfA = makeTransform(Real(-3), 4, Real(0.31) * step);
        Transform xfB = makeTransform(Real(-3) + distance * std::cos(angle),
                                      4 + distance * std::sin(angle), Real(-0.17) * step);
        Manifold m = collideChecked(*a, xfA, *b, xfB);
        // Apart, the normal separates the shapes, so it points from A's
        // centre towards B's.
        if (m.pointCount > 0 && separationOf(*a, xfA, *b, xfB) > 0) {
          EXPECT_GT(m.normal.dot(xfB.p - xfA.p), 0) << "step " << step;
        }
      }
    }
  }
}

TEST(CollideFunction, DispatchesEachOrderedPairAndLeavesCirclePolygonToTheCaller) {
  EXPECT_NE(collideFunction(ShapeType::Circle, ShapeType::Circle), nullptr);
  EXPECT_NE(collideFunction(ShapeType::Polygon, ShapeType::Circle), nullptr);
  EXPECT_NE(collideFunction(ShapeType::Polygon, ShapeType::Polygon), nullptr);
  EXPECT_EQ(collideFunction(ShapeType::Circle, ShapeType::Polygon), nullptr);
  // A type value decoded from bad input has no function rather than reading past the table.
  EXPECT_EQ(collideFunction(static_cast<ShapeType>(7), ShapeType::Circle), nullptr);

  Shape circle = Shape::makeCircle(Real(0.5));
  Transform xfA = makeTransform(0, 0);
  Transform xfB = makeTransform(Real(0.2), Real(0.9));
  Manifold viaTable = collideFunction(ShapeType::Polygon, ShapeType::Circle)(
      refOf(kUnitBox).geometry, xfA, refOf(circle).geometry, xfB, kSpeculativeDistance);
  Manifold direct = collidePolygonAndCircle(kUnitBox.polygon(), xfA, circle.circle(), xfB);
  ASSERT_EQ(viaTable.pointCount, 1);
  ASSERT_EQ(direct.pointCount, 1);
  expectVecNear(viaTable.points[0].point, direct.points[0].point, 0);
}

// The world grows a contact's speculative distance by how far its pair may
// close in a step (contact.cpp): every function keeps points out to the
// distance it is given, and only that far.
TEST(CollideFunctions, KeepPointsOutToTheSpeculativeDistanceGiven) {
  const Shape circle = Shape::makeCircle(Real(0.5));
  const Shape capsule = Shape::makeCapsule(Vec2(Real(-0.5), 0), Vec2(Real(0.5), 0), Real(0.25));
  const Shape segment = Shape::makeSegment(Vec2(-1, 0), Vec2(1, 0));
  // B straight above A, touching when its centre is `touching` above A's.
  struct Pair {
    const Shape& a;
    const Shape& b;
    Real touching;
  };
  const Pair pairs[] = {
      {circle, circle, 1},           {kUnitBox, circle, 1},
      {kUnitBox, kUnitBox, 1},       {capsule, circle, Real(0.75)},
      {capsule, capsule, Real(0.5)}, {kUnitBox, capsule, Real(0.75)},
      {segment, circle, Real(0.5)},  {segment, kUnitBox, Real(0.5)},
  };
  const Real gap = 3 * kSpeculativeDistance;
  const Transform xfA = makeTransform(0, 0);
  for (const Pair& pair : pairs) {
    const Transform xfB = makeTransform(0, pair.touching + gap);
    EXPECT_EQ(collideChecked(pair.a, xfA, pair.b, xfB).pointCount, 0);
    EXPECT_EQ(collideChecked(pair.a, xfA, pair.b, xfB, Real(0.9) * gap).pointCount, 0);
    const Manifold m = collideChecked(pair.a, xfA, pair.b, xfB, 2 * gap);
    ASSERT_GT(m.pointCount, 0);
    expectVecNear(m.normal, Vec2(0, 1), kTolerance);
    for (int i = 0; i < m.pointCount; ++i) EXPECT_NEAR(m.points[i].separation, gap, kTolerance);
  }
}

// ---- computeSeparation ----

TEST(ComputeSeparation, Circles_ExactGapWhenApartAndDepthWhenOverlapping) {
  Shape a = Shape::makeCircle(Real(0.5));
  Shape b = Shape::makeCircle(Real(0.25));
  EXPECT_NEAR(separationOf(a, makeTransform(0, 0), b, makeTransform(3, 4)), Real(4.25), kTolerance);
  EXPECT_NEAR(separationOf(a, makeTransform(0, 0), b, makeTransform(Real(0.6), 0)), Real(-0.15),
              kTolerance);
  EXPECT_NEAR(separationOf(a, makeTransform(1, 1), b, makeTransform(1, 1)), Real(-0.75),
              kTolerance);
}

TEST(ComputeSeparation, PolygonAndCircle_ExactInBothOrders) {
  Shape box = Shape::makePolygon(makeBox(1, 1));
  Shape circle = Shape::makeCircle(Real(0.5));
  struct Case {
    Vec2 centre;
    Real expected;
  };
  const Case cases[] = {
      {Vec2(3, 0), Real(1.5)},           // facing a face
      {Vec2(4, 5), Real(4.5)},           // beyond vertex (1, 1): gap (3, 4)
      {Vec2(Real(1.2), 0), Real(-0.3)},  // centre outside, overlapping
      {Vec2(Real(0.5), 0), Real(-1)},    // centre inside: 0.5 deep plus the radius
  };
  Transform xfBox = makeTransform(Real(-7), 2, Real(0.9));
  for (const Case& c : cases) {
    Transform xfCircle{xfBox.apply(c.centre), Rot::fromAngle(Real(0.3))};
    EXPECT_NEAR(separationOf(box, xfBox, circle, xfCircle), c.expected, kTolerance);
    EXPECT_NEAR(separationOf(circle, xfCircle, box, xfBox), c.expected, kTolerance);
  }
}

TEST(ComputeSeparation, Polygons_ExactGapWhenApartNegativeWhenOverlappingInBothOrders) {
  Real halfDiagonal = Real(0.5) * std::sqrt(Real(2));
  struct Case {
    Transform xfB;
    Real expected;
  };
  const Case cases[] = {
      {makeTransform(3, 0), 2},                          // face to face
      {makeTransform(Real(1.3), Real(1.4)), Real(0.5)},  // corner to corner: gap (0.3, 0.4)
      {makeTransform(Real(0.1), 1 + halfDiagonal - Real(0.4), kQuarterTurn),
       Real(0.1)},                                // corner to face
      {makeTransform(0, Real(0.8)), Real(-0.2)},  // overlapping by 0.2
  };
  for (const Case& c : cases) {
    EXPECT_NEAR(separationOf(kUnitBox, makeTransform(0, 0), kUnitBox, c.xfB), c.expected,
                kTolerance);
    EXPECT_NEAR(separationOf(kUnitBox, c.xfB, kUnitBox, makeTransform(0, 0)), c.expected,
                kTolerance);
  }
}

}  // namespace
}  // namespace impulse
