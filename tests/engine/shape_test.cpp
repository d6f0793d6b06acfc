#include "impulse/shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace impulse {
namespace {

constexpr double kPi = std::numbers::pi;

// Float keeps about 7 significant digits; the checks below allow a relative
// error of 1e-5 on quantities of order 1..100.
constexpr double kRelativeTolerance = 1e-5;

void expectRelativeNear(double actual, double expected) {
  EXPECT_NEAR(actual, expected, kRelativeTolerance * std::abs(expected));
}

void expectVecNear(const Vec2& actual, const Vec2& expected, double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

std::span<const Vec2> verticesOf(const Polygon& polygon) {
  return {polygon.vertices.data(), static_cast<std::size_t>(polygon.count)};
}

// Anticlockwise and convex, unit outward normals perpendicular to their edge,
// origin inside.
void expectWellFormed(const Polygon& polygon) {
  ASSERT_GE(polygon.count, kMinPolygonVertices);
  ASSERT_LE(polygon.count, kMaxPolygonVertices);
  for (int i = 0; i < polygon.count; ++i) {
    const Vec2& v0 = polygon.vertices[i];
    const Vec2& v1 = polygon.vertices[(i + 1) % polygon.count];
    const Vec2& v2 = polygon.vertices[(i + 2) % polygon.count];
    const Vec2& n = polygon.normals[i];
    EXPECT_GT(cross(v1 - v0, v2 - v1), 0) << "turn at vertex " << (i + 1) % polygon.count;
    EXPECT_NEAR(n.norm(), 1, 1e-6) << "normal " << i;
    EXPECT_NEAR(n.dot((v1 - v0).normalized()), 0, 1e-6) << "normal " << i;
    EXPECT_GT(n.dot(v0), 0) << "normal " << i << " points inwards";
  }
}

// The centroid of a stored polygon, measured independently of the stored
// frame: building from its own vertices reports the centroid in that frame.
Vec2 centroidOf(const Polygon& polygon) {
  const PolygonBuild rebuilt = buildPolygon(verticesOf(polygon));
  EXPECT_EQ(rebuilt.error, ShapeError::None);
  return rebuilt.centroid;
}

// Polar moment of a triangle about its centroid: m (a^2 + b^2 + c^2) / 36.
double triangleInertia(double mass, const Vec2& a, const Vec2& b, const Vec2& c) {
  const double sumSquares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return mass * sumSquares / 36;
}

double triangleArea(const Vec2& a, const Vec2& b, const Vec2& c) {
  return 0.5 * std::abs(cross(b - a, c - a));
}

TEST(ShapeMassTest, BoxMatchesClosedForm) {
  const Real halfWidth = 2, halfHeight = Real(0.5), density = 3;
  const Polygon box = makeBox(halfWidth, halfHeight);
  expectWellFormed(box);
  const MassProperties mass = computeMassProperties(Shape::makePolygon(box), density);
  const double w = 2 * halfWidth, h = 2 * halfHeight, m = density * w * h;
  expectRelativeNear(mass.area, w * h);
  expectRelativeNear(mass.mass, m);
  expectRelativeNear(mass.inertia, m * (w * w + h * h) / 12);
}

TEST(ShapeMassTest, RightTriangleMatchesClosedForm) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(3, 0), Vec2(0, 4)};
  const PolygonBuild build = buildPolygon(points);
  ASSERT_EQ(build.error, ShapeError::None);
  expectWellFormed(build.polygon);
  // Centroid of a triangle = vertex mean; tolerance 1e-5 m.
  expectVecNear(build.centroid, Vec2(1, Real(4.0 / 3.0)), 1e-5);
  const Real density = 2;
  const MassProperties mass = computeMassProperties(Shape::makePolygon(build.polygon), density);
  expectRelativeNear(mass.area, 6);
  expectRelativeNear(mass.mass, 12);
  // Legs 3 and 4: I = b h^3/36 + h b^3/36 about the centroid = (m/36)(9+16+25).
  expectRelativeNear(mass.inertia, 12.0 * 50 / 36);
}

