#include "impulse/shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impulse {
namespace {

// Geometry is checked and integrated in double: the engine stores float, but
// user points may sit far from the origin and cross products of their
// differences lose too many bits in single precision.
using Point = Eigen::Vector2d;

double cross2(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

Point toPoint(const Vec2& v) { return v.cast<double>(); }

// Area, centroid and polar second moment about the centroid of a polygon of
// unit density.
struct AreaMoments {
  double area = 0;
  Point centroid = Point::Zero();
  double inertia = 0;
};

// Triangle fan about the vertex mean rather than the origin: the mean lies
// inside a convex polygon, so every triangle is positive and small, and the
// sums do not cancel even when the polygon sits far from the origin.
AreaMoments computeAreaMoments(std::span<const Point> anticlockwise) {
  const int count = static_cast<int>(anticlockwise.size());
  Point reference = Point::Zero();
  for (const Point& p : anticlockwise) reference += p;
  reference /= count;

  double area = 0;
  Point firstMoment = Point::Zero();
  double inertiaAboutReference = 0;
  for (int i = 0; i < count; ++i) {
    const Point e1 = anticlockwise[i] - reference;
    const Point e2 = anticlockwise[(i + 1) % count] - reference;
    const double twiceArea = cross2(e1, e2);
    area += 0.5 * twiceArea;
    // Triangle (reference, e1, e2): centroid at (e1 + e2) / 3.
    firstMoment += (0.5 * twiceArea / 3.0) * (e1 + e2);
    const double intX2 = e1.x() * e1.x() + e2.x() * e1.x() + e2.x() * e2.x();
    const double intY2 = e1.y() * e1.y() + e2.y() * e1.y() + e2.y() * e2.y();
    inertiaAboutReference += (twiceArea / 12.0) * (intX2 + intY2);
  }

  AreaMoments moments;
  moments.area = area;
  const Point offset = firstMoment / area;
  moments.centroid = reference + offset;
  // Parallel axis theorem: move the second moment from the reference to the centroid.
  moments.inertia = inertiaAboutReference - area * offset.squaredNorm();
  return moments;
}

// Outward normals of an anticlockwise polygon: the interior lies to the left
// of each edge, so the outward side is the right perpendicular.
void computeNormals(Polygon& polygon) {
  for (int i = 0; i < polygon.count; ++i) {
    const Point edge =
        toPoint(polygon.vertices[(i + 1) % polygon.count]) - toPoint(polygon.vertices[i]);
    const Point normal = Point(edge.y(), -edge.x()).normalized();
    polygon.normals[i] = normal.cast<Real>();
  }
}

// Points closer than this are one point to the user (half the linear slop,
// far above float resolution at world scale).
constexpr double kDuplicateTolerance = 0.5 * kLinearSlop;
// A vertex this close to the line through its neighbours adds no corner, as
// Box2D's hull builder also judges with a linear tolerance.
constexpr double kCollinearTolerance = 0.5 * kLinearSlop;

// User points in double, shifted to their mean: far-off input frames then
// lose no precision in the cross products below.
struct Outline {
  int count = 0;
  std::array<Point, kMaxPolygonVertices> points{};
  Point offset = Point::Zero();

  const Point& at(int i) const { return points[(i % count + count) % count]; }
};

bool allFinite(std::span<const Vec2> points) {
  return std::all_of(points.begin(), points.end(), [](const Vec2& p) { return isFinite(p); });
}

// Requires finite points, at most kMaxPolygonVertices of them.
Outline makeOutline(std::span<const Vec2> points) {
  Outline outline;
  outline.count = static_cast<int>(points.size());
  for (const Vec2& p : points) outline.offset += toPoint(p);
  if (outline.count > 0) outline.offset /= outline.count;
  for (int i = 0; i < outline.count; ++i) outline.points[i] = toPoint(points[i]) - outline.offset;
  return outline;
}

double signedArea(const Outline& outline) {
  double twiceArea = 0;
  for (int i = 0; i < outline.count; ++i) twiceArea += cross2(outline.at(i), outline.at(i + 1));
  return 0.5 * twiceArea;
}

// Every pair, not just neighbours: a point clicked twice anywhere is a mistake.
bool hasDuplicates(const Outline& outline) {
  for (int i = 0; i < outline.count; ++i) {
    for (int j = i + 1; j < outline.count; ++j) {
      if ((outline.at(i) - outline.at(j)).norm() < kDuplicateTolerance) return true;
    }
  }
  return false;
}

// Also catches all points on one line, since then every vertex is on the
// line of its neighbours.
bool hasCollinearVertex(const Outline& outline) {
  for (int i = 0; i < outline.count; ++i) {
    const Point& previous = outline.at(i - 1);
    const Point chord = outline.at(i + 1) - previous;
    const double distance = std::abs(cross2(chord, outline.at(i) - previous)) / chord.norm();
    if (distance < kCollinearTolerance) return true;
  }
  return false;
}

int orientation(const Point& a, const Point& b, const Point& c) {
  const double turn = cross2(b - a, c - a);
  return (turn > 0) - (turn < 0);
}

// Closed segments: touching counts as crossing, since a vertex resting on
// another edge leaves no interior between them either.
bool segmentsIntersect(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int abc = orientation(a, b, c);
  const int abd = orientation(a, b, d);
  const int cda = orientation(c, d, a);
  const int cdb = orientation(c, d, b);
  if (abc * abd < 0 && cda * cdb < 0) return true;
  const auto onSegment = [](const Point& p, const Point& q, const Point& r) {
    return r.x() >= std::min(p.x(), q.x()) && r.x() <= std::max(p.x(), q.x()) &&
           r.y() >= std::min(p.y(), q.y()) && r.y() <= std::max(p.y(), q.y());
  };
  return (abc == 0 && onSegment(a, b, c)) || (abd == 0 && onSegment(a, b, d)) ||
         (cda == 0 && onSegment(c, d, a)) || (cdb == 0 && onSegment(c, d, b));
}

bool hasCrossingEdges(const Outline& outline) {
  for (int i = 0; i < outline.count; ++i) {
    // Edge j must share no vertex with edge i: skip i+1 and, for i = 0, the
    // closing edge count-1.
    for (int j = i + 2; j < outline.count; ++j) {
      if (i == 0 && j == outline.count - 1) continue;
      if (segmentsIntersect(outline.at(i), outline.at(i + 1), outline.at(j), outline.at(j + 1))) {
        return true;
      }
    }
  }
  return false;
}

// Run on a simple outline only: then every turn agreeing with the winding
// means convex.
bool hasReflexVertex(const Outline& outline) {
  const double winding = signedArea(outline);
  for (int i = 0; i < outline.count; ++i) {
    const double turn =
        cross2(outline.at(i) - outline.at(i - 1), outline.at(i + 1) - outline.at(i));
    if (turn * winding <= 0) return true;
  }
  return false;
}

// The checks buildPolygon and checkPolygonInProgress share, cheapest and most
// specific first so the user is told the most direct problem.
ShapeError checkOutline(const Outline& outline) {
  if (hasDuplicates(outline)) return ShapeError::DuplicatePoints;
  if (outline.count < kMinPolygonVertices) return ShapeError::None;
  if (hasCollinearVertex(outline)) return ShapeError::CollinearPoints;
  if (hasCrossingEdges(outline)) return ShapeError::SelfIntersecting;
  if (hasReflexVertex(outline)) return ShapeError::NonConvex;
  return ShapeError::None;
}

// Builds the stored polygon from a valid outline; returns its area.
double fillPolygon(const Outline& outline, PolygonBuild& build) {
  std::array<Point, kMaxPolygonVertices> anticlockwise{};
  const bool clockwise = signedArea(outline) < 0;
  for (int i = 0; i < outline.count; ++i) {
    // Reversal keeps point 0 first, so the user's first click stays vertex 0.
    anticlockwise[i] = outline.at(clockwise ? -i : i);
  }
  const AreaMoments moments = computeAreaMoments(std::span(anticlockwise.data(), outline.count));
  build.polygon.count = outline.count;
  for (int i = 0; i < outline.count; ++i) {
    build.polygon.vertices[i] = (anticlockwise[i] - moments.centroid).cast<Real>();
  }
  computeNormals(build.polygon);
  build.centroid = (moments.centroid + outline.offset).cast<Real>();
  return moments.area;
}

// A refused shape carries only its error, nothing a caller could misuse.
PolygonBuild refused(ShapeError error) {
  PolygonBuild build;
  build.error = error;
  return build;
}

// describe() cannot see the caller's limits; its figures quote the defaults.
static_assert(ShapeLimits{}.minArea == Real(1e-3) && ShapeLimits{}.maxArea == Real(1000));
static_assert(ShapeLimits{}.minRadius == Real(0.02) && ShapeLimits{}.maxRadius == Real(20));
static_assert(kLinearSlop == Real(0.005), "duplicate message quotes 2.5 mm");

}  // namespace

std::string_view describe(ShapeError error) {
  switch (error) {
    case ShapeError::None:
      return "shape is valid";
    case ShapeError::TooFewVertices:
      return "polygon needs at least 3 vertices";
    case ShapeError::TooManyVertices:
      return "polygon has more than 16 vertices";
    case ShapeError::NonFinite:
      return "shape has a non-finite coordinate (NaN or infinity)";
    case ShapeError::DuplicatePoints:
      return "polygon has duplicate points (closer than 2.5 mm)";
    case ShapeError::CollinearPoints:
      return "polygon has three collinear points";
    case ShapeError::SelfIntersecting:
      return "polygon edges cross each other (self-intersecting)";
    case ShapeError::NonConvex:
      return "polygon is not convex";
    case ShapeError::AreaOutOfRange:
      return "polygon area is outside the supported range (0.001 to 1000 square metres)";
    case ShapeError::RadiusOutOfRange:
      return "circle radius is outside the supported range (0.02 to 20 metres)";
  }
  return "unknown shape error";
}

Polygon makeBox(Real halfWidth, Real halfHeight) {
  Polygon box;
  box.count = 4;
  box.vertices = {Vec2(-halfWidth, -halfHeight), Vec2(halfWidth, -halfHeight),
                  Vec2(halfWidth, halfHeight), Vec2(-halfWidth, halfHeight)};
  box.normals = {Vec2(0, -1), Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0)};
  return box;
}

