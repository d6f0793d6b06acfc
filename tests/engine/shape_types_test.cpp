// Geometry of every shape type: mass properties, bounds, containment,
// validation, chains and the convex decomposition of concave polygons.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "impulse/shape.h"

namespace impulse {
namespace {

constexpr double kPi = std::numbers::pi;
// Float keeps about 7 significant digits: 1e-5 relative on figures of order 1..100.
constexpr double kRelativeTolerance = 1e-5;

void expectRelativeNear(double actual, double expected) {
  EXPECT_NEAR(actual, expected, kRelativeTolerance * std::abs(expected));
}

void expectVecNear(const Vec2& actual, const Vec2& expected, double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

// Area, centroid and polar moment about the centroid by the midpoint rule
// on a grid over the shape's box, using containsPoint: an estimate that
// shares no formula with computeMassProperties.
MassProperties integrateOnGrid(const Shape& shape, int cells) {
  const AABB box = computeAABB(shape, {});
  const double dx = (box.upper.x() - box.lower.x()) / cells;
  const double dy = (box.upper.y() - box.lower.y()) / cells;
  double area = 0, mx = 0, my = 0, second = 0;
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      const double x = box.lower.x() + (i + 0.5) * dx;
      const double y = box.lower.y() + (j + 0.5) * dy;
      if (!containsPoint(shape, {}, Vec2(Real(x), Real(y)))) continue;
      area += dx * dy;
      mx += x * dx * dy;
      my += y * dx * dy;
      second += (x * x + y * y) * dx * dy;
    }
  }
  MassProperties result;
  result.area = Real(area);
  result.center = Vec2(Real(mx / area), Real(my / area));
  result.inertia = Real(second - area * (mx * mx + my * my) / (area * area));
  return result;
}

// ---- Mass properties ----

TEST(ShapeTypesMass, CircleWithOffsetCentre_HasItsCentreAndDiscInertiaAboutIt) {
  const Real radius = Real(0.4), density = 2;
  const MassProperties mass =
      computeMassProperties(Shape::makeCircle(radius, Vec2(1, -2)), density);
  const double area = kPi * radius * radius;
  expectRelativeNear(mass.area, area);
  expectRelativeNear(mass.mass, density * area);
  expectRelativeNear(mass.inertia, 0.5 * density * area * radius * radius);
  expectVecNear(mass.center, Vec2(1, -2), 1e-7);
}

// A rectangle L x 2r and one disc cut in half, each half moved h = L/2
// outwards: I = I_rect + pi r^4/2 + 2h (4 r^3 / 3) + h^2 pi r^2 (the middle
// term is 2h times the disc's integral of |x|).
TEST(ShapeTypesMass, Capsule_MatchesRectanglePlusTwoHalfDiscs) {
  const Real radius = Real(0.3), density = Real(1.5);
  const Vec2 c1(-1, 2), c2(Real(0.6), Real(3.2));  // length 2
  const MassProperties mass = computeMassProperties(Shape::makeCapsule(c1, c2, radius), density);
  const double r = radius, length = 2, h = length / 2;
  const double area = 2 * r * length + kPi * r * r;
  const double inertia = 2 * r * length * (length * length + 4 * r * r) / 12 +
                         kPi * r * r * r * r / 2 + 2 * h * (4 * r * r * r / 3) +
                         h * h * kPi * r * r;
  expectRelativeNear(mass.area, area);
  expectRelativeNear(mass.mass, density * area);
  expectRelativeNear(mass.inertia, density * inertia);
  expectVecNear(mass.center, Vec2(Real(-0.2), Real(2.6)), 1e-6);
}

TEST(ShapeTypesMass, Capsule_AgreesWithGridIntegration) {
  const Shape capsule =
      Shape::makeCapsule(Vec2(Real(-0.5), Real(0.1)), Vec2(Real(0.7), Real(0.4)), Real(0.25));
  const MassProperties exact = computeMassProperties(capsule, 1);
  const MassProperties grid = integrateOnGrid(capsule, 1000);
  // The grid's boundary cells err by ~ perimeter x cell / 2: under 2e-3 relative here.
  EXPECT_NEAR(grid.area, exact.area, 2e-3 * exact.area);
  EXPECT_NEAR(grid.inertia, exact.inertia, 2e-3 * exact.inertia);
  expectVecNear(grid.center, exact.center, 1e-3);
}

// Rounded box = a (2w+2r) x 2h slab, two 2w x r strips and four quarter
// discs; a quarter disc at corner a with its centroid k = 4r/(3 pi) out
// along each axis adds A (r^2/2 + 2k(w + h) + w^2 + h^2).
TEST(ShapeTypesMass, RoundedBox_MatchesSlabStripsAndQuarterDiscs) {
  const double w = 1, h = 0.5, r = 0.2, density = 3;
  Polygon box = makeBox(Real(w), Real(h));
  box.radius = Real(r);
  const MassProperties mass = computeMassProperties(Shape::makePolygon(box), Real(density));
  const double slabW = 2 * (w + r), slabH = 2 * h, slab = slabW * slabH;
  const double strip = 2 * w * r, quarter = kPi * r * r / 4, k = 4 * r / (3 * kPi);
  const double area = slab + 2 * strip + 4 * quarter;
  const double inertia =
      slab * (slabW * slabW + slabH * slabH) / 12 +
      2 * (strip * (4 * w * w + r * r) / 12 + strip * (h + r / 2) * (h + r / 2)) +
      4 * quarter * (r * r / 2 + 2 * k * (w + h) + w * w + h * h);
  expectRelativeNear(mass.area, area);
  expectRelativeNear(mass.mass, density * area);
  expectRelativeNear(mass.inertia, density * inertia);
  expectVecNear(mass.center, Vec2::Zero(), 1e-7);
}

TEST(ShapeTypesMass, RoundedOffCentreTriangle_AgreesWithGridIntegration) {
  Polygon triangle;
  triangle.count = 3;
  triangle.vertices = {Vec2(1, 1), Vec2(3, Real(1.5)), Vec2(Real(1.5), 3)};
  const std::vector<Vec2> corners = {triangle.vertices[0], triangle.vertices[1],
                                     triangle.vertices[2]};
  const PolygonBuild build = buildPolygon(corners);
  ASSERT_EQ(build.error, ShapeError::None);
  triangle.normals = build.polygon.normals;
  triangle.centroid = build.centroid;
  triangle.radius = Real(0.3);
  const Shape shape = Shape::makePolygon(triangle);
  ASSERT_EQ(validateShape(shape), ShapeError::None);
  const MassProperties exact = computeMassProperties(shape, 1);
  const MassProperties grid = integrateOnGrid(shape, 1000);
  EXPECT_NEAR(grid.area, exact.area, 2e-3 * exact.area);
  EXPECT_NEAR(grid.inertia, exact.inertia, 2e-3 * exact.inertia);
  expectVecNear(grid.center, exact.center, 1e-3);
  // Perimeter strips weigh the centroid differently from the core's: the
  // exact centre is not the core centroid.
  const double perimeter = (corners[1] - corners[0]).norm() + (corners[2] - corners[1]).norm() +
                           (corners[0] - corners[2]).norm();
  const double coreArea = 0.5 * std::abs(cross(corners[1] - corners[0], corners[2] - corners[0]));
  expectRelativeNear(exact.area, coreArea + perimeter * 0.3 + kPi * 0.09);
}

TEST(ShapeTypesMass, SegmentsAndChainSegments_HaveNoMass) {
  const MassProperties segment =
      computeMassProperties(Shape::makeSegment(Vec2(0, 0), Vec2(1, 0)), 5);
  EXPECT_EQ(segment.area, 0);
  EXPECT_EQ(segment.mass, 0);
  EXPECT_EQ(segment.inertia, 0);
  const ChainBuild chain =
      buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(3, 0)}, false);
  ASSERT_EQ(chain.error, ShapeError::None);
  EXPECT_EQ(computeMassProperties(Shape{chain.segments[0]}, 5).mass, 0);
}