TEST(ShapeMassTest, OffCentreTriangleMatchesClosedForm) {
  const Vec2 a(100, 50), b(104, 51), c(101, 55);
  const std::vector<Vec2> points = {a, b, c};
  const PolygonBuild build = buildPolygon(points);
  ASSERT_EQ(build.error, ShapeError::None);
  expectWellFormed(build.polygon);
  // Far from the origin float resolves ~1e-5 m; allow 1e-4 m.
  expectVecNear(build.centroid, (a + b + c) / 3, 1e-4);
  const MassProperties mass = computeMassProperties(Shape::makePolygon(build.polygon), 1);
  const double area = triangleArea(a, b, c);
  expectRelativeNear(mass.area, area);
  expectRelativeNear(mass.inertia, triangleInertia(area, a, b, c));
}

TEST(ShapeMassTest, RegularPolygonsMatchClosedForm) {
  const Real radius = Real(1.5), density = Real(0.7);
  for (int n = kMinPolygonVertices; n <= kMaxPolygonVertices; ++n) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const Polygon polygon = makeRegularPolygon(n, radius);
    ASSERT_EQ(polygon.count, n);
    expectWellFormed(polygon);
    // Centroid at the origin within 1e-6 m.
    expectVecNear(centroidOf(polygon), Vec2::Zero(), 1e-6);
    const double r2 = double(radius) * radius;
    const double area = 0.5 * n * r2 * std::sin(2 * kPi / n);
    const double m = density * area;
    const double cosine = std::cos(kPi / n);
    const MassProperties mass = computeMassProperties(Shape::makePolygon(polygon), density);
    expectRelativeNear(mass.area, area);
    expectRelativeNear(mass.mass, m);
    expectRelativeNear(mass.inertia, m * r2 / 6 * (1 + 2 * cosine * cosine));
  }
}

TEST(ShapeMassTest, CircleMatchesClosedForm) {
  const Real radius = Real(0.8), density = Real(2.5);
  const MassProperties mass = computeMassProperties(Shape::makeCircle(radius), density);
  const double area = kPi * radius * radius;
  const double m = density * area;
  expectRelativeNear(mass.area, area);
  expectRelativeNear(mass.mass, m);
  expectRelativeNear(mass.inertia, m * radius * radius / 2);
}

TEST(ShapeMassTest, QuadrilateralCentroidIsAreaCentroidNotVertexMean) {
  // Rectangle [0,4]x[0,1] plus triangle (0,1),(4,1),(0,3).
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(4, 0), Vec2(4, 1), Vec2(0, 3)};
  const double rectArea = 4, triArea = 4, area = rectArea + triArea;
  const Vec2 rectCentroid(2, 0.5);
  const Vec2 triCentroid = (Vec2(0, 1) + Vec2(4, 1) + Vec2(0, 3)) / 3;
  const Vec2 centroid = (rectArea * rectCentroid + triArea * triCentroid) / area;

  const PolygonBuild build = buildPolygon(points);
  ASSERT_EQ(build.error, ShapeError::None);
  expectWellFormed(build.polygon);
  // (5/3, 13/12), not the vertex mean (2, 1); tolerance 1e-5 m.
  expectVecNear(build.centroid, centroid, 1e-5);
  EXPECT_GT((build.centroid - Vec2(2, 1)).norm(), 0.1);

  const double rectInertia = rectArea * (16 + 1) / 12;
  const double triInertia = triangleInertia(triArea, Vec2(0, 1), Vec2(4, 1), Vec2(0, 3));
  const double inertia = rectInertia + rectArea * (rectCentroid - centroid).squaredNorm() +
                         triInertia + triArea * (triCentroid - centroid).squaredNorm();
  const MassProperties mass = computeMassProperties(Shape::makePolygon(build.polygon), 1);
  expectRelativeNear(mass.area, area);
  expectRelativeNear(mass.inertia, inertia);
}

