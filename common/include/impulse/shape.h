#pragma once
/// Collision shapes, their validation and their exact mass properties.
///
/// A body owns exactly one shape, expressed in the body's local frame whose
/// origin is the shape's centroid (= the body's centre of mass).

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "impulse/constants.h"
#include "impulse/math.h"

namespace impulse {

enum class ShapeType : std::uint8_t { Circle = 0, Polygon = 1 };
inline constexpr int kShapeTypeCount = 2;

/// Circle centred on the body origin.
struct Circle {
  Real radius = Real(0.5);
};

/// Convex polygon, anticlockwise, centroid at the local origin.
/// normals[i] is the outward unit normal of edge vertices[i] -> vertices[i+1].
struct Polygon {
  int count = 0;
  std::array<Vec2, kMaxPolygonVertices> vertices{};
  std::array<Vec2, kMaxPolygonVertices> normals{};
};

struct Shape {
  ShapeType type = ShapeType::Circle;
  Circle circle;
  Polygon polygon;

  static Shape makeCircle(Real radius) {
    Shape s;
    s.type = ShapeType::Circle;
    s.circle.radius = radius;
    return s;
  }
  static Shape makePolygon(const Polygon& polygon) {
    Shape s;
    s.type = ShapeType::Polygon;
    s.polygon = polygon;
    return s;
  }
};

/// Area, mass and rotational inertia about the centroid.
struct MassProperties {
  Real area = 0;
  Real mass = 0;
  Real inertia = 0;
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
/// (in order, either winding) still form, or can close into, a convex polygon
/// with no duplicate or collinear points. Fewer than 3 points only need to be
/// finite and distinct. The area range is not checked here.
ShapeError checkPolygonInProgress(std::span<const Vec2> points);

/// Axis-aligned box centred on the origin.
Polygon makeBox(Real halfWidth, Real halfHeight);

/// Regular polygon with `count` vertices on a circle of `radius` around the origin.
Polygon makeRegularPolygon(int count, Real radius);

/// Exact area, mass (= area x density) and inertia about the centroid.
MassProperties computeMassProperties(const Shape& shape, Real density);

/// Tight bounding box of the shape placed at transform.
AABB computeAABB(const Shape& shape, const Transform& transform);

/// Largest distance from the centroid to any point of the shape.
Real computeExtent(const Shape& shape);

/// Smallest distance from the centroid to the shape's boundary (the radius of
/// the largest centred inscribed circle). Continuous collision uses it to tell
/// which bodies move fast relative to their size.
Real computeInnerRadius(const Shape& shape);

/// True when world point lies inside (or on) the shape at transform.
bool containsPoint(const Shape& shape, const Transform& transform, const Vec2& point);

}  // namespace impulse
