// Manifolds of one-sided chain segments against solid shapes. A chain
// segment collides on its right side only, and its ghost vertices (its
// neighbours' far ends) tell it which contacts belong to a neighbour, so that
// a body sliding over a join never meets the join's vertex ("ghost
// collisions"). The classification of normals by the Gauss map of the join
// follows Box2D v3 (box2d.org/posts/2020/06/ghost-collisions).

#include <algorithm>
#include <limits>

#include "impulse/manifold.h"
#include "manifold_internal.h"

namespace impulse {
namespace {

using namespace narrow;

// Joins turning less than this (the sine of ~0.6 degrees) count as flat:
// their vertex has no region of its own.
constexpr Real kConvexSine = Real(0.01);
// A normal within this sine of a face normal is that face's.
constexpr Real kNormalSine = Real(0.01);

// The segment and its two joins, in the segment's frame.
struct Joins {
  Vec2 point1 = Vec2::Zero();
  Vec2 point2 = Vec2::Zero();
  Vec2 tangent = Vec2::Zero();  // unit, point1 -> point2
  Vec2 normal = Vec2::Zero();   // the collision side: right of the tangent
  Vec2 normal0 = Vec2::Zero();  // the previous segment's (ghost1 -> point1)
  Vec2 normal2 = Vec2::Zero();  // the next segment's (point2 -> ghost2)
  bool convex1 = false;         // the surface turns away at point1
  bool convex2 = false;
};

Joins makeJoins(const ChainSegment& chain) {
  Joins joins;
  joins.point1 = chain.segment.point1;
  joins.point2 = chain.segment.point2;
  joins.tangent = (joins.point2 - joins.point1).normalized();
  joins.normal = rightPerp(joins.tangent);
  Vec2 edge0 = (joins.point1 - chain.ghost1).normalized();
  Vec2 edge2 = (chain.ghost2 - joins.point2).normalized();
  joins.normal0 = rightPerp(edge0);
  joins.normal2 = rightPerp(edge2);
  joins.convex1 = cross(edge0, joins.tangent) >= kConvexSine;
  joins.convex2 = cross(joins.tangent, edge2) >= kConvexSine;
  return joins;
}

enum class NormalKind {
  Admit,  // this segment's: its face, or within a convex join's vertex region
  Skip,   // past a convex join: the neighbour's face region
  Snap,   // towards a flat or concave join: only the face normal belongs here
};

bool nearFaceNormal(const Joins& joins, const Vec2& normal) {
  return normal.dot(joins.normal) > 0 && std::abs(cross(joins.normal, normal)) < kNormalSine;
}

// Where a contact normal (from the segment to the other shape) falls on the
// Gauss map of the segment and its joins.
NormalKind classify(const Joins& joins, const Vec2& normal) {
  if (nearFaceNormal(joins, normal)) {
    return NormalKind::Admit;
  }
  if (normal.dot(joins.tangent) <= 0) {
    if (!joins.convex1) return NormalKind::Snap;
    return cross(normal, joins.normal0) > kNormalSine ? NormalKind::Skip : NormalKind::Admit;
  }
  if (!joins.convex2) return NormalKind::Snap;
  return cross(joins.normal2, normal) > kNormalSine ? NormalKind::Skip : NormalKind::Admit;
}

// Deepest vertex of the polygon along a normal from a point on the line.
Real deepestAlong(const Polygon& polygon, const Vec2& normal, const Vec2& origin) {
  Real deepest = std::numeric_limits<Real>::max();
  for (int i = 0; i < polygon.count; ++i) {
    deepest = std::min(deepest, normal.dot(polygon.vertices[i] - origin));
  }
  return deepest;
}

// With the polygon's face as reference, the segment is the incident edge
// unless a neighbour faces the polygon's face more directly at the deeper
// end: then that neighbour's contact it is.
bool neighbourIsIncident(const Joins& joins, const Vec2& faceNormal, const Vec2& faceVertex) {
  bool point1Deeper =
      faceNormal.dot(joins.point1 - faceVertex) < faceNormal.dot(joins.point2 - faceVertex);
  const Vec2& neighbour = point1Deeper ? (joins.convex1 ? joins.normal0 : joins.normal)
                                       : (joins.convex2 ? joins.normal2 : joins.normal);
  return neighbour.dot(faceNormal) < joins.normal.dot(faceNormal);
}

// When the polygon's incident edge lies wholly past an end of the segment,
// the contact is a vertex's, and it is this segment's only if the edge lies
// in front of the segment: past the end and below the segment's line, the
// polygon rests on the neighbour (clipping would measure it along this
// face's normal, deep and wrong).
bool reachesFromTheFront(const Joins& joins, const Polygon& polygon, int incidentEdge) {
  const Vec2& w1 = polygon.vertices[incidentEdge];
  const Vec2& w2 = polygon.vertices[nextIndex(incidentEdge, polygon.count)];
  // The incident edge runs against the tangent: w2 is its lower end.
  Real length = joins.tangent.dot(joins.point2 - joins.point1);
  bool beforePoint1 = joins.tangent.dot(w1 - joins.point1) < 0;
  bool pastPoint2 = joins.tangent.dot(w2 - joins.point1) > length;
  if (!beforePoint1 && !pastPoint2) return true;
  const Vec2& vertex = beforePoint1 ? joins.point1 : joins.point2;
  Vec2 gap = closestPointOnSegment(vertex, w1, w2) - vertex;
  return joins.normal.dot(gap) > kMinDirectionLength;
}

}  // namespace

// In the segment's frame, with c the centre:
//   behind the segment's line: no contact (one-sided)
//   before point1 and within the previous segment's reach (c projects onto
//   it), or past point2 and within the next one's: the neighbour's contact
//   else the nearest point of the segment, as for a segment and a circle
Manifold collideChainSegmentAndCircle(const ChainSegment& a, const Transform& xfA, const Circle& b,
                                      const Transform& xfB, Real speculativeDistance) {
  Vec2 center = placeInA(relativeTransform(xfA, xfB), b.center);
  const Vec2& p1 = a.segment.point1;
  const Vec2& p2 = a.segment.point2;
  Vec2 edge = p2 - p1;
  if (rightPerp(edge).dot(center - p1) < 0) {
    return {};
  }
  Vec2 nearest;
  if (edge.dot(center - p1) <= 0) {
    if ((p1 - a.ghost1).dot(center - p1) <= 0) return {};
    nearest = p1;
  } else if (edge.dot(p2 - center) <= 0) {
    if ((a.ghost2 - p2).dot(center - p2) > 0) return {};
    nearest = p2;
  } else {
    nearest = closestPointOnSegment(center, p1, p2);
  }
  Vec2 offset = center - nearest;
  Real distance = offset.norm();
  if (distance - b.radius >= speculativeDistance) {
    return {};
  }
  Vec2 normal =
      distance > kMinDirectionLength ? Vec2(offset / distance) : Vec2(rightPerp(edge).normalized());
  Vec2 surfaceB = center - b.radius * normal;
  LocalPoint point{Real(0.5) * (nearest + surfaceB), distance - b.radius, makeFeatureId(0, 0)};
  return toWorld(normal, std::span(&point, 1), xfA, xfB, speculativeDistance);
}

// In the segment's frame (the polygon, rounded by r, transformed into it):
//   the polygon's centroid behind the segment and behind each convex
//   neighbour: no contact (one-sided)
//   the full separating axis test of the two cores beyond r + speculative
//   distance: no contact
//   one-sided axes: the segment's normal; each convex neighbour's normal
//   (the neighbour's contact if it separates most); the polygon's faces
//   whose reversed normal this segment admits
//   polygon face clearly best: clip the segment to it, unless a neighbour
//   faces it more directly at the deeper end
//   else the segment's face: clip the polygon's incident edge to it, unless
//   that edge lies wholly past an end and not in front of the segment
//   a single corner point whose normal the segment does not admit: none;
//   within a sine of 0.01 of the face normal: the face normal
Manifold collideChainSegmentAndPolygon(const ChainSegment& a, const Transform& xfA,
                                       const Polygon& b, const Transform& xfB,
                                       Real speculativeDistance) {
  Polygon localB = transformPolygon(b, relativeTransform(xfA, xfB));
  Joins joins = makeJoins(a);
  const Vec2& c = localB.centroid;
  bool behind1 = joins.normal.dot(c - joins.point1) < 0;
  bool behind0 = !joins.convex1 || joins.normal0.dot(c - joins.point1) < 0;
  bool behind2 = !joins.convex2 || joins.normal2.dot(c - joins.point2) < 0;
  if (behind1 && behind0 && behind2) {
    return {};
  }

  Polygon segment = makeTwoSidedPolygon(joins.point1, joins.point2, 0);
  Real coreSeparation = std::max(findMaxSeparation(segment, localB).separation,
                                 findMaxSeparation(localB, segment).separation);
  if (coreSeparation - localB.radius >= speculativeDistance) {
    return {};
  }

  Real faceSeparation = deepestAlong(localB, joins.normal, joins.point1);
  Real neighbourSeparation = -std::numeric_limits<Real>::max();
  if (joins.convex1) {
    neighbourSeparation = deepestAlong(localB, joins.normal0, joins.point1);
  }
  if (joins.convex2) {
    neighbourSeparation =
        std::max(neighbourSeparation, deepestAlong(localB, joins.normal2, joins.point2));
  }
  FaceQuery polygonFace;
  for (int i = 0; i < localB.count; ++i) {
    const Vec2& n = localB.normals[i];
    if (classify(joins, -n) != NormalKind::Admit) continue;
    Real separation = std::min(n.dot(joins.point1 - localB.vertices[i]),
                               n.dot(joins.point2 - localB.vertices[i]));
    if (separation > polygonFace.separation) polygonFace = {i, separation};
  }

  EdgeContacts contacts;
  if (polygonFace.separation > std::max(faceSeparation, neighbourSeparation) + kFaceTolerance) {
    const Vec2& faceNormal = localB.normals[polygonFace.index];
    if (neighbourIsIncident(joins, faceNormal, localB.vertices[polygonFace.index])) {
      return {};
    }
    contacts = clipIncidentEdge(localB, polygonFace.index, segment, 0);
    contacts.normal = -contacts.normal;
    for (LocalPoint& point : contacts.points) point.id = swapFeatures(point.id);
  } else {
    if (neighbourSeparation > faceSeparation) {
      return {};
    }
    int incidentEdge = findIncidentEdge(localB, joins.normal);
    if (!reachesFromTheFront(joins, localB, incidentEdge)) {
      return {};
    }
    contacts = clipIncidentEdge(segment, 0, localB, incidentEdge);
  }
  if (contacts.count == 1) {
    if (classify(joins, contacts.normal) != NormalKind::Admit) {
      return {};
    }
    // A vertex's normal this close to the face's is the face's: otherwise a
    // body resting across a flat join would be tilted by where round-off
    // puts the vertex.
    if (nearFaceNormal(joins, contacts.normal)) contacts.normal = joins.normal;
  }
  return toWorld(contacts.normal, std::span(contacts.points.data(), contacts.count), xfA, xfB,
                 speculativeDistance);
}

// A capsule is a rounded two-vertex polygon.
Manifold collideChainSegmentAndCapsule(const ChainSegment& a, const Transform& xfA,
                                       const Capsule& b, const Transform& xfB,
                                       Real speculativeDistance) {
  return collideChainSegmentAndPolygon(a, xfA, makeTwoSidedPolygon(b.center1, b.center2, b.radius),
                                       xfB, speculativeDistance);
}

}  // namespace impulse