// Two unit squares side by side are one 2 x 1 rectangle: I = m (4 + 1) / 12.
TEST(ShapeTypesMass, Combine_TwoSquaresMakeOneRectangle) {
  const Shape left =
      translated(Shape::makePolygon(makeBox(Real(0.5), Real(0.5))), Vec2(-Real(0.5), 3));
  const Shape right =
      translated(Shape::makePolygon(makeBox(Real(0.5), Real(0.5))), Vec2(Real(0.5), 3));
  const std::vector<MassProperties> parts = {computeMassProperties(left, 2),
                                             computeMassProperties(right, 2)};
  const MassProperties total = combineMassProperties(parts);
  expectRelativeNear(total.area, 2);
  expectRelativeNear(total.mass, 4);
  expectRelativeNear(total.inertia, 4.0 * 5 / 12);
  expectVecNear(total.center, Vec2(0, 3), 1e-6);
}

TEST(ShapeTypesMass, Combine_CircleAndCapsuleUseTheParallelAxis) {
  const MassProperties circle = computeMassProperties(Shape::makeCircle(Real(0.5), Vec2(2, 0)), 1);
  const MassProperties capsule =
      computeMassProperties(Shape::makeCapsule(Vec2(-1, 0), Vec2(0, 0), Real(0.25)), 1);
  const std::vector<MassProperties> parts = {circle, capsule};
  const MassProperties total = combineMassProperties(parts);
  const double m = double(circle.mass) + capsule.mass;
  const double cx = (circle.mass * 2.0 + capsule.mass * -0.5) / m;
  expectRelativeNear(total.mass, m);
  EXPECT_NEAR(total.center.x(), cx, 1e-6);
  expectRelativeNear(total.inertia, circle.inertia + circle.mass * (2 - cx) * (2 - cx) +
                                        capsule.inertia + capsule.mass * (-0.5 - cx) * (-0.5 - cx));
}

