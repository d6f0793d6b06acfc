// Rays against each kind of shape, worked in the shape's own frame (where
// its geometry is stored) and turned back to world at the end.

#include "ray_cast.h"

#include <cmath>
#include <span>

#include "manifold_internal.h"

namespace impulse {
namespace {

struct LocalRay {
  Vec2 origin = Vec2::Zero();
  Vec2 translation = Vec2::Zero();
};

// A hit with its normal in the shape's frame.
struct LocalHit {
  Real fraction = 0;
  Vec2 normal = Vec2::Zero();
};

std::optional<LocalHit> nearer(const std::optional<LocalHit>& a, const std::optional<LocalHit>& b) {
  if (!a) return b;
  if (!b) return a;
  return b->fraction < a->fraction ? b : a;
}

// Circle, worked along the unit direction u so a long ray keeps its
// precision (s = origin - centre, L = ray length):
//   along = -s.u        where the ray passes closest to the centre
//   c = s + along u     that closest point; |c| > r misses
//   enter = along - sqrt(r^2 - |c|^2), a hit when it lies in [0, L]
// A ray starting inside has enter < 0, so it does not hit.
std::optional<LocalHit> rayCastCircle(const LocalRay& ray, const Vec2& center, Real radius) {
  const Real length = ray.translation.norm();
  const Vec2 direction = ray.translation / length;
  const Vec2 offset = ray.origin - center;
  const Real along = -offset.dot(direction);
  const Real closestSquared = (offset + along * direction).squaredNorm();
  const Real radiusSquared = radius * radius;
  if (closestSquared > radiusSquared) return std::nullopt;
  const Real enter = along - std::sqrt(radiusSquared - closestSquared);
  if (enter < 0 || enter > length) return std::nullopt;
  return LocalHit{enter / length, (offset + enter * direction).normalized()};
}

// Segment p1-p2 with unit normal n on its right (a chain's collision side):
//   approach = d.n; parallel rays miss
//   fraction = (p1 - origin).n / approach, in [0, 1]
//   the point must lie between p1 and p2
// One-sided, only a ray going against n (from the right) hits.
std::optional<LocalHit> rayCastSegment(const LocalRay& ray, const Vec2& p1, const Vec2& p2,
                                       bool oneSided) {
  const Vec2 edge = p2 - p1;
  const Vec2 normal = rightPerp(edge).normalized();
  const Real approach = ray.translation.dot(normal);
  if (approach == 0 || (oneSided && approach > 0)) return std::nullopt;
  const Real fraction = (p1 - ray.origin).dot(normal) / approach;
  if (fraction < 0 || fraction > 1) return std::nullopt;
  const Real along = (ray.origin + fraction * ray.translation - p1).dot(edge);
  if (along < 0 || along > edge.squaredNorm()) return std::nullopt;
  return LocalHit{fraction, approach < 0 ? normal : Vec2(-normal)};
}

// Sharp convex polygon: the ray clipped by each face's half-plane
// n.(x - v) <= 0 (Cyrus-Beck):
//   a face the ray approaches (d.n < 0) raises where it enters
//   a face it leaves (d.n > 0) lowers where it exits
//   a face it runs parallel to, from outside, misses
// A hit needs a face entered after the origin (so an origin inside misses)
// and the entry before the exit.
std::optional<LocalHit> rayCastSharpPolygon(const LocalRay& ray, const Polygon& polygon) {
  Real enter = 0;
  Real exit = 1;
  int enteredFace = -1;
  for (int i = 0; i < polygon.count; ++i) {
    const Vec2& normal = polygon.normals[i];
    const Real inside = normal.dot(polygon.vertices[i] - ray.origin);
    const Real approach = normal.dot(ray.translation);
    if (approach == 0) {
      if (inside < 0) return std::nullopt;
      continue;
    }
    const Real crossing = inside / approach;
    if (approach < 0 && crossing > enter) {
      enter = crossing;
      enteredFace = i;
    } else if (approach > 0 && crossing < exit) {
      exit = crossing;
    }
    if (enter > exit) return std::nullopt;
  }
  if (enteredFace < 0) return std::nullopt;
  return LocalHit{enter, polygon.normals[enteredFace]};
}

// Within `radius` of the core, or inside a core of three or more vertices.
bool insideRounded(const Vec2& point, std::span<const Vec2> vertices, std::span<const Vec2> normals,
                   Real radius) {
  const int count = static_cast<int>(vertices.size());
  bool insideCore = count >= 3;
  for (int i = 0; i < count; ++i) {
    const Vec2& next = vertices[narrow::nextIndex(i, count)];
    const Vec2 closest = narrow::closestPointOnSegment(point, vertices[i], next);
    if ((point - closest).squaredNorm() <= radius * radius) return true;
    insideCore = insideCore && normals[i].dot(point - vertices[i]) <= 0;
  }
  return insideCore;
}

// A rounded core (a capsule's two centres, or a rounded polygon): the shape
// is the core's faces pushed out by the radius, joined by circles around
// its vertices. Each of those lies within the shape and its surface is made
// of them, so from outside the first one the ray enters is where it enters
// the shape. The faces are hit from outside only.
std::optional<LocalHit> rayCastRounded(const LocalRay& ray, std::span<const Vec2> vertices,
                                       std::span<const Vec2> normals, Real radius) {
  if (insideRounded(ray.origin, vertices, normals, radius)) return std::nullopt;
  const int count = static_cast<int>(vertices.size());
  std::optional<LocalHit> best;
  for (int i = 0; i < count; ++i) {
    const Vec2 push = radius * normals[i];
    const Vec2& next = vertices[narrow::nextIndex(i, count)];
    best = nearer(best, rayCastSegment(ray, vertices[i] + push, next + push, true));
    best = nearer(best, rayCastCircle(ray, vertices[i], radius));
  }
  return best;
}

std::optional<LocalHit> rayCastLocal(const LocalRay& ray, const Circle& circle) {
  return rayCastCircle(ray, circle.center, circle.radius);
}

std::optional<LocalHit> rayCastLocal(const LocalRay& ray, const Capsule& capsule) {
  // A two-vertex core: the edge there and the edge back, each with its
  // outward (right) normal.
  const Vec2 side = rightPerp(capsule.center2 - capsule.center1).normalized();
  const Vec2 vertices[2] = {capsule.center1, capsule.center2};
  const Vec2 normals[2] = {side, -side};
  return rayCastRounded(ray, vertices, normals, capsule.radius);
}

std::optional<LocalHit> rayCastLocal(const LocalRay& ray, const Segment& segment) {
  return rayCastSegment(ray, segment.point1, segment.point2, false);
}

std::optional<LocalHit> rayCastLocal(const LocalRay& ray, const Polygon& polygon) {
  if (polygon.radius <= 0) return rayCastSharpPolygon(ray, polygon);
  const auto count = static_cast<std::size_t>(polygon.count);
  return rayCastRounded(ray, std::span(polygon.vertices).first(count),
                        std::span(polygon.normals).first(count), polygon.radius);
}

std::optional<LocalHit> rayCastLocal(const LocalRay& ray, const ChainSegment& chain) {
  return rayCastSegment(ray, chain.segment.point1, chain.segment.point2, true);
}

}  // namespace

std::optional<ShapeRayHit> rayCastShape(ShapeRef shape, const Transform& transform,
                                        const Vec2& origin, const Vec2& translation) {
  const LocalRay ray{transform.applyInverse(origin), transform.q.applyInverse(translation)};
  const std::optional<LocalHit> hit =
      visitGeometry(shape, [&](const auto& geometry) { return rayCastLocal(ray, geometry); });
  if (!hit) return std::nullopt;
  return ShapeRayHit{hit->fraction, transform.q.apply(hit->normal)};
}

}  // namespace impulse
