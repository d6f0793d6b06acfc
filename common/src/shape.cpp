#include "impulse/shape.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "shape_ref.h"

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

// A polygon's points closer than this are one point to the user, and a
// vertex this close to the line through its neighbours adds no corner (as
// Box2D's hull builder also judges, with a linear tolerance). A tenth of
// the linear slop: far above float resolution at world scale, so slivers
// and repeated clicks are refused, yet below a playing card's 2 mm, which
// a house of cards is built from.
constexpr double kPolygonPointTolerance = 0.1 * kLinearSlop;

// Points of a closed outline, read with wrap-around indices.
class Ring {
 public:
  explicit Ring(std::span<const Point> points) : points_(points) {}
  int size() const { return static_cast<int>(points_.size()); }
  const Point& at(int i) const {
    const int n = size();
    return points_[static_cast<std::size_t>((i % n + n) % n)];
  }

 private:
  std::span<const Point> points_;
};

// User points in double, shifted to their mean: far-off input frames then
// lose no precision in the cross products below.
struct Outline {
  int count = 0;
  std::array<Point, kMaxPolygonVertices> points{};
  Point offset = Point::Zero();

  Ring ring() const { return Ring(std::span(points.data(), static_cast<std::size_t>(count))); }
};

bool allFinite(std::span<const Vec2> points) {
  return std::all_of(points.begin(), points.end(), [](const Vec2& p) { return isFinite(p); });
}

Point meanOf(std::span<const Vec2> points) {
  Point mean = Point::Zero();
  for (const Vec2& p : points) mean += toPoint(p);
  return points.empty() ? mean : Point(mean / static_cast<double>(points.size()));
}

// Requires finite points, at most kMaxPolygonVertices of them.
Outline makeOutline(std::span<const Vec2> points) {
  Outline outline;
  outline.count = static_cast<int>(points.size());
  outline.offset = meanOf(points);
  for (int i = 0; i < outline.count; ++i) outline.points[i] = toPoint(points[i]) - outline.offset;
  return outline;
}

double signedArea(const Ring& ring) {
  double twiceArea = 0;
  for (int i = 0; i < ring.size(); ++i) twiceArea += cross2(ring.at(i), ring.at(i + 1));
  return 0.5 * twiceArea;
}

// Every pair, not just neighbours: a point clicked twice anywhere is a mistake.
bool hasDuplicates(const Ring& ring) {
  for (int i = 0; i < ring.size(); ++i) {
    for (int j = i + 1; j < ring.size(); ++j) {
      if ((ring.at(i) - ring.at(j)).norm() < kPolygonPointTolerance) return true;
    }
  }
  return false;
}

// Distance from b to the line through a and c.
double distanceToChord(const Point& a, const Point& b, const Point& c) {
  const Point chord = c - a;
  return std::abs(cross2(chord, b - a)) / chord.norm();
}