Polygon makeRegularPolygon(int count, Real radius) {
  // The vertex array is fixed-size: clamp rather than write past it.
  count = std::clamp(count, kMinPolygonVertices, kMaxPolygonVertices);
  Polygon polygon;
  polygon.count = count;
  const double step = 2 * std::numbers::pi / count;
  // Start half a step before straight down so edge 0 is horizontal at the
  // bottom: the shape rests flat, and count 4 gives an axis-aligned square.
  const double start = -std::numbers::pi / 2 - step / 2;
  for (int i = 0; i < count; ++i) {
    const double angle = start + i * step;
    polygon.vertices[i] = (radius * Point(std::cos(angle), std::sin(angle))).cast<Real>();
  }
  computeNormals(polygon);
  return polygon;
}

MassProperties computeMassProperties(const Shape& shape, Real density) {
  MassProperties properties;
  if (shape.type == ShapeType::Circle) {
    const double r = shape.circle.radius;
    const double area = std::numbers::pi * r * r;
    const double mass = density * area;
    properties.area = static_cast<Real>(area);
    properties.mass = static_cast<Real>(mass);
    properties.inertia = static_cast<Real>(0.5 * mass * r * r);
    return properties;
  }
  const Polygon& polygon = shape.polygon;
  std::array<Point, kMaxPolygonVertices> points;
  for (int i = 0; i < polygon.count; ++i) points[i] = toPoint(polygon.vertices[i]);
  // Inertia is about the polygon's own centroid, which by the Polygon
  // contract is the body origin.
  const AreaMoments moments = computeAreaMoments(std::span(points.data(), polygon.count));
  properties.area = static_cast<Real>(moments.area);
  properties.mass = static_cast<Real>(density * moments.area);
  properties.inertia = static_cast<Real>(density * moments.inertia);
  return properties;
}

