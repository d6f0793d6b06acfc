#pragma once
/// Collision shapes, their validation and their exact mass properties.
///
/// Shapes are expressed in their body's frame, whose origin is the body's
/// centre of mass.

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <variant>
#include <vector>

#include "impulse/constants.h"
#include "impulse/math.h"

namespace impulse {

/// The kinds of shape, in the order of Shape's alternatives. The collide
/// table (shape_pair.cpp) is indexed by two of these and checked at compile
/// time to hold an entry for every pair.
enum class ShapeType : std::uint8_t {
  Circle = 0,
  Capsule = 1,
  Segment = 2,
  Polygon = 3,
  ChainSegment = 4
};
inline constexpr int kShapeTypeCount = 5;

/// Circle in the body's frame.
struct Circle {
  Vec2 center = Vec2::Zero();
  Real radius = Real(0.5);
};

/// The points within `radius` of the segment center1-center2: a stadium.
struct Capsule {
  Vec2 center1 = Vec2::Zero();
  Vec2 center2 = Vec2::Zero();
  Real radius = Real(0.25);
};

/// A line segment: no area and no mass, for static terrain and walls.
struct Segment {
  Vec2 point1 = Vec2::Zero();
  Vec2 point2 = Vec2::Zero();
};

/// Convex polygon, anticlockwise, in the body's frame, optionally rounded:
/// the shape is every point within `radius` of the polygon.
/// normals[i] is the outward unit normal of edge vertices[i] -> vertices[i+1].
struct Polygon {
  int count = 0;
  std::array<Vec2, kMaxPolygonVertices> vertices{};
  std::array<Vec2, kMaxPolygonVertices> normals{};
  Vec2 centroid = Vec2::Zero();
  Real radius = 0;
};

/// One segment of a chain: collides on its right side only (the outside of
/// an anticlockwise loop), and its neighbours' far ends (the ghost vertices)
/// let it ignore contacts that belong to the next segment, so a body slides
/// over the joins without catching.
struct ChainSegment {
  Vec2 ghost1 = Vec2::Zero();
  Segment segment;
  Vec2 ghost2 = Vec2::Zero();
  /// The chain this segment belongs to (shapes of one chain never collide).
  std::int32_t chainId = -1;
};

/// A shape's geometry in its body's frame; the alternative's index is its
/// ShapeType.
struct Shape {
  std::variant<Circle, Capsule, Segment, Polygon, ChainSegment> geometry;

  ShapeType type() const { return static_cast<ShapeType>(geometry.index()); }
  const Circle& circle() const { return std::get<Circle>(geometry); }
  const Capsule& capsule() const { return std::get<Capsule>(geometry); }
  const Segment& segment() const { return std::get<Segment>(geometry); }
  const Polygon& polygon() const { return std::get<Polygon>(geometry); }
  const ChainSegment& chainSegment() const { return std::get<ChainSegment>(geometry); }