TEST(ShapeTypesMass, Combine_OnePartComesBackBitIdentical) {
  const MassProperties part =
      computeMassProperties(Shape::makePolygon(makeRegularPolygon(7, Real(0.9))), Real(1.3));
  const MassProperties total = combineMassProperties(std::span(&part, 1));
  EXPECT_EQ(total.area, part.area);
  EXPECT_EQ(total.mass, part.mass);
  EXPECT_EQ(total.inertia, part.inertia);
  EXPECT_EQ(total.center, part.center);
}

TEST(ShapeTypesMass, CentredPolygon_KeepsItsStoredCentroidExactly) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(3, Real(0.2)), Vec2(Real(2.5), 2),
                                    Vec2(Real(0.3), Real(1.7))};
  const PolygonBuild build = buildPolygon(points);
  ASSERT_EQ(build.error, ShapeError::None);
  EXPECT_EQ(build.polygon.centroid, Vec2::Zero());
  EXPECT_EQ(computeMassProperties(Shape::makePolygon(build.polygon), 1).center, Vec2::Zero());
}

// ---- Translation, bounds, extent, containment ----

TEST(ShapeTypesGeometry, Translated_MovesTheCentreAndKeepsTheInertia) {
  const Vec2 offset(Real(0.5), Real(-1.5));
  Polygon rounded = makeBox(1, Real(0.5));
  rounded.radius = Real(0.1);
  ChainSegment chain{Vec2(-1, 0), Segment{Vec2(0, 0), Vec2(1, 0)}, Vec2(2, 0), 3};
  for (const Shape& shape :
       {Shape::makeCircle(Real(0.5), Vec2(1, 1)),
        Shape::makeCapsule(Vec2(0, 0), Vec2(1, 0), Real(0.2)), Shape::makePolygon(rounded),
        Shape::makeSegment(Vec2(0, 0), Vec2(2, 1)), Shape{chain}}) {
    SCOPED_TRACE(static_cast<int>(shape.type()));
    const Shape moved = translated(shape, offset);
    const MassProperties before = computeMassProperties(shape, 1);
    const MassProperties after = computeMassProperties(moved, 1);
    EXPECT_NEAR(after.inertia, before.inertia, 1e-5 * (1 + before.inertia));
    if (before.mass > 0) expectVecNear(after.center, before.center + offset, 1e-6);
    const AABB a = computeAABB(shape, {});
    const AABB b = computeAABB(moved, {});
    expectVecNear(b.lower, a.lower + offset, 1e-6);
    expectVecNear(b.upper, a.upper + offset, 1e-6);
  }
  const Shape movedChain = translated(Shape{chain}, offset);
  expectVecNear(movedChain.chainSegment().ghost1, Vec2(-1, 0) + offset, 1e-7);
  EXPECT_EQ(movedChain.chainSegment().chainId, 3);
}

