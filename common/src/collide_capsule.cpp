// Manifolds of capsules (and segments, capsules of radius 0) against circles
// and capsules: closest points of their core segments.

#include <algorithm>

#include "impulse/manifold.h"
#include "manifold_internal.h"

namespace impulse {
namespace {

using namespace narrow;

// The part of segment x-y whose projection on `axis` (from `origin`) lies in
// [0, length]; the caller knows the two overlap.
struct Clipped {
  Vec2 first = Vec2::Zero();
  Vec2 second = Vec2::Zero();
};

Clipped clipToSlab(const Vec2& x, const Vec2& y, const Vec2& origin, const Vec2& axis,
                   Real length) {
  Real fx = axis.dot(x - origin);
  Real fy = axis.dot(y - origin);
  if (fx == fy) return {x, y};
  Real t0 = -fx / (fy - fx);
  Real t1 = (length - fx) / (fy - fx);
  Real low = std::max(Real(0), std::min(t0, t1));
  Real high = std::min(Real(1), std::max(t0, t1));
  return {x + low * (y - x), x + high * (y - x)};
}

// Side of segment p-q (unit direction u) facing the points x and y: the
// normal and the smaller of their distances along it.
struct Side {
  Vec2 normal = Vec2::Zero();
  Real separation = 0;
};

Side facingSide(const Vec2& p, const Vec2& u, const Vec2& x, const Vec2& y) {
  Vec2 normal = leftPerp(u);
  Real sx = normal.dot(x - p);
  Real sy = normal.dot(y - p);
  Real plus = std::min(sx, sy);
  Real minus = std::min(-sx, -sy);
  return plus > minus ? Side{normal, plus} : Side{-normal, minus};
}

bool projectsWithin(const Vec2& p, const Vec2& u, Real length, const Vec2& x, const Vec2& y) {
  Real fx = u.dot(x - p);
  Real fy = u.dot(y - p);
  return !((fx <= 0 && fy <= 0) || (fx >= length && fy >= length));
}

// Contact at c (a point of the incident core) with the reference core's
// surface along normal n at separation s of the cores: midway between the
// surfaces.
LocalPoint midwayPoint(const Vec2& c, const Vec2& n, Real s, Real referenceRadius,
                       Real incidentRadius, std::uint16_t id) {
  return {c + (Real(0.5) * (referenceRadius - incidentRadius - s)) * n,
          s - referenceRadius - incidentRadius, id};
}

// Core segments p1-q1 (A, radius rA) and p2-q2 (B, radius rB) in A's frame:
//   closest points c1, c2 at distance d; no contact beyond the speculative
//   distance
//   when each segment projects onto the other (lying along each other):
//     reference = the segment whose facing side separates the other more;
//     clip the other segment to the reference's extent: two points, kept
//     when one of them is within a linear slop of d (otherwise the segments
//     cross at an angle and the closest points say more)
//   else one point midway between c1 and c2, normal along c2 - c1
Manifold collideCores(const Vec2& p1, const Vec2& q1, Real rA, const Vec2& p2, const Vec2& q2,
                      Real rB, const Transform& xfA, const Transform& xfB,
                      Real speculativeDistance) {
  SegmentClosestPoints closest = closestPoints(p1, q1, p2, q2);
  Vec2 gap = closest.point2 - closest.point1;
  Real distance = gap.norm();
  if (distance - rA - rB >= speculativeDistance) {
    return {};
  }
  Real length1 = (q1 - p1).norm();
  Real length2 = (q2 - p2).norm();
  Vec2 u1 = length1 > 0 ? Vec2((q1 - p1) / length1) : Vec2(1, 0);
  Vec2 u2 = length2 > 0 ? Vec2((q2 - p2) / length2) : Vec2(1, 0);

  if (projectsWithin(p1, u1, length1, p2, q2) && projectsWithin(p2, u2, length2, p1, q1)) {
    Side sideA = facingSide(p1, u1, p2, q2);
    Side sideB = facingSide(p2, u2, p1, q1);
    if (sideA.separation >= sideB.separation) {
      Clipped c = clipToSlab(p2, q2, p1, u1, length1);
      Real s1 = sideA.normal.dot(c.first - p1);
      Real s2 = sideA.normal.dot(c.second - p1);
      if (std::min(s1, s2) <= distance + kLinearSlop) {
        std::array<LocalPoint, 2> points = {
            midwayPoint(c.first, sideA.normal, s1, rA, rB, makeFeatureId(0, 0)),
            midwayPoint(c.second, sideA.normal, s2, rA, rB, makeFeatureId(0, 1))};
        return toWorld(sideA.normal, points, xfA, xfB, speculativeDistance);
      }
    } else {
      Clipped c = clipToSlab(p1, q1, p2, u2, length2);
      Real s1 = sideB.normal.dot(c.first - p2);
      Real s2 = sideB.normal.dot(c.second - p2);
      if (std::min(s1, s2) <= distance + kLinearSlop) {
        std::array<LocalPoint, 2> points = {
            midwayPoint(c.first, sideB.normal, s1, rB, rA, makeFeatureId(0, 0)),
            midwayPoint(c.second, sideB.normal, s2, rB, rA, makeFeatureId(1, 0))};
        return toWorld(-sideB.normal, points, xfA, xfB, speculativeDistance);
      }
    }
  }

  Vec2 normal;
  if (distance > kMinDirectionLength) {
    normal = gap / distance;
  } else {
    // Cores touching: A's side facing B's middle.
    normal = leftPerp(u1);
    if (normal.dot(Real(0.5) * (p2 + q2) - p1) < 0) normal = -normal;
  }
  Vec2 surfaceA = closest.point1 + rA * normal;
  Vec2 surfaceB = closest.point2 - rB * normal;
  LocalPoint point{Real(0.5) * (surfaceA + surfaceB), distance - rA - rB,
                   makeFeatureId(closest.fraction1 == 0 ? 0 : 1, closest.fraction2 == 0 ? 0 : 1)};
  return toWorld(normal, std::span(&point, 1), xfA, xfB, speculativeDistance);
}

// A core segment p-q of radius rA against circle B: the point of the segment
// nearest the centre plays the first circle's centre.
Manifold collideCoreAndCircle(const Vec2& p, const Vec2& q, Real rA, const Circle& b,
                              const Transform& xfA, const Transform& xfB,
                              Real speculativeDistance) {
  Vec2 center = placeInA(relativeTransform(xfA, xfB), b.center);
  Vec2 nearest = closestPointOnSegment(center, p, q);
  Vec2 offset = center - nearest;
  Real distance = offset.norm();
  if (distance - rA - b.radius >= speculativeDistance) {
    return {};
  }
  // A centre on the core: push out of the segment's left side.
  Vec2 normal =
      distance > kMinDirectionLength ? Vec2(offset / distance) : Vec2(leftPerp(q - p).normalized());
  Vec2 surfaceA = nearest + rA * normal;
  Vec2 surfaceB = center - b.radius * normal;
  LocalPoint point{Real(0.5) * (surfaceA + surfaceB), distance - rA - b.radius,
                   makeFeatureId(0, 0)};
  return toWorld(normal, std::span(&point, 1), xfA, xfB, speculativeDistance);
}

}  // namespace

Manifold collideCapsuleAndCircle(const Capsule& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, Real speculativeDistance) {
  return collideCoreAndCircle(a.center1, a.center2, a.radius, b, xfA, xfB, speculativeDistance);
}

Manifold collideCapsules(const Capsule& a, const Transform& xfA, const Capsule& b,
                         const Transform& xfB, Real speculativeDistance) {
  Transform relative = relativeTransform(xfA, xfB);
  return collideCores(a.center1, a.center2, a.radius, relative.apply(b.center1),
                      relative.apply(b.center2), b.radius, xfA, xfB, speculativeDistance);
}

Manifold collideSegmentAndCircle(const Segment& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, Real speculativeDistance) {
  return collideCoreAndCircle(a.point1, a.point2, 0, b, xfA, xfB, speculativeDistance);
}

Manifold collideSegmentAndCapsule(const Segment& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB, Real speculativeDistance) {
  Transform relative = relativeTransform(xfA, xfB);
  return collideCores(a.point1, a.point2, 0, relative.apply(b.center1), relative.apply(b.center2),
                      b.radius, xfA, xfB, speculativeDistance);
}

}  // namespace impulse
