#include "impulse/manifold.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>

#include "manifold_internal.h"

namespace impulse {
namespace narrow {

Polygon transformPolygon(const Polygon& polygon, const Transform& xf) {
  Polygon result;
  result.count = polygon.count;
  for (int i = 0; i < polygon.count; ++i) {
    result.vertices[i] = xf.apply(polygon.vertices[i]);
    result.normals[i] = xf.q.apply(polygon.normals[i]);
  }
  result.centroid = placeInA(xf, polygon.centroid);
  result.radius = polygon.radius;
  return result;
}

Polygon makeTwoSidedPolygon(const Vec2& point1, const Vec2& point2, Real radius) {
  Polygon polygon;
  polygon.count = 2;
  polygon.vertices[0] = point1;
  polygon.vertices[1] = point2;
  polygon.normals[0] = rightPerp(point2 - point1).normalized();
  polygon.normals[1] = -polygon.normals[0];
  polygon.centroid = Real(0.5) * (point1 + point2);
  polygon.radius = radius;
  return polygon;
}

Vec2 closestPointOnSegment(const Vec2& p, const Vec2& s1, const Vec2& s2) {
  Vec2 edge = s2 - s1;
  Real lengthSquared = edge.squaredNorm();
  // A zero-length segment is a point: any fraction gives it.
  Real fraction = lengthSquared > 0
                      ? std::clamp((p - s1).dot(edge) / lengthSquared, Real(0), Real(1))
                      : Real(0);
  return s1 + fraction * edge;
}

// Ericson, Real-Time Collision Detection 5.1.9: the unclamped minimum on
// the first, the second's point nearest to it clamped, and the first redone
// when the second was clamped.
SegmentClosestPoints closestPoints(const Vec2& p1, const Vec2& q1, const Vec2& p2, const Vec2& q2) {
  Vec2 d1 = q1 - p1;
  Vec2 d2 = q2 - p2;
  Vec2 r = p1 - p2;
  Real dd1 = d1.squaredNorm();
  Real dd2 = d2.squaredNorm();
  Real rd1 = d1.dot(r);
  Real rd2 = d2.dot(r);
  Real d12 = d1.dot(d2);
  // Validated capsules are at least a linear slop long; a zero length here
  // still gives a point, never a division by zero.
  Real denominator = dd1 * dd2 - d12 * d12;
  Real f1 = denominator > 0 ? std::clamp((d12 * rd2 - rd1 * dd2) / denominator, Real(0), Real(1))
                            : Real(0);
  Real f2 = dd2 > 0 ? (d12 * f1 + rd2) / dd2 : Real(0);
  if (f2 < 0) {
    f2 = 0;
    f1 = dd1 > 0 ? std::clamp(-rd1 / dd1, Real(0), Real(1)) : Real(0);
  } else if (f2 > 1) {
    f2 = 1;
    f1 = dd1 > 0 ? std::clamp((d12 - rd1) / dd1, Real(0), Real(1)) : Real(0);
  }
  return {f1, f2, p1 + f1 * d1, p2 + f2 * d2};
}

// Distance from a point to the polygon's boundary.
Real distanceToBoundary(const Polygon& polygon, const Vec2& p) {
  Real distance = std::numeric_limits<Real>::max();
  for (int i = 0; i < polygon.count; ++i) {
    Vec2 closest = closestPointOnSegment(p, polygon.vertices[i],
                                         polygon.vertices[nextIndex(i, polygon.count)]);
    distance = std::min(distance, (p - closest).norm());
  }
  return distance;
}

// Face whose plane the point lies furthest in front of (least deep behind,
// when the point is inside).
FaceQuery findMaxSeparation(const Polygon& polygon, const Vec2& p) {
  FaceQuery best;
  for (int i = 0; i < polygon.count; ++i) {
    Real separation = polygon.normals[i].dot(p - polygon.vertices[i]);
    if (separation > best.separation) {
      best = {i, separation};
    }
  }
  return best;
}

// Separating axis test over the reference polygon's edge normals: for each
// face, the deepest vertex of the other polygon; the face where that vertex
// is least deep is the axis of least penetration (or of largest gap).
FaceQuery findMaxSeparation(const Polygon& reference, const Polygon& other) {
  FaceQuery best;
  for (int i = 0; i < reference.count; ++i) {
    Real deepest = std::numeric_limits<Real>::max();
    for (int j = 0; j < other.count; ++j) {
      deepest =
          std::min(deepest, reference.normals[i].dot(other.vertices[j] - reference.vertices[i]));
    }
    if (deepest > best.separation) {
      best = {i, deepest};
    }
  }
  return best;
}

// The incident edge is the one facing the reference face most directly: its
// normal is the most anti-parallel to the reference normal.
int findIncidentEdge(const Polygon& incident, const Vec2& referenceNormal) {
  int best = 0;
  Real minDot = std::numeric_limits<Real>::max();
  for (int i = 0; i < incident.count; ++i) {
    Real dot = referenceNormal.dot(incident.normals[i]);
    if (dot < minDot) {
      minDot = dot;
      best = i;
    }
  }
  return best;
}

// Contact between point `incidentPoint` of the incident core and the
// reference face along normal, placed midway between the two surfaces (each
// core's surface lies its radius out along the normal).
static LocalPoint faceContact(const Vec2& incidentPoint, const Vec2& faceVertex, const Vec2& normal,
                              std::uint16_t id, Real referenceRadius, Real incidentRadius) {
  Real separation = normal.dot(incidentPoint - faceVertex);
  Vec2 point = incidentPoint - Real(0.5) * separation * normal;
  // Sharp polygons skip the term, so their contacts keep the bits they had
  // before shapes had radii.
  if (referenceRadius != 0 || incidentRadius != 0) {
    point += (Real(0.5) * (referenceRadius - incidentRadius)) * normal;
  }
  return {point, separation - referenceRadius - incidentRadius, id};
}

// The incident edge lies wholly beside the reference face, so the nearest
// features are the face's end vertex and the incident edge. When apart, the
// true direction between them is the normal: the face normal would
// under-report the gap and make a corner sliding past a corner snag on a
// speculative contact.
static EdgeContacts cornerContact(const Vec2& faceNormal, const Vec2& referenceVertex,
                                  const Vec2& incident1, const Vec2& incident2,
                                  const Vec2& nearestIncidentVertex, std::uint16_t id,
                                  Real referenceRadius, Real incidentRadius) {
  Vec2 closest = closestPointOnSegment(referenceVertex, incident1, incident2);
  Vec2 gap = closest - referenceVertex;
  EdgeContacts contacts;
  contacts.count = 1;
  if (faceNormal.dot(gap) > kMinDirectionLength) {
    Real distance = gap.norm();
    contacts.normal = gap / distance;
    Vec2 point = referenceVertex + Real(0.5) * gap;
    if (referenceRadius != 0 || incidentRadius != 0) {
      point += (Real(0.5) * (referenceRadius - incidentRadius)) * contacts.normal;
    }
    contacts.points[0] = {point, distance - referenceRadius - incidentRadius, id};
  } else {
    // Corners touching within round-off: the gap is too short to give a
    // direction, so push along the face, as clipping would.
    contacts.normal = faceNormal;
    contacts.points[0] = faceContact(nearestIncidentVertex, referenceVertex, faceNormal, id,
                                     referenceRadius, incidentRadius);
  }
  return contacts;
}

// Clips the incident edge to the slab between the reference face's side
// planes. The incident edge runs against the face's tangent (both polygons
// are anticlockwise), so its second vertex is the lower one along it.
EdgeContacts clipIncidentEdge(const Polygon& reference, int referenceEdge, const Polygon& incident,
                              int incidentEdge) {
  int i11 = referenceEdge;
  int i12 = nextIndex(i11, reference.count);
  int i21 = incidentEdge;
  int i22 = nextIndex(i21, incident.count);
  const Vec2& v11 = reference.vertices[i11];
  const Vec2& v12 = reference.vertices[i12];
  const Vec2& w1 = incident.vertices[i21];
  const Vec2& w2 = incident.vertices[i22];
  const Vec2& normal = reference.normals[i11];
  const Real r1 = reference.radius;
  const Real r2 = incident.radius;

  Vec2 tangent = leftPerp(normal);
  Real faceLength = tangent.dot(v12 - v11);
  Real lower = tangent.dot(w2 - v11);
  Real upper = tangent.dot(w1 - v11);
  if (upper < 0) {
    return cornerContact(normal, v11, w1, w2, w1, makeFeatureId(i11, i21), r1, r2);
  }
  if (lower > faceLength) {
    return cornerContact(normal, v12, w1, w2, w2, makeFeatureId(i12, i22), r1, r2);
  }

  // Each interpolation happens only when the incident edge crosses that side
  // plane, so upper - lower is then strictly positive.
  Vec2 pointLower = lower < 0 ? Vec2(w2 + (-lower / (upper - lower)) * (w1 - w2)) : w2;
  Vec2 pointUpper =
      upper > faceLength ? Vec2(w2 + ((faceLength - lower) / (upper - lower)) * (w1 - w2)) : w1;

  EdgeContacts contacts;
  contacts.normal = normal;
  contacts.count = 2;
  contacts.points[0] = faceContact(pointLower, v11, normal, makeFeatureId(i11, i22), r1, r2);
  contacts.points[1] = faceContact(pointUpper, v11, normal, makeFeatureId(i12, i21), r1, r2);
  return contacts;
}

std::uint16_t swapFeatures(std::uint16_t id) { return makeFeatureId(id & 0xFF, id >> 8); }

void placeInWorld(const LocalPoint& local, const Transform& xfA, const Transform& xfB, ManifoldPoint& out) {
  out.anchorA = xfA.q.apply(local.point);
  out.anchorB = out.anchorA + (xfA.p - xfB.p);
  out.point = xfA.p + out.anchorA;
  out.separation = local.separation;
  out.id = local.id;
}

Manifold toWorld(const Vec2& localNormal, std::span<const LocalPoint> points, const Transform& xfA,
                 const Transform& xfB, Real speculativeDistance) {
  Manifold manifold;
  for (const LocalPoint& local : points) {
    if (local.separation >= speculativeDistance) {
      continue;
    }
    placeInWorld(local, xfA, xfB, manifold.points[manifold.pointCount++]);
  }
  if (manifold.pointCount > 0) {
    manifold.normal = xfA.q.apply(localNormal);
  }
  return manifold;
}

// Cores separated by a tenth of the slop at least: the direction between
// their nearest points is well defined.
constexpr Real kCoresApart = Real(0.1) * kLinearSlop;

// When the cores are apart and the nearest points of the reference and
// incident edges are a vertex of each, the contact is between those two
// vertices, along the line joining them (false otherwise).
static bool closestVertexPair(const Polygon& reference, int referenceEdge, const Polygon& incident,
                              int incidentEdge, EdgeContacts& contacts) {
  int i11 = referenceEdge;
  int i12 = nextIndex(i11, reference.count);
  int i21 = incidentEdge;
  int i22 = nextIndex(i21, incident.count);
  SegmentClosestPoints closest = closestPoints(reference.vertices[i11], reference.vertices[i12],
                                               incident.vertices[i21], incident.vertices[i22]);
  bool atVertex1 = closest.fraction1 == 0 || closest.fraction1 == 1;
  bool atVertex2 = closest.fraction2 == 0 || closest.fraction2 == 1;
  Vec2 gap = closest.point2 - closest.point1;
  Real distance = gap.norm();
  if (!atVertex1 || !atVertex2 || distance <= kCoresApart) {
    return false;
  }
  contacts.normal = gap / distance;
  contacts.count = 1;
  Vec2 surface1 = closest.point1 + reference.radius * contacts.normal;
  Vec2 surface2 = closest.point2 - incident.radius * contacts.normal;
  contacts.points[0] = {
      Real(0.5) * (surface1 + surface2), distance - reference.radius - incident.radius,
      makeFeatureId(closest.fraction1 == 0 ? i11 : i12, closest.fraction2 == 0 ? i21 : i22)};
  return true;
}

// In A's frame (B transformed into it), each polygon the points within its
// radius of its core:
//   sA, faceA = max separation of the cores over A's edge normals (SAT);
//   sB, faceB likewise
//   if max(sA, sB) - radii >= speculative distance: no contact
//   reference face = faceA unless sB > sA + tolerance (then faceB, flipped)
//   incident edge = edge of the other polygon most anti-parallel to it
//   (rounded or two-vertex polygons) if the nearest points of the two edges
//   are a vertex of each, apart: one point between them
//   else if the incident edge lies wholly beside the reference face:
//     one point between the face's end vertex and the incident edge
//   else clip the incident edge to the face's side planes: two points, each
//     with separation measured along the reference normal, minus the radii
//   keep the points within the speculative distance
//   flipped: negate the normal so it points from A to B, swap id features
Manifold collideLocalPolygons(const Polygon& a, const Polygon& localB, const Transform& xfA,
                              const Transform& xfB, Real speculativeDistance) {
  FaceQuery faceA = findMaxSeparation(a, localB);
  FaceQuery faceB = findMaxSeparation(localB, a);
  if (std::max(faceA.separation, faceB.separation) - (a.radius + localB.radius) >=
      speculativeDistance) {
    return {};
  }

  bool flip = faceB.separation > faceA.separation + kFaceTolerance;
  const Polygon& reference = flip ? localB : a;
  const Polygon& incident = flip ? a : localB;
  int referenceEdge = flip ? faceB.index : faceA.index;
  int incidentEdge = findIncidentEdge(incident, reference.normals[referenceEdge]);
  EdgeContacts contacts;
  // Rounded shapes, capsules and segments may touch at two vertices while
  // their cores are apart, where clipping would cut the nearest vertex away.
  // Sharp polygons of three vertices or more keep the corner logic of
  // clipIncidentEdge, and their bits.
  bool vertexPairPossible =
      (a.radius > 0 || localB.radius > 0 || a.count == 2 || localB.count == 2) &&
      std::max(faceA.separation, faceB.separation) > kCoresApart;
  if (!(vertexPairPossible &&
        closestVertexPair(reference, referenceEdge, incident, incidentEdge, contacts))) {
    contacts = clipIncidentEdge(reference, referenceEdge, incident, incidentEdge);
  }
  if (flip) {
    contacts.normal = -contacts.normal;
    for (LocalPoint& point : contacts.points) {
      point.id = swapFeatures(point.id);
    }
  }
  return toWorld(contacts.normal, std::span(contacts.points.data(), contacts.count), xfA, xfB,
                 speculativeDistance);
}

}  // namespace narrow

namespace {

using namespace narrow;

// The point midway between a point of A's surface and a circle B's surface
// along a unit normal (A's frame), with id 0: circle contacts keep id 0
// whichever feature of A they touch, so a circle rolling over a polygon's
// vertex keeps its warm-start impulse.
LocalPoint midSurfacePoint(const Vec2& surfaceA, const Vec2& centerB, Real radiusB, const Vec2& normal,
                           Real separation) {
  Vec2 surfaceB = centerB - radiusB * normal;
  return {Real(0.5) * (surfaceA + surfaceB), separation, makeFeatureId(0, 0)};
}

// That point as a single-point contact.
Manifold circleContact(const Vec2& surfaceA, const Vec2& centerB, Real radiusB, const Vec2& normal,
                       Real separation, const Transform& xfA, const Transform& xfB,
                       Real speculativeDistance) {
  const LocalPoint point = midSurfacePoint(surfaceA, centerB, radiusB, normal, separation);
  return toWorld(normal, std::span(&point, 1), xfA, xfB, speculativeDistance);
}

// Circle B whose centre lies in the Voronoi region of a vertex of A (a core
// vertex, `radiusA` out from A's surface).
Manifold circleVertexContact(const Vec2& vertex, Real radiusA, const Vec2& centerB, Real radiusB,
                             const Transform& xfA, const Transform& xfB, Real speculativeDistance) {
  Vec2 offset = centerB - vertex;
  Real distance = offset.norm();
  Vec2 normal = offset / distance;
  Vec2 surfaceA = radiusA != 0 ? Vec2(vertex + radiusA * normal) : vertex;
  return circleContact(surfaceA, centerB, radiusB, normal, distance - radiusA - radiusB, xfA, xfB,
                       speculativeDistance);
}

}  // namespace

// In A's frame: the normal is the unit vector from A's centre to B's, the
// separation is the centre distance minus both radii, and the point lies
// midway between the two surface points along the normal.
Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b,
                        const Transform& xfB, Real speculativeDistance) {
  const CirclePoint pair = circlesInA(a, xfA, b, xfB);
  return toWorld(pair.normal, std::span(&pair.point, 1), xfA, xfB, speculativeDistance);
}