  static Shape makeCircle(Real radius, const Vec2& center = Vec2::Zero()) {
    return {Circle{center, radius}};
  }
  static Shape makePolygon(const Polygon& polygon) { return {polygon}; }
  static Shape makeCapsule(const Vec2& center1, const Vec2& center2, Real radius) {
    return {Capsule{center1, center2, radius}};
  }
  static Shape makeSegment(const Vec2& point1, const Vec2& point2) {
    return {Segment{point1, point2}};
  }
};

/// Shape types with area (and so mass): circles, capsules and polygons.
/// Segments and chains are boundaries: static terrain, or massless parts.
constexpr bool isSolid(ShapeType type) {
  return type == ShapeType::Circle || type == ShapeType::Capsule || type == ShapeType::Polygon;
}

/// Area, mass and rotational inertia about the centroid.
struct MassProperties {
  Real area = 0;
  Real mass = 0;
  Real inertia = 0;            ///< about `center`
  Vec2 center = Vec2::Zero();  ///< centroid in the body's frame
};

/// Ranges a shape must fall in. Defaults suit scenes of tens of metres.
struct ShapeLimits {
  Real minRadius = Real(0.02);
  Real maxRadius = Real(20);
  Real minArea = Real(1e-3);
  Real maxArea = Real(1000);
};

/// Every reason a shape is refused; each has its own message (describe()).
enum class ShapeError : std::uint8_t {
  None,
  TooFewVertices,
  TooManyVertices,
  NonFinite,
  DuplicatePoints,
  CollinearPoints,
  SelfIntersecting,
  NonConvex,
  AreaOutOfRange,
  RadiusOutOfRange,
  SegmentTooShort,    ///< segment, or a capsule's centres, closer than the linear slop
  ChainTooFewPoints,  ///< a chain needs 4 points or more
  ChainTooManyPoints,
  ChainCrossing,             ///< two segments of a chain cross or fold back
  CapsuleRadiusOutOfRange,   ///< outside [minRadius, maxRadius]
  RoundingRadiusOutOfRange,  ///< a polygon's rounding radius outside [0, maxRadius]
  Clockwise,                 ///< a stored polygon's vertices run clockwise
  BadNormals,                ///< a stored polygon's normals are not its edges' outward unit normals
  TooManyConcavePoints,      ///< decomposePolygon takes at most kMaxConcavePoints
  BadCentroid,               ///< a stored polygon's centroid is not its vertices' centroid
};

/// A readable sentence naming the problem, suitable to show to a user as is.
std::string_view describe(ShapeError error);

/// Result of building a polygon from user points.
struct PolygonBuild {
  ShapeError error = ShapeError::None;
  /// Valid only when error == None: local, anticlockwise, centroid at origin.
  Polygon polygon;
  /// Centroid of the input points' polygon, in the input frame.
  Vec2 centroid = Vec2::Zero();
};

/// Validates points (either winding, in any frame) and builds the polygon.
PolygonBuild buildPolygon(std::span<const Vec2> points, const ShapeLimits& limits = {});

/// Validates a circle radius.
ShapeError validateCircle(Real radius, const ShapeLimits& limits = {});

/// For interactive drawing: ShapeError::None when the points placed so far
/// (in order, either winding) still form, or can close into, a simple polygon
/// (convex or not: World::createPolygon splits a concave one) with no
/// crossing edges and no duplicate or collinear points. Fewer than 3 points only need to be
/// finite and distinct. The area range is not checked here.
ShapeError checkPolygonInProgress(std::span<const Vec2> points);

/// Axis-aligned box centred on the origin.
Polygon makeBox(Real halfWidth, Real halfHeight);

/// Regular polygon with `count` vertices on a circle of `radius` around the origin.
Polygon makeRegularPolygon(int count, Real radius);

/// The area centroid of a polygon's core (its vertices), whatever their
/// frame: what Polygon::centroid must hold when a polygon is made from points
/// that buildPolygon did not centre (validateShape refuses a stale one).
/// Zero for a count outside 3..16.
Vec2 computePolygonCentroid(const Polygon& polygon);

/// Validates any shape: finite numbers, radii and areas in range, segments
/// and capsules longer than the linear slop, polygons anticlockwise,
/// strictly convex, with distinct points, their edges' outward unit normals
/// and their vertices' centroid (within 1 mm per metre of size). Unlike a
/// user's drawing, a stored polygon (a decomposition's piece) may have three
/// nearly collinear points.
ShapeError validateShape(const Shape& shape, const ShapeLimits& limits = {});

/// A chain's points, in order, made into one-sided segments with ghost
/// vertices. Open: segment i joins points i and i+1, the first and last
/// points only serve as ghosts (count - 3 segments). Loop: every point joins
/// the next, the last joins the first (count segments). Refused with the
/// error: fewer than 4 or more than kMaxChainPoints points, non-finite or
/// duplicate neighbours, segments crossing each other.
struct ChainBuild {
  ShapeError error = ShapeError::None;
  std::vector<ChainSegment> segments;
};
inline constexpr int kMaxChainPoints = 1024;
ChainBuild buildChain(std::span<const Vec2> points, bool loop);

/// A simple (not self-intersecting) polygon, convex or not, split into
/// convex pieces of at most kMaxPolygonVertices vertices, in the input frame
/// (each piece anticlockwise, its centroid field set). Ear clipping, then
/// Hertel-Mehlhorn merging: at most four times the fewest pieces possible.
/// Refused like buildPolygon (duplicate, collinear, crossing points); the
/// area range applies to the whole polygon, not to each piece.
struct ConvexDecomposition {
  ShapeError error = ShapeError::None;
  std::vector<Polygon> pieces;
};
inline constexpr int kMaxConcavePoints = 256;
ConvexDecomposition decomposePolygon(std::span<const Vec2> points, const ShapeLimits& limits = {});

/// Exact area, mass (= area x density), centroid and inertia about the
/// centroid. Segments and chain segments have none (zero area and mass).
MassProperties computeMassProperties(const Shape& shape, Real density);

/// The union of parts (each about its own centroid): total mass, the
/// mass-weighted centroid and the inertia about it (parallel axis theorem).
MassProperties combineMassProperties(std::span<const MassProperties> parts);

/// The shape moved by `offset` in its body's frame (used when the body's
/// centre of mass moves because a shape was added or removed).
Shape translated(const Shape& shape, const Vec2& offset);

/// Tight bounding box of the shape placed at transform.
AABB computeAABB(const Shape& shape, const Transform& transform);

/// Largest distance from the body origin to any point of the shape.
Real computeExtent(const Shape& shape);

/// How thin the shape is: the smallest distance from its own centroid to
/// its boundary (0 for segments). Continuous collision uses it to tell which
/// bodies move fast relative to their size.
Real computeInnerRadius(const Shape& shape);

/// True when world point lies inside (or on) the shape at transform
/// (never for segments and chain segments, which have no inside).
bool containsPoint(const Shape& shape, const Transform& transform, const Vec2& point);

}  // namespace impulse