TEST(ShapeTypesGeometry, Aabbs_IncludeRadiiAndOnlyTheSegmentOfAChain) {
  const Transform xf{Vec2(2, 1), Rot::fromAngle(Real(kPi / 2))};
  // Quarter turn: local (x, y) -> (-y, x).
  const AABB capsule = computeAABB(Shape::makeCapsule(Vec2(0, 0), Vec2(2, 0), Real(0.5)), xf);
  expectVecNear(capsule.lower, Vec2(Real(1.5), Real(0.5)), 1e-6);
  expectVecNear(capsule.upper, Vec2(Real(2.5), Real(3.5)), 1e-6);
  Polygon rounded = makeBox(1, Real(0.5));
  rounded.radius = Real(0.25);
  const AABB box = computeAABB(Shape::makePolygon(rounded), xf);
  expectVecNear(box.lower, Vec2(Real(1.25), Real(-0.25)), 1e-6);
  expectVecNear(box.upper, Vec2(Real(2.75), Real(2.25)), 1e-6);
  const AABB circle = computeAABB(Shape::makeCircle(Real(0.5), Vec2(1, 0)), xf);
  expectVecNear(circle.lower, Vec2(Real(1.5), Real(1.5)), 1e-6);
  expectVecNear(circle.upper, Vec2(Real(2.5), Real(2.5)), 1e-6);
  const ChainSegment chain{Vec2(-5, -5), Segment{Vec2(0, 0), Vec2(1, 0)}, Vec2(9, 9), -1};
  const AABB line = computeAABB(Shape{chain}, {});
  expectVecNear(line.lower, Vec2(0, 0), 1e-7);
  expectVecNear(line.upper, Vec2(1, 0), 1e-7);
}

TEST(ShapeTypesGeometry, ExtentAndInnerRadius_ForEachType) {
  const Shape capsule = Shape::makeCapsule(Vec2(1, 0), Vec2(-3, 0), Real(0.5));
  EXPECT_NEAR(computeExtent(capsule), 3.5, 1e-6);
  EXPECT_NEAR(computeInnerRadius(capsule), 0.5, 1e-6);
  Polygon rounded = makeBox(2, 1);
  rounded.radius = Real(0.25);
  EXPECT_NEAR(computeExtent(Shape::makePolygon(rounded)), std::sqrt(5.0) + 0.25, 1e-6);
  EXPECT_NEAR(computeInnerRadius(Shape::makePolygon(rounded)), 1.25, 1e-6);
  const Shape circle = Shape::makeCircle(Real(0.5), Vec2(3, 4));
  EXPECT_NEAR(computeExtent(circle), 5.5, 1e-6);
  EXPECT_NEAR(computeInnerRadius(circle), 0.5, 1e-6);
  const Shape segment = Shape::makeSegment(Vec2(3, 4), Vec2(-1, 0));
  EXPECT_NEAR(computeExtent(segment), 5, 1e-6);
  EXPECT_EQ(computeInnerRadius(segment), 0);
}