// Also catches all points on one line, since then every vertex is on the
// line of its neighbours.
bool hasCollinearVertex(const Ring& ring) {
  for (int i = 0; i < ring.size(); ++i) {
    if (distanceToChord(ring.at(i - 1), ring.at(i), ring.at(i + 1)) < kPolygonPointTolerance) {
      return true;
    }
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

bool hasCrossingEdges(const Ring& ring) {
  const int count = ring.size();
  for (int i = 0; i < count; ++i) {
    // Edge j must share no vertex with edge i: skip i+1 and, for i = 0, the
    // closing edge count-1.
    for (int j = i + 2; j < count; ++j) {
      if (i == 0 && j == count - 1) continue;
      if (segmentsIntersect(ring.at(i), ring.at(i + 1), ring.at(j), ring.at(j + 1))) return true;
    }
  }
  return false;
}

// Run on a simple outline only: then every turn agreeing with the winding
// means convex.
bool hasReflexVertex(const Ring& ring) {
  const double winding = signedArea(ring);
  for (int i = 0; i < ring.size(); ++i) {
    const double turn = cross2(ring.at(i) - ring.at(i - 1), ring.at(i + 1) - ring.at(i));
    if (turn * winding <= 0) return true;
  }
  return false;
}

// The checks of a simple polygon, cheapest and most specific first so the
// user is told the most direct problem.
ShapeError checkSimple(const Ring& ring) {
  if (hasDuplicates(ring)) return ShapeError::DuplicatePoints;
  if (ring.size() < kMinPolygonVertices) return ShapeError::None;
  if (hasCollinearVertex(ring)) return ShapeError::CollinearPoints;
  if (hasCrossingEdges(ring)) return ShapeError::SelfIntersecting;
  return ShapeError::None;
}

// The checks buildPolygon and checkPolygonInProgress share.
ShapeError checkOutline(const Outline& outline) {
  if (const ShapeError error = checkSimple(outline.ring()); error != ShapeError::None) return error;
  if (outline.count >= kMinPolygonVertices && hasReflexVertex(outline.ring())) {
    return ShapeError::NonConvex;
  }
  return ShapeError::None;
}

// Builds the stored polygon from a valid outline; returns its area.
double fillPolygon(const Outline& outline, PolygonBuild& build) {
  std::array<Point, kMaxPolygonVertices> anticlockwise{};
  const Ring ring = outline.ring();
  const bool clockwise = signedArea(ring) < 0;
  for (int i = 0; i < outline.count; ++i) {
    // Reversal keeps point 0 first, so the user's first click stays vertex 0.
    anticlockwise[i] = ring.at(clockwise ? -i : i);
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
static_assert(kLinearSlop == Real(0.005), "duplicate message quotes 0.5 mm");

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
      return "polygon has duplicate points (closer than 0.5 mm)";
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
    case ShapeError::SegmentTooShort:
      return "segment is shorter than 5 mm: its two points (a capsule's two centres, a chain's "
             "neighbouring points) must be at least 5 mm apart";
    case ShapeError::ChainTooFewPoints:
      return "chain needs at least 4 points: an open chain's first and last points only guide "
             "its ends, so it needs 2 more than its segments";
    case ShapeError::ChainTooManyPoints:
      return "chain has more than 1024 points";
    case ShapeError::ChainCrossing:
      return "chain crosses itself: two of its segments cross, touch or fold back onto each other";
    case ShapeError::CapsuleRadiusOutOfRange:
      return "capsule radius is outside the supported range (0.02 to 20 metres)";
    case ShapeError::RoundingRadiusOutOfRange:
      return "polygon rounding radius is outside the supported range (0 to 20 metres)";
    case ShapeError::Clockwise:
      return "polygon vertices run clockwise: they must run anticlockwise";
    case ShapeError::BadNormals:
      return "polygon normals are not the outward unit normals of its edges";
    case ShapeError::TooManyConcavePoints:
      return "concave polygon has more than 256 points";
    case ShapeError::BadCentroid:
      return "polygon centroid is not the centroid of its vertices";
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

namespace {

// Area, first moment and polar second moment about a reference point, of
// unit density: pieces given this way add up.
struct Moments {
  double area = 0;
  Point firstMoment = Point::Zero();  // area x centroid, relative to the reference
  double polar = 0;                   // second moment about the reference

  void addPiece(double pieceArea, const Point& centroid, double inertiaAboutCentroid) {
    area += pieceArea;
    firstMoment += pieceArea * centroid;
    polar += inertiaAboutCentroid + pieceArea * centroid.squaredNorm();
  }
};

MassProperties toMassProperties(double area, double density, const Point& center,
                                double inertiaPerDensity) {
  MassProperties properties;
  properties.area = static_cast<Real>(area);
  properties.mass = static_cast<Real>(density * area);
  properties.inertia = static_cast<Real>(density * inertiaPerDensity);
  properties.center = center.cast<Real>();
  return properties;
}

MassProperties circleMass(const Circle& circle, double density) {
  const double r = circle.radius;
  const double area = std::numbers::pi * r * r;
  const double mass = density * area;
  MassProperties properties;
  properties.area = static_cast<Real>(area);
  properties.mass = static_cast<Real>(mass);
  properties.inertia = static_cast<Real>(0.5 * mass * r * r);
  properties.center = circle.center;
  return properties;
}

// A rectangle of length L and width 2r, and the two half discs that close it
// (together one disc). A half disc's centroid lies 4r / (3 pi) from its flat
// side; its inertia about the flat side's midpoint is r^2/2 per unit area,
// moved to its centroid and then to the capsule's centre (parallel axis).
MassProperties capsuleMass(const Capsule& capsule, double density) {
  const Point c1 = toPoint(capsule.center1);
  const Point c2 = toPoint(capsule.center2);
  const double r = capsule.radius;
  const double length = (c2 - c1).norm();
  const double boxArea = 2 * r * length;
  const double boxInertia = boxArea * (length * length + 4 * r * r) / 12;
  const double halfDiscArea = 0.5 * std::numbers::pi * r * r;
  const double centroidOffset = 4 * r / (3 * std::numbers::pi);
  const double distance = 0.5 * length + centroidOffset;
  const double halfDiscInertia =
      halfDiscArea * (0.5 * r * r - centroidOffset * centroidOffset + distance * distance);
  return toMassProperties(boxArea + 2 * halfDiscArea, density, 0.5 * (c1 + c2),
                          boxInertia + 2 * halfDiscInertia);
}

// The rounded polygon is its core, a rectangle of width `radius` on each edge
// and a circular sector at each vertex (the sectors' angles add to a full
// turn). Each piece is exact; they are summed about the core's vertex mean.
MassProperties polygonMass(const Polygon& polygon, double density) {
  std::array<Point, kMaxPolygonVertices> points;
  for (int i = 0; i < polygon.count; ++i) points[i] = toPoint(polygon.vertices[i]);
  const std::span<const Point> core(points.data(), static_cast<std::size_t>(polygon.count));
  const AreaMoments coreMoments = computeAreaMoments(core);
  double area = coreMoments.area;
  Point center = coreMoments.centroid;
  double inertia = coreMoments.inertia;

  const double r = polygon.radius;
  if (r > 0) {
    const Point reference = coreMoments.centroid;
    Moments sum;
    sum.addPiece(coreMoments.area, Point::Zero(), coreMoments.inertia);
    const Ring ring(core);
    for (int i = 0; i < polygon.count; ++i) {
      const Point v0 = ring.at(i) - reference;
      const Point v1 = ring.at(i + 1) - reference;
      const Point edge = v1 - v0;
      const Point normal = Point(edge.y(), -edge.x()).normalized();
      const std::array<Point, 4> strip = {v0, v0 + r * normal, v1 + r * normal, v1};
      const AreaMoments stripMoments = computeAreaMoments(strip);
      sum.addPiece(stripMoments.area, stripMoments.centroid, stripMoments.inertia);

      // The sector at v1 spans from this edge's normal to the next one's.
      const Point next = ring.at(i + 2) - reference - v1;
      const Point nextNormal = Point(next.y(), -next.x()).normalized();
      const double angle = std::atan2(cross2(normal, nextNormal), normal.dot(nextNormal));
      const double sectorArea = 0.5 * angle * r * r;
      const Point bisector = (normal + nextNormal).normalized();
      const double apexToCentroid = 4 * r * std::sin(0.5 * angle) / (3 * angle);
      // Polar moment about the apex is r^2/2 per unit area; move it to the centroid.
      const double sectorInertia = sectorArea * (0.5 * r * r - apexToCentroid * apexToCentroid);
      sum.addPiece(sectorArea, v1 + apexToCentroid * bisector, sectorInertia);
    }
    area = sum.area;
    const Point offset = sum.firstMoment / sum.area;
    center = reference + offset;
    inertia = sum.polar - sum.area * offset.squaredNorm();
  }

  // The stored centroid is exact by construction (buildPolygon centres the
  // polygon on the origin); a computed one within float noise of it is that
  // noise, and keeping the stored value keeps a centred body where it is.
  const double size = std::sqrt(area);
  if ((center - toPoint(polygon.centroid)).norm() <= 1e-6 * size) {
    center = toPoint(polygon.centroid);
  }
  return toMassProperties(area, density, center, inertia);
}

template <class... Handlers>
struct Overloaded : Handlers... {
  using Handlers::operator()...;
};
template <class... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

// A chain segment's geometry proper: its ghosts only steer collisions.
const Segment& lineOf(const Segment& segment) { return segment; }
const Segment& lineOf(const ChainSegment& chain) { return chain.segment; }

AABB boxAround(std::span<const Vec2> points, const Transform& transform, Real radius) {
  AABB box{transform.apply(points[0]), transform.apply(points[0])};
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vec2 v = transform.apply(points[i]);
    box.lower = box.lower.cwiseMin(v);
    box.upper = box.upper.cwiseMax(v);
  }
  return box.expanded(radius);
}

Real distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 edge = b - a;
  const Real lengthSquared = edge.squaredNorm();
  const Real fraction =
      lengthSquared > 0 ? std::clamp((p - a).dot(edge) / lengthSquared, Real(0), Real(1)) : Real(0);
  return (p - (a + fraction * edge)).norm();
}

bool finitePolygon(const Polygon& polygon) {
  for (int i = 0; i < polygon.count; ++i) {
    if (!isFinite(polygon.vertices[i]) || !isFinite(polygon.normals[i])) return false;
  }
  return isFinite(polygon.centroid) && isFinite(polygon.radius);
}

// Stored normals within this of the recomputed ones pass (float round-off
// of the caller's own computation is far below it).
constexpr double kNormalTolerance = 1e-3;
// A stored centroid may be off by this per metre of the polygon's size: far
// above float round-off, far below anything that changes how it collides
// (chain segments use it to tell which side a polygon is on).
constexpr double kCentroidTolerance = 1e-3;

ShapeError validatePolygon(const Polygon& polygon, const ShapeLimits& limits) {
  if (polygon.count < kMinPolygonVertices) return ShapeError::TooFewVertices;
  if (polygon.count > kMaxPolygonVertices) return ShapeError::TooManyVertices;
  if (!finitePolygon(polygon)) return ShapeError::NonFinite;
  if (polygon.radius < 0 || polygon.radius > limits.maxRadius) {
    return ShapeError::RoundingRadiusOutOfRange;
  }
  const std::span<const Vec2> vertices(polygon.vertices.data(),
                                       static_cast<std::size_t>(polygon.count));
  const Outline outline = makeOutline(vertices);
  // Not the collinear rule of user drawings: a stored polygon only needs
  // distinct points and strictly convex turns (a convex decomposition's
  // piece may keep a vertex a millimetre off its neighbours' chord).
  if (hasDuplicates(outline.ring())) return ShapeError::DuplicatePoints;
  if (hasCrossingEdges(outline.ring())) return ShapeError::SelfIntersecting;
  if (hasReflexVertex(outline.ring())) return ShapeError::NonConvex;
  if (signedArea(outline.ring()) < 0) return ShapeError::Clockwise;
  for (int i = 0; i < polygon.count; ++i) {
    const Point edge = outline.ring().at(i + 1) - outline.ring().at(i);
    const Point normal = Point(edge.y(), -edge.x()).normalized();
    if ((toPoint(polygon.normals[i]) - normal).norm() > kNormalTolerance) {
      return ShapeError::BadNormals;
    }
  }
  const AreaMoments core = computeAreaMoments(std::span(outline.points.data(), outline.count));
  const Point centroid = core.centroid + outline.offset;
  if ((centroid - toPoint(polygon.centroid)).norm() > kCentroidTolerance * std::sqrt(core.area)) {
    return ShapeError::BadCentroid;
  }
  const double area = computeMassProperties(Shape::makePolygon(polygon), 1).area;
  if (area < limits.minArea || area > limits.maxArea) return ShapeError::AreaOutOfRange;
  return ShapeError::None;
}

ShapeError validateLine(const Segment& segment) {
  if (!isFinite(segment.point1) || !isFinite(segment.point2)) return ShapeError::NonFinite;
  if ((toPoint(segment.point2) - toPoint(segment.point1)).norm() < kLinearSlop) {
    return ShapeError::SegmentTooShort;
  }
  return ShapeError::None;
}

}  // namespace

Vec2 computePolygonCentroid(const Polygon& polygon) {
  // Counts outside the array come from unchecked input: no centroid to give.
  if (polygon.count < kMinPolygonVertices || polygon.count > kMaxPolygonVertices) {
    return Vec2::Zero();
  }
  const Outline outline =
      makeOutline(std::span(polygon.vertices.data(), static_cast<std::size_t>(polygon.count)));
  const AreaMoments core = computeAreaMoments(std::span(outline.points.data(), outline.count));
  return (core.centroid + outline.offset).cast<Real>();
}

ShapeError validateShape(const Shape& shape, const ShapeLimits& limits) {
  return std::visit(
      Overloaded{
          [&](const Circle& circle) {
            if (!isFinite(circle.center)) return ShapeError::NonFinite;
            return validateCircle(circle.radius, limits);
          },
          [&](const Capsule& capsule) {
            if (!isFinite(capsule.radius)) return ShapeError::NonFinite;
            if (const ShapeError error = validateLine({capsule.center1, capsule.center2});
                error != ShapeError::None) {
              return error;
            }
            if (capsule.radius < limits.minRadius || capsule.radius > limits.maxRadius) {
              return ShapeError::CapsuleRadiusOutOfRange;
            }
            return ShapeError::None;
          },
          [&](const Segment& segment) { return validateLine(segment); },
          [&](const Polygon& polygon) { return validatePolygon(polygon, limits); },
          [&](const ChainSegment& chain) {
            if (!isFinite(chain.ghost1) || !isFinite(chain.ghost2)) return ShapeError::NonFinite;
            return validateLine(chain.segment);
          },
      },
      shape.geometry);
}

ShapeRef refOf(const Shape& shape) {
  return std::visit([&](const auto& geometry) { return ShapeRef{shape.type(), &geometry}; },
                    shape.geometry);
}

Shape shapeOf(ShapeRef shape) {
  return visitGeometry(shape, [](const auto& geometry) { return Shape{geometry}; });
}

MassProperties computeMassProperties(const Shape& shape, Real density) {
  return computeMassProperties(refOf(shape), density);
}

MassProperties computeMassProperties(ShapeRef shape, Real density) {
  return visitGeometry(shape, Overloaded{
                        [&](const Circle& circle) { return circleMass(circle, density); },
                        [&](const Capsule& capsule) { return capsuleMass(capsule, density); },
                        [&](const Polygon& polygon) { return polygonMass(polygon, density); },
                        [](const auto&) { return MassProperties{}; },
                    });
}

// Sums in double: a single part comes back exactly as it went in, since
// m * c / m and I + m * 0 are exact for float inputs.
MassProperties combineMassProperties(std::span<const MassProperties> parts) {
  double area = 0;
  double mass = 0;
  Point firstMoment = Point::Zero();
  for (const MassProperties& part : parts) {
    area += part.area;
    mass += part.mass;
    firstMoment += static_cast<double>(part.mass) * toPoint(part.center);
  }
  MassProperties total;
  total.area = static_cast<Real>(area);
  total.mass = static_cast<Real>(mass);
  if (mass <= 0) return total;
  const Point center = firstMoment / mass;
  double inertia = 0;
  for (const MassProperties& part : parts) {
    inertia += part.inertia + part.mass * (toPoint(part.center) - center).squaredNorm();
  }
  total.inertia = static_cast<Real>(inertia);
  total.center = center.cast<Real>();
  return total;
}

Shape translated(const Shape& shape, const Vec2& offset) {
  Shape moved = shape;
  std::visit(Overloaded{
                 [&](Circle& circle) { circle.center += offset; },
                 [&](Capsule& capsule) {
                   capsule.center1 += offset;
                   capsule.center2 += offset;
                 },
                 [&](Segment& segment) {
                   segment.point1 += offset;
                   segment.point2 += offset;
                 },
                 [&](Polygon& polygon) {
                   for (int i = 0; i < polygon.count; ++i) polygon.vertices[i] += offset;
                   polygon.centroid += offset;
                 },
                 [&](ChainSegment& chain) {
                   chain.ghost1 += offset;
                   chain.segment.point1 += offset;
                   chain.segment.point2 += offset;
                   chain.ghost2 += offset;
                 },
             },
             moved.geometry);
  return moved;
}

AABB computeAABB(const Shape& shape, const Transform& transform) {
  return computeAABB(refOf(shape), transform);
}

AABB computeAABB(ShapeRef shape, const Transform& transform) {
  return visitGeometry(
      shape,
      Overloaded{
          [&](const Circle& circle) {
            // A centred circle (the common case) skips the rotation.
            const Vec2 center =
                circle.center.isZero() ? transform.p : transform.apply(circle.center);
            const Vec2 r(circle.radius, circle.radius);
            return AABB{center - r, center + r};
          },
          [&](const Capsule& capsule) {
            const std::array<Vec2, 2> centers = {capsule.center1, capsule.center2};
            return boxAround(centers, transform, capsule.radius);
          },
          [&](const Polygon& polygon) {
            return boxAround(std::span(polygon.vertices.data(), polygon.count), transform,
                             polygon.radius);
          },
          [&](const auto& line) {
            const std::array<Vec2, 2> points = {lineOf(line).point1, lineOf(line).point2};
            return boxAround(points, transform, 0);
          },
      });
}

Real computeExtent(const Shape& shape) { return computeExtent(refOf(shape)); }

Real computeExtent(ShapeRef shape) {
  return visitGeometry(shape, Overloaded{
                        [](const Circle& circle) { return circle.center.norm() + circle.radius; },
                        [](const Capsule& capsule) {
                          return std::max(capsule.center1.norm(), capsule.center2.norm()) +
                                 capsule.radius;
                        },
                        [](const Polygon& polygon) {
                          Real extent = 0;
                          for (int i = 0; i < polygon.count; ++i) {
                            extent = std::max(extent, polygon.vertices[i].norm());
                          }
                          return extent + polygon.radius;
                        },
                        [](const auto& line) {
                          return std::max(lineOf(line).point1.norm(), lineOf(line).point2.norm());
                        },
                    });
}

Real computeInnerRadius(const Shape& shape) { return computeInnerRadius(refOf(shape)); }

Real computeInnerRadius(ShapeRef shape) {
  return visitGeometry(
      shape,
      Overloaded{
          [](const Circle& circle) { return circle.radius; },
          [](const Capsule& capsule) { return capsule.radius; },
          [](const Polygon& polygon) {
            // For a convex polygon around its centroid, the nearest boundary
            // point lies on the nearest edge line, at distance n . (v - c).
            Real inner = polygon.normals[0].dot(polygon.vertices[0] - polygon.centroid);
            for (int i = 1; i < polygon.count; ++i) {
              inner =
                  std::min(inner, polygon.normals[i].dot(polygon.vertices[i] - polygon.centroid));
            }
            return inner + polygon.radius;
          },
          [](const auto&) { return Real(0); },
      });
}

bool containsPoint(const Shape& shape, const Transform& transform, const Vec2& point) {
  return containsPoint(refOf(shape), transform, point);
}

bool containsPoint(ShapeRef shape, const Transform& transform, const Vec2& point) {
  const Vec2 local = transform.applyInverse(point);
  return visitGeometry(
      shape,
      Overloaded{
          [&](const Circle& circle) {
            return (local - circle.center).squaredNorm() <= circle.radius * circle.radius;
          },
          [&](const Capsule& capsule) {
            return distanceToSegment(local, capsule.center1, capsule.center2) <= capsule.radius;
          },
          [&](const Polygon& polygon) {
            Real deepest = -std::numeric_limits<Real>::max();
            for (int i = 0; i < polygon.count; ++i) {
              deepest = std::max(deepest, polygon.normals[i].dot(local - polygon.vertices[i]));
            }
            if (deepest <= 0) return true;
            if (polygon.radius <= 0 || deepest > polygon.radius) return false;
            // Outside the core but within the rounding band of its faces:
            // the nearest core point decides.
            Real distance = std::numeric_limits<Real>::max();
            for (int i = 0; i < polygon.count; ++i) {
              distance =
                  std::min(distance, distanceToSegment(local, polygon.vertices[i],
                                                       polygon.vertices[(i + 1) % polygon.count]));
            }
            return distance <= polygon.radius;
          },
          [](const auto&) { return false; },
      });
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
  // Concave outlines are welcome (the world splits them); crossing ones not.
  return checkSimple(makeOutline(points).ring());
}

namespace {

// Neighbouring chain points closer than this make a segment too short to
// give a direction; the same slop capsules and segments are held to.
constexpr double kChainPointSpacing = kLinearSlop;

// Edges a and b of a chain (a before b) share vertex `joint`: they fold back
// when b leaves the joint along a, reversed and within half the linear slop
// of collinear.
constexpr double kChainFoldTolerance = 0.5 * kLinearSlop;

bool foldsBack(const Point& before, const Point& joint, const Point& after) {
  const Point in = joint - before;
  const Point out = after - joint;
  return in.dot(out) < 0 && std::abs(cross2(in, out)) <= kChainFoldTolerance * out.norm();
}

// Every edge of the polyline against every other edge that shares no point
// with it; neighbours only for folding back.
bool chainCrosses(std::span<const Point> points, bool loop) {
  const int count = static_cast<int>(points.size());
  const int edges = loop ? count : count - 1;
  const Ring ring(points);
  for (int i = 0; i < edges; ++i) {
    if ((loop || i + 2 < count) && foldsBack(ring.at(i), ring.at(i + 1), ring.at(i + 2))) {
      return true;
    }
    for (int j = i + 2; j < edges; ++j) {
      if (loop && i == 0 && j == count - 1) continue;
      if (segmentsIntersect(ring.at(i), ring.at(i + 1), ring.at(j), ring.at(j + 1))) return true;
    }
  }
  return false;
}

ChainBuild refusedChain(ShapeError error) {
  ChainBuild build;
  build.error = error;
  return build;
}

}  // namespace

ChainBuild buildChain(std::span<const Vec2> points, bool loop) {
  const int count = static_cast<int>(points.size());
  if (count < 4) return refusedChain(ShapeError::ChainTooFewPoints);
  if (count > kMaxChainPoints) return refusedChain(ShapeError::ChainTooManyPoints);
  if (!allFinite(points)) return refusedChain(ShapeError::NonFinite);
  const Point offset = meanOf(points);
  std::vector<Point> shifted(points.size());
  for (int i = 0; i < count; ++i) shifted[i] = toPoint(points[i]) - offset;
  const int segmentCount = loop ? count : count - 3;
  const Ring ring(shifted);
  for (int i = 0; i < (loop ? count : count - 1); ++i) {
    if ((ring.at(i + 1) - ring.at(i)).norm() < kChainPointSpacing) {
      return refusedChain(ShapeError::SegmentTooShort);
    }
  }
  if (chainCrosses(shifted, loop)) return refusedChain(ShapeError::ChainCrossing);

  ChainBuild build;
  build.segments.reserve(static_cast<std::size_t>(segmentCount));
  // Open: segment k joins points k+1 and k+2; loop: point k and the next.
  const int first = loop ? 0 : 1;
  for (int k = 0; k < segmentCount; ++k) {
    const int i = first + k;
    ChainSegment segment;
    segment.ghost1 = points[static_cast<std::size_t>((i - 1 + count) % count)];
    segment.segment = {points[static_cast<std::size_t>(i % count)],
                       points[static_cast<std::size_t>((i + 1) % count)]};
    segment.ghost2 = points[static_cast<std::size_t>((i + 2) % count)];
    build.segments.push_back(segment);
  }
  return build;
}

namespace {

// Ear clipping keeps the best-shaped ear each time: the ratio of twice its
// area to its longest edge squared (1 for no triangle, ~0.87 equilateral),
// so no needle triangle is cut while a fatter one is available.
double earQuality(const Point& a, const Point& b, const Point& c) {
  const double longest =
      std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return cross2(b - a, c - b) / longest;
}

bool insideTriangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  return cross2(b - a, p - a) >= 0 && cross2(c - b, p - b) >= 0 && cross2(a - c, p - c) >= 0;
}

// Triangles of an anticlockwise simple polygon, as index triples.
std::vector<std::array<int, 3>> triangulate(std::span<const Point> points) {
  std::vector<int> remaining(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) remaining[i] = static_cast<int>(i);
  std::vector<std::array<int, 3>> triangles;
  while (remaining.size() > 3) {
    const int n = static_cast<int>(remaining.size());
    int best = -1;
    double bestQuality = 0;
    for (int i = 0; i < n; ++i) {
      const int ia = remaining[(i + n - 1) % n], ib = remaining[i], ic = remaining[(i + 1) % n];
      const Point &a = points[ia], &b = points[ib], &c = points[ic];
      const double quality = earQuality(a, b, c);
      if (quality <= bestQuality) continue;
      bool empty = true;
      for (int j : remaining) {
        if (j != ia && j != ib && j != ic && insideTriangle(points[j], a, b, c)) {
          empty = false;
          break;
        }
      }
      if (empty) {
        best = i;
        bestQuality = quality;
      }
    }
    // A simple polygon always has an ear (two ears theorem); none found
    // means round-off broke simplicity, and the caller refuses it.
    if (best < 0) return {};
    triangles.push_back(
        {remaining[(best + n - 1) % n], remaining[best], remaining[(best + 1) % n]});
    remaining.erase(remaining.begin() + best);
  }
  triangles.push_back({remaining[0], remaining[1], remaining[2]});
  return triangles;
}

// Position of the directed edge from -> to in piece, or -1.
int findEdge(const std::vector<int>& piece, int from, int to) {
  const int n = static_cast<int>(piece.size());
  for (int i = 0; i < n; ++i) {
    if (piece[i] == from && piece[(i + 1) % n] == to) return i;
  }
  return -1;
}

bool strictlyConvex(std::span<const Point> points, const std::vector<int>& piece) {
  const int n = static_cast<int>(piece.size());
  for (int i = 0; i < n; ++i) {
    const Point& a = points[piece[(i + n - 1) % n]];
    const Point& b = points[piece[i]];
    const Point& c = points[piece[(i + 1) % n]];
    if (cross2(b - a, c - b) <= 0 || distanceToChord(a, b, c) < kPolygonPointTolerance)
      return false;
  }
  return true;
}

// Tries to join piece p with the piece across one of its edges; true when it did.
bool mergeAcrossAnEdge(std::span<const Point> points, std::vector<std::vector<int>>& pieces,
                       std::size_t& p) {
  const int n = static_cast<int>(pieces[p].size());
  for (int e = 0; e < n; ++e) {
    const int from = pieces[p][e], to = pieces[p][(e + 1) % n];
    for (std::size_t q = 0; q < pieces.size(); ++q) {
      const int back = q == p ? -1 : findEdge(pieces[q], to, from);
      if (back < 0) continue;
      // Walk p from `to` round to `from`, then q past `from` up to `to`.
      std::vector<int> joined;
      for (int k = 0; k < n; ++k) joined.push_back(pieces[p][(e + 1 + k) % n]);
      const int m = static_cast<int>(pieces[q].size());
      for (int k = 2; k < m; ++k) joined.push_back(pieces[q][(back + k) % m]);
      if (static_cast<int>(joined.size()) > kMaxPolygonVertices ||
          !strictlyConvex(points, joined)) {
        break;  // an edge borders one other piece only
      }
      pieces[p] = std::move(joined);
      pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(q));
      if (q < p) --p;
      return true;
    }
  }
  return false;
}

// Hertel-Mehlhorn: drop each diagonal whose two sides still make a convex
// piece of at most kMaxPolygonVertices vertices. One pass suffices: pieces
// only grow, so a diagonal once needed stays needed.
std::vector<std::vector<int>> mergeTriangles(std::span<const Point> points,
                                             const std::vector<std::array<int, 3>>& triangles) {
  std::vector<std::vector<int>> pieces;
  for (const auto& t : triangles) pieces.push_back({t[0], t[1], t[2]});
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    while (mergeAcrossAnEdge(points, pieces, p)) {
    }
  }
  return pieces;
}