// Index k such that a.vertices[(i + k) % n] matches b.vertices[i], or -1.
int rotationBetween(const Polygon& a, const Polygon& b, double tolerance) {
  if (a.count != b.count) return -1;
  for (int k = 0; k < a.count; ++k) {
    bool matches = true;
    for (int i = 0; i < a.count && matches; ++i) {
      matches = (a.vertices[(i + k) % a.count] - b.vertices[i]).norm() < tolerance;
    }
    if (matches) return k;
  }
  return -1;
}

TEST(ShapeBuildTest, ClockwiseAndAnticlockwiseInputGiveSamePolygon) {
  const std::vector<Vec2> anticlockwise = {Vec2(1, 1), Vec2(4, 0.5), Vec2(5, 3), Vec2(3, 4.5),
                                           Vec2(0.5, 3)};
  const std::vector<Vec2> clockwise(anticlockwise.rbegin(), anticlockwise.rend());
  const PolygonBuild a = buildPolygon(anticlockwise);
  const PolygonBuild b = buildPolygon(clockwise);
  ASSERT_EQ(a.error, ShapeError::None);
  ASSERT_EQ(b.error, ShapeError::None);
  expectWellFormed(a.polygon);
  expectWellFormed(b.polygon);
  // Same vertices up to index rotation, within 1e-5 m.
  EXPECT_GE(rotationBetween(a.polygon, b.polygon, 1e-5), 0);
  expectVecNear(a.centroid, b.centroid, 1e-5);
  const MassProperties massA = computeMassProperties(Shape::makePolygon(a.polygon), 1);
  const MassProperties massB = computeMassProperties(Shape::makePolygon(b.polygon), 1);
  expectRelativeNear(massB.area, massA.area);
  expectRelativeNear(massB.inertia, massA.inertia);
}

TEST(ShapeBuildTest, StoredVerticesAreInputMinusCentroid) {
  const std::vector<Vec2> points = {Vec2(10, 20), Vec2(13, 20), Vec2(13, 22), Vec2(10, 22)};
  const PolygonBuild build = buildPolygon(points);
  ASSERT_EQ(build.error, ShapeError::None);
  expectVecNear(build.centroid, Vec2(11.5, 21), 1e-5);
  for (int i = 0; i < build.polygon.count; ++i) {
    expectVecNear(build.polygon.vertices[i] + build.centroid, points[i], 1e-5);
  }
  // Rebuilding the stored polygon finds its centroid at the origin (1e-6 m).
  expectVecNear(centroidOf(build.polygon), Vec2::Zero(), 1e-6);
}

void expectRefused(std::span<const Vec2> points, ShapeError expected,
                   const ShapeLimits& limits = {}) {
  const PolygonBuild build = buildPolygon(points, limits);
  EXPECT_EQ(build.error, expected) << describe(build.error);
  EXPECT_EQ(build.polygon.count, 0) << "a refused polygon must carry no vertices";
  EXPECT_FALSE(describe(expected).empty());
}

TEST(ShapeErrorTest, FewerThanThreePointsAreTooFewVertices) {
  expectRefused({}, ShapeError::TooFewVertices);
  const std::vector<Vec2> two = {Vec2(0, 0), Vec2(1, 0)};
  expectRefused(two, ShapeError::TooFewVertices);
}

TEST(ShapeErrorTest, SeventeenPointsAreTooManyVertices) {
  std::vector<Vec2> points;
  for (int i = 0; i < kMaxPolygonVertices + 1; ++i) {
    const double angle = 2 * kPi * i / (kMaxPolygonVertices + 1);
    points.emplace_back(Real(std::cos(angle)), Real(std::sin(angle)));
  }
  expectRefused(points, ShapeError::TooManyVertices);
  points.pop_back();
  EXPECT_EQ(buildPolygon(points).error, ShapeError::None);
}