TEST(ShapeTypesGeometry, ContainsPoint_CapsuleRoundedPolygonAndNeverALine) {
  const Transform xf{Vec2(1, 1), Rot::fromAngle(Real(0.3))};
  const auto world = [&](Real x, Real y) { return xf.apply(Vec2(x, y)); };
  const Shape capsule = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.5));
  EXPECT_TRUE(containsPoint(capsule, xf, world(Real(1.45), 0)));
  EXPECT_FALSE(containsPoint(capsule, xf, world(Real(1.55), 0)));
  EXPECT_TRUE(containsPoint(capsule, xf, world(0, Real(0.49))));
  // Beside the cap's corner of the bounding box: outside the round end.
  EXPECT_FALSE(containsPoint(capsule, xf, world(Real(1.4), Real(0.4))));

  Polygon rounded = makeBox(1, 1);
  rounded.radius = Real(0.5);
  const Shape box = Shape::makePolygon(rounded);
  const Real d = Real(0.5 / std::sqrt(2.0));
  EXPECT_TRUE(containsPoint(box, xf, world(1 + Real(0.95) * d, 1 + Real(0.95) * d)));
  EXPECT_FALSE(containsPoint(box, xf, world(1 + Real(1.05) * d, 1 + Real(1.05) * d)));
  EXPECT_TRUE(containsPoint(box, xf, world(Real(1.45), 0)));
  EXPECT_FALSE(containsPoint(box, xf, world(Real(1.55), 0)));

  EXPECT_FALSE(containsPoint(Shape::makeSegment(Vec2(-1, 0), Vec2(1, 0)), xf, world(0, 0)));
}

// ---- Validation ----

TEST(ShapeTypesValidation, EachTypeIsRefusedForItsOwnProblem) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_EQ(validateShape(Shape::makeCircle(Real(0.5), Vec2(1, 2))), ShapeError::None);
  EXPECT_EQ(validateShape(Shape::makeCircle(Real(0.5), Vec2(nan, 2))), ShapeError::NonFinite);
  EXPECT_EQ(validateShape(Shape::makeCircle(Real(0.001))), ShapeError::RadiusOutOfRange);

  EXPECT_EQ(validateShape(Shape::makeCapsule(Vec2(0, 0), Vec2(1, 0), Real(0.2))), ShapeError::None);
  EXPECT_EQ(validateShape(Shape::makeCapsule(Vec2(0, 0), Vec2(Real(0.004), 0), Real(0.2))),
            ShapeError::SegmentTooShort);
  EXPECT_EQ(validateShape(Shape::makeCapsule(Vec2(0, 0), Vec2(1, 0), Real(25))),
            ShapeError::CapsuleRadiusOutOfRange);
  EXPECT_EQ(validateShape(Shape::makeCapsule(Vec2(0, 0), Vec2(1, 0), nan)), ShapeError::NonFinite);

  EXPECT_EQ(validateShape(Shape::makeSegment(Vec2(0, 0), Vec2(0, 1))), ShapeError::None);
  EXPECT_EQ(validateShape(Shape::makeSegment(Vec2(0, 0), Vec2(0, Real(0.001)))),
            ShapeError::SegmentTooShort);

  Polygon box = makeBox(1, 1);
  EXPECT_EQ(validateShape(Shape::makePolygon(box)), ShapeError::None);
  box.radius = Real(0.1);
  EXPECT_EQ(validateShape(Shape::makePolygon(box)), ShapeError::None);
  box.radius = -1;
  EXPECT_EQ(validateShape(Shape::makePolygon(box)), ShapeError::RoundingRadiusOutOfRange);
  box.radius = 0;
  std::swap(box.normals[0], box.normals[1]);
  EXPECT_EQ(validateShape(Shape::makePolygon(box)), ShapeError::BadNormals);
  Polygon clockwise = makeBox(1, 1);
  std::reverse(clockwise.vertices.begin(), clockwise.vertices.begin() + 4);
  EXPECT_EQ(validateShape(Shape::makePolygon(clockwise)), ShapeError::Clockwise);
  Polygon dent = makeBox(1, 1);
  dent.vertices[2] = Vec2(Real(-0.5), Real(-0.5));
  EXPECT_EQ(validateShape(Shape::makePolygon(dent)), ShapeError::NonConvex);
  Polygon offCentre = makeBox(1, 1);
  offCentre.centroid = Vec2(Real(0.01), 0);
  EXPECT_EQ(validateShape(Shape::makePolygon(offCentre)), ShapeError::BadCentroid);
  // Points in another frame: the helper gives the centroid to store.
  Polygon moved = makeBox(1, Real(0.5));
  for (int i = 0; i < 4; ++i) moved.vertices[i] += Vec2(7, -3);
  EXPECT_EQ(validateShape(Shape::makePolygon(moved)), ShapeError::BadCentroid);
  expectVecNear(computePolygonCentroid(moved), Vec2(7, -3), 1e-6);
  moved.centroid = computePolygonCentroid(moved);
  EXPECT_EQ(validateShape(Shape::makePolygon(moved)), ShapeError::None);
  EXPECT_EQ(validateShape(translated(Shape::makePolygon(makeBox(1, 1)), Vec2(30, -40))),
            ShapeError::None);
  Polygon two;
  two.count = 2;
  EXPECT_EQ(validateShape(Shape::makePolygon(two)), ShapeError::TooFewVertices);

  const ChainSegment chain{Vec2(-1, 0), Segment{Vec2(0, 0), Vec2(Real(0.001), 0)}, Vec2(2, 0), -1};
  EXPECT_EQ(validateShape(Shape{chain}), ShapeError::SegmentTooShort);
}