AABB computeAABB(const Shape& shape, const Transform& transform) {
  if (shape.type == ShapeType::Circle) {
    const Vec2 r(shape.circle.radius, shape.circle.radius);
    return {transform.p - r, transform.p + r};
  }
  const Polygon& polygon = shape.polygon;
  AABB box{transform.apply(polygon.vertices[0]), transform.apply(polygon.vertices[0])};
  for (int i = 1; i < polygon.count; ++i) {
    const Vec2 v = transform.apply(polygon.vertices[i]);
    box.lower = box.lower.cwiseMin(v);
    box.upper = box.upper.cwiseMax(v);
  }
  return box;
}

Real computeExtent(const Shape& shape) {
  if (shape.type == ShapeType::Circle) return shape.circle.radius;
  Real extent = 0;
  for (int i = 0; i < shape.polygon.count; ++i) {
    extent = std::max(extent, shape.polygon.vertices[i].norm());
  }
  return extent;
}

Real computeInnerRadius(const Shape& shape) {
  if (shape.type == ShapeType::Circle) return shape.circle.radius;
  // For a convex polygon around the origin, the nearest boundary point lies on
  // the nearest edge line, at distance n . v from the origin.
  const Polygon& polygon = shape.polygon;
  Real inner = polygon.normals[0].dot(polygon.vertices[0]);
  for (int i = 1; i < polygon.count; ++i) {
    inner = std::min(inner, polygon.normals[i].dot(polygon.vertices[i]));
  }
  return inner;
}