TEST(ShapeErrorTest, NanOrInfinityIsNonFinite) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real inf = std::numeric_limits<Real>::infinity();
  const std::vector<Vec2> withNan = {Vec2(0, 0), Vec2(1, nan), Vec2(0, 1)};
  const std::vector<Vec2> withInf = {Vec2(0, 0), Vec2(1, 0), Vec2(-inf, 1)};
  expectRefused(withNan, ShapeError::NonFinite);
  expectRefused(withInf, ShapeError::NonFinite);
}

TEST(ShapeErrorTest, RepeatedOrNearlyRepeatedPointIsDuplicate) {
  const std::vector<Vec2> repeated = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 1)};
  // 0.2 mm apart: below the 0.5 mm duplicate tolerance.
  const std::vector<Vec2> nearly = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1),
                                    Vec2(Real(0.0002), 0)};
  expectRefused(repeated, ShapeError::DuplicatePoints);
  expectRefused(nearly, ShapeError::DuplicatePoints);
}

TEST(ShapeErrorTest, PointOnTheLineOfItsNeighboursIsCollinear) {
  const std::vector<Vec2> midEdge = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)};
  const std::vector<Vec2> allOnALine = {Vec2(0, 0), Vec2(1, 1), Vec2(3, 3)};
  // 0.2 mm off the line, below the 0.5 mm tolerance.
  const std::vector<Vec2> nearlyOnEdge = {Vec2(0, 0), Vec2(1, Real(-0.0002)), Vec2(2, 0),
                                          Vec2(2, 2), Vec2(0, 2)};
  expectRefused(midEdge, ShapeError::CollinearPoints);
  expectRefused(allOnALine, ShapeError::CollinearPoints);
  expectRefused(nearlyOnEdge, ShapeError::CollinearPoints);
}

// A playing card (2 mm by 40 cm) is a valid box: its corners 2 mm apart are
// distinct points, each off the line of its neighbours. Its 8 cm^2 needs a
// world's lower minimum area. A sliver ten times thinner is refused.
TEST(ShapeErrorTest, TwoMillimetreCardIsValid_TwoTenthsOfAMillimetreSliverIsNot) {
  const auto box = [](Real halfWidth) {
    return std::vector<Vec2>{Vec2(-halfWidth, Real(-0.2)), Vec2(halfWidth, Real(-0.2)),
                             Vec2(halfWidth, Real(0.2)), Vec2(-halfWidth, Real(0.2))};
  };
  const ShapeLimits smallShapes{.minArea = Real(1e-5)};
  const PolygonBuild card = buildPolygon(box(Real(0.001)), smallShapes);
  EXPECT_EQ(card.error, ShapeError::None) << describe(card.error);
  EXPECT_NEAR(card.polygon.vertices[1].x() - card.polygon.vertices[0].x(), 0.002, 1e-6);
  expectRefused(box(Real(0.0001)), ShapeError::DuplicatePoints, smallShapes);
}

TEST(ShapeErrorTest, CrossingEdgesAreSelfIntersecting) {
  const std::vector<Vec2> bowtie = {Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(0, 2)};
  const std::vector<Vec2> pentagram = {Vec2(0, 3), Vec2(2, -2), Vec2(-3, 1), Vec2(3, 1),
                                       Vec2(-2, -2)};
  // Vertex (2,0) rests on edge (0,0)-(4,0); no vertex is on its neighbours' line.
  const std::vector<Vec2> touching = {Vec2(0, 0), Vec2(4, 0), Vec2(4, 3), Vec2(2, 0), Vec2(0, 3)};
  expectRefused(bowtie, ShapeError::SelfIntersecting);
  expectRefused(pentagram, ShapeError::SelfIntersecting);
  expectRefused(touching, ShapeError::SelfIntersecting);
}