namespace narrow {

CirclePoint circlesInA(const Circle& a, const Transform& xfA, const Circle& b, const Transform& xfB) {
  Vec2 centerB = placeInA(relativeTransform(xfA, xfB), b.center);
  Vec2 offset = a.center.isZero() ? centerB : Vec2(centerB - a.center);
  Real distance = offset.norm();
  // Concentric circles have no preferred direction; any unit normal gives a
  // valid push apart, and A's local up is as good as any.
  Vec2 normal = distance > kMinDirectionLength ? Vec2(offset / distance) : Vec2(0, 1);
  Vec2 surfaceA = a.center.isZero() ? Vec2(a.radius * normal) : Vec2(a.center + a.radius * normal);
  return {normal, midSurfacePoint(surfaceA, centerB, b.radius, normal, distance - a.radius - b.radius)};
}

}  // namespace narrow

// In A's frame, with c the circle centre, r its radius and R A's rounding:
//   face i = argmax n_i . (c - v_i)           (max separation s)
//   if s > r + R + speculative distance: no contact
//   if c lies outside the core (s > 0) beyond either end of face i:
//     vertex region: normal = (c - v) / |c - v|, separation = |c - v| - r - R
//   else (face region, also when c is inside):
//     normal = n_i, separation = s - r - R
Manifold collidePolygonAndCircle(const Polygon& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB, Real speculativeDistance) {
  Vec2 center = placeInA(relativeTransform(xfA, xfB), b.center);
  FaceQuery face = findMaxSeparation(a, center);
  if (face.separation - b.radius - a.radius >= speculativeDistance) {
    return {};
  }

  const Vec2& v1 = a.vertices[face.index];
  const Vec2& v2 = a.vertices[nextIndex(face.index, a.count)];
  // Only a centre clearly outside gives a well defined vertex direction;
  // |c - v| >= s then guarantees a length to normalise.
  if (face.separation > kMinDirectionLength) {
    if ((center - v1).dot(v2 - v1) < 0) {
      return circleVertexContact(v1, a.radius, center, b.radius, xfA, xfB, speculativeDistance);
    }
    if ((center - v2).dot(v1 - v2) < 0) {
      return circleVertexContact(v2, a.radius, center, b.radius, xfA, xfB, speculativeDistance);
    }
  }

  const Vec2& normal = a.normals[face.index];
  Vec2 onFace = center - face.separation * normal;
  if (a.radius != 0) onFace += a.radius * normal;
  return circleContact(onFace, center, b.radius, normal, face.separation - b.radius - a.radius, xfA,
                       xfB, speculativeDistance);
}

Manifold collidePolygons(const Polygon& a, const Transform& xfA, const Polygon& b,
                         const Transform& xfB, Real speculativeDistance) {
  return collideLocalPolygons(a, transformPolygon(b, relativeTransform(xfA, xfB)), xfA, xfB,
                              speculativeDistance);
}

// A capsule is a rounded two-vertex polygon.
Manifold collidePolygonAndCapsule(const Polygon& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB, Real speculativeDistance) {
  return collidePolygons(a, xfA, makeTwoSidedPolygon(b.center1, b.center2, b.radius), xfB,
                         speculativeDistance);
}

// A segment is a two-vertex polygon of radius 0.
Manifold collideSegmentAndPolygon(const Segment& a, const Transform& xfA, const Polygon& b,
                                  const Transform& xfB, Real speculativeDistance) {
  return collidePolygons(makeTwoSidedPolygon(a.point1, a.point2, 0), xfA, b, xfB,
                         speculativeDistance);
}

}  // namespace impulse
