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

SubmergedPart polygonPart(const Polygon& polygon, const Transform& transform, std::span<const Vec2> region) {
  thread_local std::vector<Vec2d> points, scratch;
  points.clear();
  for (int i = 0; i < polygon.count; ++i) points.push_back(transform.apply(polygon.vertices[i]).cast<double>());
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

}  // namespace

SubmergedPart submergedPart(const Shape& shape, const Transform& transform, std::span<const Vec2> region) {
  if (shape.type == ShapeType::Circle) return circlePart(transform.p.cast<double>(), shape.circle.radius, region);
  return polygonPart(shape.polygon, transform, region);
}

}  // namespace impulse
