// Exact intersection of a shape with a convex region (impulse/submerged.h).
// Computed in double: the world's floats would lose the small areas of
// bodies that barely touch the surface.

#include "impulse/submerged.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace impulse {

namespace {

using Vec2d = Eigen::Vector2d;

double crossd(const Vec2d& a, const Vec2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Area and first moment (area x centroid) of a piece, summed signed.
struct Moments {
  double area = 0;
  Vec2d moment = Vec2d::Zero();
  void add(const Moments& other) {
    area += other.area;
    moment += other.moment;
  }
  SubmergedPart part(const Vec2d& origin) const {
    if (area <= 0) return {};
    return {area, (origin + moment / area).cast<Real>()};
  }
};

Moments triangleFromOrigin(const Vec2d& p, const Vec2d& q) {
  const double area = 0.5 * crossd(p, q);
  return {area, area * (p + q) / 3};
}

// Sector of the circle between the directions of p and q (signed angle).
Moments sector(const Vec2d& p, const Vec2d& q, double radius) {
  const double angle = std::atan2(crossd(p, q), p.dot(q));
  const double half = 0.5 * angle;
  const Vec2d start = p.normalized();
  const Vec2d bisector(start.x() * std::cos(half) - start.y() * std::sin(half),
                       start.x() * std::sin(half) + start.y() * std::cos(half));
  // Area r^2 a / 2, centroid 4 r sin(a/2) / (3 a) along the bisector.
  return {0.5 * radius * radius * angle, (2.0 / 3.0) * radius * radius * radius * std::sin(half) * bisector};
}

// The disc of `radius` at the origin intersected with the triangle (0, a, b),
// signed by the triangle's winding.
Moments discTriangle(const Vec2d& a, const Vec2d& b, double radius) {
  const Vec2d edge = b - a;
  // |a + t edge|^2 = r^2 where the edge crosses the circle.
  const double qa = edge.squaredNorm(), qb = 2 * a.dot(edge), qc = a.squaredNorm() - radius * radius;
  double cuts[4] = {0, 1, 1, 1};
  int count = 1;
  const double discriminant = qb * qb - 4 * qa * qc;
  if (qa > 0 && discriminant > 0) {
    const double root = std::sqrt(discriminant);
    for (double t : {(-qb - root) / (2 * qa), (-qb + root) / (2 * qa)}) {
      if (t > 0 && t < 1) cuts[count++] = t;
    }
  }
  cuts[count++] = 1;
  Moments sum;
  for (int k = 0; k + 1 < count; ++k) {
    const Vec2d p = a + cuts[k] * edge, q = a + cuts[k + 1] * edge;
    const bool inside = (0.5 * (p + q)).squaredNorm() <= radius * radius;
    sum.add(inside ? triangleFromOrigin(p, q) : sector(p, q, radius));
  }
  return sum;
}

SubmergedPart circlePart(const Vec2d& center, double radius, std::span<const Vec2> region) {
  Moments sum;
  for (std::size_t i = 0; i < region.size(); ++i) {
    const Vec2d a = region[i].cast<double>() - center;
    const Vec2d b = region[(i + 1) % region.size()].cast<double>() - center;
    sum.add(discTriangle(a, b, radius));
  }
  return sum.part(center);
}

// Sutherland-Hodgman: keep the side of edge a->b on the left (inside).
void clipByEdge(std::vector<Vec2d>& points, std::vector<Vec2d>& scratch, const Vec2d& a, const Vec2d& b) {
  scratch.clear();
  const Vec2d edge = b - a;
  auto side = [&](const Vec2d& p) { return crossd(edge, p - a); };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2d& p = points[i];
    const Vec2d& q = points[(i + 1) % points.size()];
    const double sp = side(p), sq = side(q);
    if (sp >= 0) scratch.push_back(p);
    if ((sp >= 0) != (sq >= 0)) scratch.push_back(p + (sp / (sp - sq)) * (q - p));
  }
  points.swap(scratch);
}

// `outline`: a convex polygon's vertices in the body's frame, anticlockwise.
SubmergedPart outlinePart(std::span<const Vec2> outline, const Transform& transform, std::span<const Vec2> region) {
  thread_local std::vector<Vec2d> points, scratch;
  points.clear();
  for (const Vec2& vertex : outline) points.push_back(transform.apply(vertex).cast<double>());
  for (std::size_t i = 0; i < region.size() && points.size() >= 3; ++i) {
    clipByEdge(points, scratch, region[i].cast<double>(), region[(i + 1) % region.size()].cast<double>());
  }
  if (points.size() < 3) return {};
  // Moments about the first point keep the sums small.
  const Vec2d origin = points[0];
  Moments sum;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    sum.add(triangleFromOrigin(points[i] - origin, points[i + 1] - origin));
  }
  return sum.part(origin);
}