ConvexDecomposition refusedDecomposition(ShapeError error) {
  ConvexDecomposition decomposition;
  decomposition.error = error;
  return decomposition;
}

}  // namespace

ConvexDecomposition decomposePolygon(std::span<const Vec2> points, const ShapeLimits& limits) {
  if (points.size() < kMinPolygonVertices) return refusedDecomposition(ShapeError::TooFewVertices);
  if (points.size() > kMaxConcavePoints) {
    return refusedDecomposition(ShapeError::TooManyConcavePoints);
  }
  if (!allFinite(points)) return refusedDecomposition(ShapeError::NonFinite);
  const Point offset = meanOf(points);
  const int count = static_cast<int>(points.size());
  std::vector<Point> shifted(points.size());
  for (int i = 0; i < count; ++i) shifted[i] = toPoint(points[i]) - offset;
  if (const ShapeError error = checkSimple(Ring(shifted)); error != ShapeError::None) {
    return refusedDecomposition(error);
  }
  const double area = signedArea(Ring(shifted));
  if (area < 0) std::reverse(shifted.begin() + 1, shifted.end());
  if (std::abs(area) < limits.minArea || std::abs(area) > limits.maxArea) {
    return refusedDecomposition(ShapeError::AreaOutOfRange);
  }
  const std::vector<std::array<int, 3>> triangles = triangulate(shifted);
  if (triangles.empty()) return refusedDecomposition(ShapeError::SelfIntersecting);

  ConvexDecomposition decomposition;
  for (const std::vector<int>& piece : mergeTriangles(shifted, triangles)) {
    std::array<Point, kMaxPolygonVertices> corners{};
    Polygon polygon;
    polygon.count = static_cast<int>(piece.size());
    for (int i = 0; i < polygon.count; ++i) corners[i] = shifted[piece[i]];
    const AreaMoments moments = computeAreaMoments(std::span(corners.data(), piece.size()));
    for (int i = 0; i < polygon.count; ++i) {
      polygon.vertices[i] = (corners[i] + offset).cast<Real>();
    }
    polygon.centroid = (moments.centroid + offset).cast<Real>();
    computeNormals(polygon);
    decomposition.pieces.push_back(polygon);
  }
  return decomposition;
}

}  // namespace impulse