bool containsPoint(const Shape& shape, const Transform& transform, const Vec2& point) {
  const Vec2 local = transform.applyInverse(point);
  if (shape.type == ShapeType::Circle) {
    return local.squaredNorm() <= shape.circle.radius * shape.circle.radius;
  }
  const Polygon& polygon = shape.polygon;
  for (int i = 0; i < polygon.count; ++i) {
    if (polygon.normals[i].dot(local - polygon.vertices[i]) > 0) return false;
  }
  return true;
}

PolygonBuild buildPolygon(std::span<const Vec2> points, const ShapeLimits& limits) {
  if (points.size() < kMinPolygonVertices) return refused(ShapeError::TooFewVertices);
  if (points.size() > kMaxPolygonVertices) return refused(ShapeError::TooManyVertices);
  if (!allFinite(points)) return refused(ShapeError::NonFinite);
  const Outline outline = makeOutline(points);
  if (const ShapeError error = checkOutline(outline); error != ShapeError::None) {
    return refused(error);
  }
  PolygonBuild build;
  const double area = fillPolygon(outline, build);
  if (area < limits.minArea || area > limits.maxArea) return refused(ShapeError::AreaOutOfRange);
  return build;
}

ShapeError validateCircle(Real radius, const ShapeLimits& limits) {
  if (!isFinite(radius)) return ShapeError::NonFinite;
  if (radius < limits.minRadius || radius > limits.maxRadius) return ShapeError::RadiusOutOfRange;
  return ShapeError::None;
}

ShapeError checkPolygonInProgress(std::span<const Vec2> points) {
  if (points.size() > kMaxPolygonVertices) return ShapeError::TooManyVertices;
  if (!allFinite(points)) return ShapeError::NonFinite;
  return checkOutline(makeOutline(points));
}

}  // namespace impulse