TEST(ShapeTypesValidation, EveryErrorHasItsOwnMessage) {
  std::set<std::string_view> messages;
  const int last = static_cast<int>(ShapeError::BadCentroid);
  for (int e = 0; e <= last; ++e) {
    const std::string_view message = describe(static_cast<ShapeError>(e));
    EXPECT_FALSE(message.empty());
    EXPECT_NE(message, "unknown shape error") << e;
    messages.insert(message);
  }
  EXPECT_EQ(messages.size(), std::size_t(last + 1));
}

TEST(ShapeTypesValidation, NewMessagesNameTheProblemInTheUsersWords) {
  EXPECT_EQ(describe(ShapeError::SegmentTooShort).substr(0, 54),
            "segment is shorter than 5 mm: its two points (a capsul");
  EXPECT_NE(describe(ShapeError::SegmentTooShort).find("at least 5 mm apart"),
            std::string_view::npos);
  EXPECT_NE(describe(ShapeError::ChainTooFewPoints).find("at least 4 points"),
            std::string_view::npos);
  EXPECT_NE(describe(ShapeError::ChainTooManyPoints).find("1024"), std::string_view::npos);
  EXPECT_NE(describe(ShapeError::ChainCrossing).find("crosses itself"), std::string_view::npos);
  EXPECT_NE(describe(ShapeError::CapsuleRadiusOutOfRange).find("capsule radius"),
            std::string_view::npos);
  EXPECT_NE(describe(ShapeError::TooManyConcavePoints).find("256"), std::string_view::npos);
  EXPECT_NE(describe(ShapeError::Clockwise).find("anticlockwise"), std::string_view::npos);
}

// ---- Chains ----

TEST(ShapeTypesChain, OpenChain_UsesFirstAndLastPointsAsGhostsOnly) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0),
                                    Vec2(3, 1), Vec2(4, 1), Vec2(5, 0)};
  const ChainBuild chain = buildChain(points, false);
  ASSERT_EQ(chain.error, ShapeError::None);
  ASSERT_EQ(chain.segments.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(chain.segments[k].ghost1, points[k]);
    EXPECT_EQ(chain.segments[k].segment.point1, points[k + 1]);
    EXPECT_EQ(chain.segments[k].segment.point2, points[k + 2]);
    EXPECT_EQ(chain.segments[k].ghost2, points[k + 3]);
  }
}

TEST(ShapeTypesChain, Loop_JoinsTheLastPointToTheFirstWithWrappedGhosts) {
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2)};
  const ChainBuild chain = buildChain(points, true);
  ASSERT_EQ(chain.error, ShapeError::None);
  ASSERT_EQ(chain.segments.size(), 4u);
  EXPECT_EQ(chain.segments[3].ghost1, points[2]);
  EXPECT_EQ(chain.segments[3].segment.point1, points[3]);
  EXPECT_EQ(chain.segments[3].segment.point2, points[0]);
  EXPECT_EQ(chain.segments[3].ghost2, points[1]);
  EXPECT_EQ(chain.segments[0].ghost1, points[3]);
}