TEST(ShapeErrorTest, SimplePolygonWithReflexVertexIsNonConvex) {
  const std::vector<Vec2> dart = {Vec2(0, 0), Vec2(2, 1), Vec2(4, 0), Vec2(2, 3)};
  const std::vector<Vec2> dartClockwise(dart.rbegin(), dart.rend());
  expectRefused(dart, ShapeError::NonConvex);
  expectRefused(dartClockwise, ShapeError::NonConvex);
}

TEST(ShapeErrorTest, AreaOutsideLimitsIsAreaOutOfRange) {
  // 0.04 x 0.04 / 2 = 8e-4 m^2 < 1e-3; 50 x 50 = 2500 m^2 > 1000.
  const std::vector<Vec2> tiny = {Vec2(0, 0), Vec2(Real(0.04), 0), Vec2(0, Real(0.04))};
  const std::vector<Vec2> huge = {Vec2(0, 0), Vec2(50, 0), Vec2(50, 50), Vec2(0, 50)};
  expectRefused(tiny, ShapeError::AreaOutOfRange);
  expectRefused(huge, ShapeError::AreaOutOfRange);
  const std::vector<Vec2> unit = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  EXPECT_EQ(buildPolygon(unit).error, ShapeError::None);
  ShapeLimits strict;
  strict.maxArea = Real(0.5);
  expectRefused(unit, ShapeError::AreaOutOfRange, strict);
}

TEST(ShapeErrorTest, CircleRadiusOutsideLimitsIsRadiusOutOfRange) {
  EXPECT_EQ(validateCircle(Real(0.5)), ShapeError::None);
  EXPECT_EQ(validateCircle(Real(0.01)), ShapeError::RadiusOutOfRange);
  EXPECT_EQ(validateCircle(0), ShapeError::RadiusOutOfRange);
  EXPECT_EQ(validateCircle(-1), ShapeError::RadiusOutOfRange);
  EXPECT_EQ(validateCircle(25), ShapeError::RadiusOutOfRange);
  ShapeLimits small;
  small.maxRadius = Real(0.4);
  EXPECT_EQ(validateCircle(Real(0.5), small), ShapeError::RadiusOutOfRange);
}

TEST(ShapeErrorTest, NonFiniteCircleRadiusIsNonFinite) {
  EXPECT_EQ(validateCircle(std::numeric_limits<Real>::quiet_NaN()), ShapeError::NonFinite);
  EXPECT_EQ(validateCircle(std::numeric_limits<Real>::infinity()), ShapeError::NonFinite);
}

TEST(ShapeErrorTest, EveryErrorHasItsOwnNonEmptyMessage) {
  const std::vector<ShapeError> errors = {
      ShapeError::TooFewVertices,  ShapeError::TooManyVertices, ShapeError::NonFinite,
      ShapeError::DuplicatePoints, ShapeError::CollinearPoints, ShapeError::SelfIntersecting,
      ShapeError::NonConvex,       ShapeError::AreaOutOfRange,  ShapeError::RadiusOutOfRange};
  std::set<std::string_view> messages;
  for (ShapeError error : errors) {
    EXPECT_FALSE(describe(error).empty()) << static_cast<int>(error);
    messages.insert(describe(error));
  }
  EXPECT_EQ(messages.size(), errors.size());
  EXPECT_NE(describe(ShapeError::TooFewVertices).find('3'), std::string_view::npos);
  EXPECT_NE(describe(ShapeError::TooManyVertices).find("16"), std::string_view::npos);
}

TEST(ShapeInProgressTest, AnticlockwiseClicksAcceptSimpleCandidatesAndRejectOthers) {
  const std::vector<Vec2> placed = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2)};
  const auto withCandidate = [&](const Vec2& candidate) {
    std::vector<Vec2> points = placed;
    points.push_back(candidate);
    return checkPolygonInProgress(points);
  };
  EXPECT_EQ(checkPolygonInProgress(std::span(placed.data(), 1)), ShapeError::None);
  EXPECT_EQ(checkPolygonInProgress(std::span(placed.data(), 2)), ShapeError::None);
  EXPECT_EQ(checkPolygonInProgress(placed), ShapeError::None);
  EXPECT_EQ(withCandidate(Vec2(1, 3)), ShapeError::None);
  EXPECT_EQ(withCandidate(Vec2(3, 1)), ShapeError::SelfIntersecting);
  EXPECT_EQ(withCandidate(Vec2(1, Real(0.5))), ShapeError::None) << "a concave dart is a simple polygon";
  EXPECT_EQ(withCandidate(Vec2(2, 4)), ShapeError::CollinearPoints);
  EXPECT_EQ(withCandidate(Vec2(2, 0)), ShapeError::DuplicatePoints);
}