// Rounded outlines (capsules, rounded polygons) are clipped as polygons whose
// corners follow the arcs in steps of kArcStep: the area is within 0.3 % of
// the rounded shape's for a rounding of a quarter of the shape's size.
constexpr double kArcStep = std::numbers::pi / 16;

// The arc of `radius` around `center` from direction angle `from` to `to`
// (anticlockwise), appended.
void appendArc(std::vector<Vec2>& outline, const Vec2& center, Real radius, double from, double to) {
  const int steps = std::max(1, int(std::ceil((to - from) / kArcStep)));
  for (int i = 0; i <= steps; ++i) {
    const double angle = from + (to - from) * i / steps;
    outline.push_back(center + radius * Vec2(Real(std::cos(angle)), Real(std::sin(angle))));
  }
}

// A convex outline with every vertex of `core` rounded by `radius`.
void roundedOutline(std::vector<Vec2>& outline, std::span<const Vec2> core, std::span<const Vec2> normals,
                    Real radius) {
  const std::size_t count = core.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2& before = normals[(i + count - 1) % count];
    const Vec2& after = normals[i];
    double from = std::atan2(before.y(), before.x());
    double to = std::atan2(after.y(), after.x());
    if (to < from) to += 2 * std::numbers::pi;
    appendArc(outline, core[i], radius, from, to);
  }
}

SubmergedPart roundedPart(const Shape& shape, const Transform& transform, std::span<const Vec2> region) {
  thread_local std::vector<Vec2> outline;
  outline.clear();
  if (shape.type() == ShapeType::Capsule) {
    const Capsule& capsule = shape.capsule();
    const Vec2 axis = (capsule.center2 - capsule.center1).normalized();
    const Vec2 right(axis.y(), -axis.x());
    const std::array<Vec2, 2> core{capsule.center1, capsule.center2};
    const std::array<Vec2, 2> normals{right, -right};
    roundedOutline(outline, core, normals, capsule.radius);
  } else {
    const Polygon& polygon = shape.polygon();
    roundedOutline(outline, std::span(polygon.vertices.data(), polygon.count),
                   std::span(polygon.normals.data(), polygon.count), polygon.radius);
  }
  return outlinePart(outline, transform, region);
}

}  // namespace

SubmergedPart submergedPart(const Shape& shape, const Transform& transform, std::span<const Vec2> region) {
  switch (shape.type()) {
    case ShapeType::Circle:
      return circlePart(transform.apply(shape.circle().center).cast<double>(), shape.circle().radius, region);
    case ShapeType::Polygon:
      if (shape.polygon().radius > 0) return roundedPart(shape, transform, region);
      return outlinePart(std::span(shape.polygon().vertices.data(), shape.polygon().count), transform, region);
    case ShapeType::Capsule:
      return roundedPart(shape, transform, region);
    case ShapeType::Segment:
    case ShapeType::ChainSegment:
      return {};  // no area, nothing to float
  }
  return {};
}

SubmergedPart submergedPart(std::span<const Shape* const> shapes, const Transform& transform,
                            std::span<const Vec2> region) {
  double area = 0;
  Vec2d moment = Vec2d::Zero();
  for (const Shape* shape : shapes) {
    const SubmergedPart part = submergedPart(*shape, transform, region);
    area += part.area;
    moment += part.area * part.centroid.cast<double>();
  }
  if (area <= 0) return {};
  return {area, (moment / area).cast<Real>()};
}

}  // namespace impulse