TEST(ShapeTypesChain, RefusesFewTooManyNonFiniteShortAndCrossing) {
  EXPECT_EQ(buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}, false).error,
            ShapeError::ChainTooFewPoints);
  std::vector<Vec2> many;
  for (int i = 0; i <= kMaxChainPoints; ++i) many.push_back(Vec2(Real(i), 0));
  EXPECT_EQ(buildChain(many, false).error, ShapeError::ChainTooManyPoints);
  many.pop_back();
  EXPECT_EQ(buildChain(many, false).error, ShapeError::None);
  EXPECT_EQ(buildChain(many, false).segments.size(), std::size_t(kMaxChainPoints - 3));
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_EQ(
      buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0), Vec2(nan, 0), Vec2(3, 0)}, false).error,
      ShapeError::NonFinite);
  EXPECT_EQ(
      buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0), Vec2(Real(1.001), 0), Vec2(3, 0)}, false)
          .error,
      ShapeError::SegmentTooShort);
  // A loop's closing edge counts: the last point on top of the first.
  EXPECT_EQ(
      buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, Real(0.002))}, true)
          .error,
      ShapeError::SegmentTooShort);
  // A figure of eight.
  EXPECT_EQ(
      buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(0, 2)}, true).error,
      ShapeError::ChainCrossing);
  // Folding back along itself.
  EXPECT_EQ(
      buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(3, 0), Vec2(1, 0), Vec2(1, 2)}, false).error,
      ShapeError::ChainCrossing);
  // The same points as an open zigzag do not cross.
  EXPECT_EQ(
      buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(4, 2)}, false).error,
      ShapeError::None);
}

// ---- Convex decomposition ----

// Every piece a valid convex polygon; their union has the input's area and centroid.
void expectDecomposes(std::span<const Vec2> points, double area, const Vec2& centroid,
                      std::size_t maxPieces) {
  const ConvexDecomposition decomposition = decomposePolygon(points);
  ASSERT_EQ(decomposition.error, ShapeError::None) << describe(decomposition.error);
  ASSERT_GE(decomposition.pieces.size(), 1u);
  EXPECT_LE(decomposition.pieces.size(), maxPieces);
  std::vector<MassProperties> parts;
  for (const Polygon& piece : decomposition.pieces) {
    EXPECT_EQ(validateShape(Shape::makePolygon(piece), ShapeLimits{Real(0.02), 20, 0, 1000}),
              ShapeError::None);
    parts.push_back(computeMassProperties(Shape::makePolygon(piece), 1));
    expectVecNear(parts.back().center, piece.centroid, 1e-5);
  }
  const MassProperties total = combineMassProperties(parts);
  EXPECT_NEAR(total.area, area, 1e-5 * area);
  expectVecNear(total.center, centroid, 1e-5);
}

TEST(ShapeTypesDecomposition, LShape_BecomesTwoConvexPieces) {
  // 3 x 3 square minus its 2 x 2 top-right corner: area 5.
  const std::vector<Vec2> points = {Vec2(0, 0), Vec2(3, 0), Vec2(3, 1),
                                    Vec2(1, 1), Vec2(1, 3), Vec2(0, 3)};
  // Centroid: (3 x 1 at (1.5, 0.5)) + (1 x 2 at (0.5, 2)) over 5 = (1.1, 1.1).
  expectDecomposes(points, 5, Vec2(Real(1.1), Real(1.1)), 2);
  std::vector<Vec2> reversed(points.rbegin(), points.rend());
  expectDecomposes(reversed, 5, Vec2(Real(1.1), Real(1.1)), 2);
}

std::vector<Vec2> circlePoints(int count, double radius, const Vec2& center = Vec2::Zero()) {
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    const double angle = 2 * kPi * i / count;
    points.push_back(center + Vec2(Real(radius * std::cos(angle)), Real(radius * std::sin(angle))));
  }
  return points;
}

double regularArea(int count, double radius) {
  return 0.5 * count * radius * radius * std::sin(2 * kPi / count);
}