TEST(ShapeInProgressTest, ClockwiseClicksAcceptSimpleCandidatesAndRejectOthers) {
  const std::vector<Vec2> placed = {Vec2(0, 0), Vec2(0, 2), Vec2(2, 2)};
  const auto withCandidate = [&](const Vec2& candidate) {
    std::vector<Vec2> points = placed;
    points.push_back(candidate);
    return checkPolygonInProgress(points);
  };
  EXPECT_EQ(checkPolygonInProgress(placed), ShapeError::None);
  EXPECT_EQ(withCandidate(Vec2(3, 1)), ShapeError::None);
  EXPECT_EQ(withCandidate(Vec2(1, 3)), ShapeError::SelfIntersecting);
  EXPECT_EQ(withCandidate(Vec2(1, Real(1.5))), ShapeError::None) << "a concave dart is a simple polygon";
  EXPECT_EQ(withCandidate(Vec2(4, 2)), ShapeError::CollinearPoints);
}

TEST(ShapeInProgressTest, FirstPointsNeedOnlyBeFiniteAndDistinct) {
  const std::vector<Vec2> same = {Vec2(1, 1), Vec2(1, 1)};
  const std::vector<Vec2> nan = {Vec2(1, 1), Vec2(std::numeric_limits<Real>::quiet_NaN(), 0)};
  const std::vector<Vec2> collinearSoFar = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)};
  EXPECT_EQ(checkPolygonInProgress({}), ShapeError::None);
  EXPECT_EQ(checkPolygonInProgress(same), ShapeError::DuplicatePoints);
  EXPECT_EQ(checkPolygonInProgress(nan), ShapeError::NonFinite);
  EXPECT_EQ(checkPolygonInProgress(std::span(collinearSoFar.data(), 2)), ShapeError::None);
  EXPECT_EQ(checkPolygonInProgress(collinearSoFar), ShapeError::CollinearPoints);
}

TEST(ShapeInProgressTest, SeventeenthPointIsRefused) {
  const Polygon sixteen = makeRegularPolygon(kMaxPolygonVertices, 2);
  std::vector<Vec2> points(sixteen.vertices.begin(), sixteen.vertices.end());
  EXPECT_EQ(checkPolygonInProgress(points), ShapeError::None);
  points.push_back(Vec2(0, 0));
  EXPECT_EQ(checkPolygonInProgress(points), ShapeError::TooManyVertices);
}

// Random point sets: the drawing check and the builder must agree on every
// shape whose area is in range, so the viewer never shows green for a polygon
// the server then refuses. A concave outline the builder calls NonConvex is
// welcome while drawing: the world splits it into convex pieces.
TEST(ShapeInProgressTest, AgreesWithBuildPolygonOnRandomPointSets) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<Real> coordinate(-3, 3);
  std::uniform_int_distribution<int> countOf(kMinPolygonVertices, 6);
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<Vec2> points(countOf(random));
    for (Vec2& p : points) p = Vec2(coordinate(random), coordinate(random));
    const ShapeError built = buildPolygon(points).error;
    const ShapeError drawn = checkPolygonInProgress(points);
    if (built == ShapeError::NonConvex) {
      EXPECT_EQ(drawn, ShapeError::None) << "trial " << trial;
    } else if (built != ShapeError::AreaOutOfRange) {
      EXPECT_EQ(drawn, built) << "trial " << trial;
    }
    if (built == ShapeError::None) ++accepted;
  }
  // Enough random triangles are valid that accepted shapes were compared too.
  EXPECT_GT(accepted, 100);
}