TEST(ShapeTypesDecomposition, ConvexInput_OnePieceUpTo16VerticesAndTwoFor24) {
  expectDecomposes(circlePoints(8, 1, Vec2(5, 5)), regularArea(8, 1), Vec2(5, 5), 1);
  expectDecomposes(circlePoints(16, 1), regularArea(16, 1), Vec2::Zero(), 1);
  expectDecomposes(circlePoints(24, 2), regularArea(24, 2), Vec2::Zero(), 2);
}

// A five-pointed star needs 5 pieces at best; Hertel-Mehlhorn stays within 4x.
TEST(ShapeTypesDecomposition, Star_AreaAndCentroidKept) {
  std::vector<Vec2> star;
  for (int i = 0; i < 10; ++i) {
    const double angle = kPi / 2 + kPi * i / 5;
    const double radius = i % 2 == 0 ? 2 : 0.8;
    star.push_back(Vec2(Real(radius * std::cos(angle)), Real(radius * std::sin(angle))));
  }
  // Ten triangles (centre, outer i, inner i+1): each 0.5 * 2 * 0.8 * sin(36 deg).
  const double area = 10 * 0.5 * 2 * 0.8 * std::sin(kPi / 5);
  expectDecomposes(star, area, Vec2::Zero(), 8);
}

// A comb of 40 teeth has r = 39 reflex vertices: Hertel-Mehlhorn's bound is
// 2r + 1 = 79 pieces (triangles alone would be 81).
TEST(ShapeTypesDecomposition, Comb_MergesIntoFewPieces) {
  std::vector<Vec2> comb = {Vec2(0, 0), Vec2(40, 0)};
  for (int tooth = 39; tooth >= 0; --tooth) {
    comb.push_back(Vec2(Real(tooth + 1), 1));
    comb.push_back(Vec2(Real(tooth + Real(0.5)), 2));
  }
  comb.push_back(Vec2(0, 1));
  // 40 x 1 base plus 40 triangles of base 1 and height 1... the last tooth
  // shares its left foot with the base corner (0, 1).
  const double area = 40 + 40 * 0.5;
  const double centroidY = (40 * 0.5 + 20 * (1 + 1.0 / 3)) / area;
  expectDecomposes(comb, area, Vec2(20, Real(centroidY)), 79);
}

TEST(ShapeTypesDecomposition, RandomStarShapedPolygons_KeepAreaAndCentroid) {
  std::mt19937 random(27);
  std::uniform_real_distribution<double> radius(0.5, 2.0);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(trial);
    const int count = 5 + trial;
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
      const double angle = 2 * kPi * i / count;
      const double r = radius(random);
      points.push_back(Vec2(Real(r * std::cos(angle)), Real(r * std::sin(angle))));
    }
    // Reference: the fan from the origin (inside a star-shaped polygon).
    double area = 0, mx = 0, my = 0;
    for (int i = 0; i < count; ++i) {
      const Vec2& a = points[i];
      const Vec2& b = points[(i + 1) % count];
      const double t = 0.5 * cross(a, b);
      area += t;
      mx += t * (a.x() + b.x()) / 3;
      my += t * (a.y() + b.y()) / 3;
    }
    const ConvexDecomposition check = decomposePolygon(points);
    if (check.error == ShapeError::CollinearPoints) continue;  // a random near-straight angle
    expectDecomposes(points, area, Vec2(Real(mx / area), Real(my / area)), std::size_t(count));
  }
}

TEST(ShapeTypesDecomposition, RefusesCrossingTooManyAndTooSmall) {
  EXPECT_EQ(
      decomposePolygon(std::vector<Vec2>{Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(0, 2)}).error,
      ShapeError::SelfIntersecting);
  EXPECT_EQ(decomposePolygon(circlePoints(kMaxConcavePoints + 1, 10)).error,
            ShapeError::TooManyConcavePoints);
  EXPECT_EQ(decomposePolygon(circlePoints(6, 0.01)).error, ShapeError::AreaOutOfRange);
  EXPECT_EQ(decomposePolygon(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0)}).error,
            ShapeError::TooFewVertices);
  EXPECT_EQ(
      decomposePolygon(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(1, 1)}).error,
      ShapeError::CollinearPoints);
}

}  // namespace
}  // namespace impulse