TEST(ShapeGeometryTest, RotatedBoxAabbIsTight) {
  const Shape box = Shape::makePolygon(makeBox(2, 1));
  const Real angle = Real(kPi / 6);
  const Transform transform{Vec2(5, -3), Rot::fromAngle(angle)};
  const AABB aabb = computeAABB(box, transform);
  const double c = std::cos(angle), s = std::sin(angle);
  const Vec2 half(Real(2 * c + 1 * s), Real(2 * s + 1 * c));
  // Tolerance 1e-5 m.
  expectVecNear(aabb.lower, transform.p - half, 1e-5);
  expectVecNear(aabb.upper, transform.p + half, 1e-5);
}

TEST(ShapeGeometryTest, CircleAabbIsCentredOnPosition) {
  const Transform transform{Vec2(-1, 2), Rot::fromAngle(1)};
  const AABB aabb = computeAABB(Shape::makeCircle(Real(0.5)), transform);
  expectVecNear(aabb.lower, Vec2(Real(-1.5), Real(1.5)), 1e-6);
  expectVecNear(aabb.upper, Vec2(Real(-0.5), Real(2.5)), 1e-6);
}

TEST(ShapeGeometryTest, RotatedBoxContainsOnlyPointsInsideIt) {
  const Shape box = Shape::makePolygon(makeBox(2, 1));
  const Transform transform{Vec2(5, -3), Rot::fromAngle(Real(kPi / 6))};
  const auto local = [&](Real x, Real y) { return transform.apply(Vec2(x, y)); };
  EXPECT_TRUE(containsPoint(box, transform, transform.p));
  EXPECT_TRUE(containsPoint(box, transform, local(Real(1.9), Real(0.9))));
  EXPECT_TRUE(containsPoint(box, transform, local(Real(-1.9), Real(-0.9))));
  EXPECT_FALSE(containsPoint(box, transform, local(Real(2.05), 0)));
  EXPECT_FALSE(containsPoint(box, transform, local(0, Real(-1.05))));
  // Inside the AABB's corner but outside the rotated box.
  const AABB aabb = computeAABB(box, transform);
  const Vec2 corner = aabb.upper - Vec2(Real(0.1), Real(0.1));
  EXPECT_FALSE(containsPoint(box, transform, corner));
}

TEST(ShapeGeometryTest, CircleContainsPointsWithinRadius) {
  const Shape circle = Shape::makeCircle(1);
  const Transform transform{Vec2(3, 4), Rot::fromAngle(2)};
  EXPECT_TRUE(containsPoint(circle, transform, Vec2(3, Real(4.99))));
  EXPECT_FALSE(containsPoint(circle, transform, Vec2(Real(3.8), Real(4.8))));
}

TEST(ShapeGeometryTest, ExtentAndInnerRadiusBoundTheShape) {
  const Shape box = Shape::makePolygon(makeBox(2, 1));
  // Tolerance 1e-6 m.
  EXPECT_NEAR(computeExtent(box), std::sqrt(5.0), 1e-6);
  EXPECT_NEAR(computeInnerRadius(box), 1, 1e-6);
  const int n = 6;
  const Real radius = 2;
  const Shape hexagon = Shape::makePolygon(makeRegularPolygon(n, radius));
  EXPECT_NEAR(computeExtent(hexagon), radius, 1e-6);
  EXPECT_NEAR(computeInnerRadius(hexagon), radius * std::cos(kPi / n), 1e-6);
  const Shape circle = Shape::makeCircle(Real(0.7));
  EXPECT_FLOAT_EQ(computeExtent(circle), Real(0.7));
  EXPECT_FLOAT_EQ(computeInnerRadius(circle), Real(0.7));
}

}  // namespace
}  // namespace impulse
