#pragma once
// Pieces of the narrow phase shared by the collide functions of manifold.cpp
// (polygons and circles), collide_capsule.cpp and collide_chain.cpp. Every
// function works in A's frame and converts to world at the end (toWorld).

#include <array>
#include <cstdint>
#include <limits>
#include <span>

#include "impulse/manifold.h"

namespace impulse::narrow {

// Reference face hysteresis: B's face is used only when it separates clearly
// more than A's, so that two nearly equal faces (a box resting flat on a box)
// do not swap roles, and contact ids, from one step to the next.
inline constexpr Real kFaceTolerance = Real(0.1) * kLinearSlop;

// Below a micrometre, float round-off in scene coordinates of tens of metres
// dominates a vector, so its direction is noise and normalising it could
// divide by zero.
inline constexpr Real kMinDirectionLength = Real(1e-6);

// A contact point in A's local frame, before conversion to world.
struct LocalPoint {
  Vec2 point = Vec2::Zero();
  Real separation = 0;
  std::uint16_t id = 0;
};

// Face of a polygon that separates the other shape the most.
struct FaceQuery {
  int index = 0;
  Real separation = -std::numeric_limits<Real>::max();
};

// Contacts of a reference face with an incident edge, in A's frame, with the
// normal pointing out of the reference face and ids in (reference, incident)
// order.
struct EdgeContacts {
  Vec2 normal = Vec2::Zero();
  std::array<LocalPoint, 2> points{};
  int count = 0;
};

inline int nextIndex(int i, int count) { return i + 1 < count ? i + 1 : 0; }

// B's transform in A's frame. Working there keeps the numbers near the origin
// even when both bodies are far from the world origin.
inline Transform relativeTransform(const Transform& xfA, const Transform& xfB) {
  return {xfA.q.applyInverse(xfB.p - xfA.p), relativeRotation(xfA.q, xfB.q)};
}

// A point of B's frame in A's frame, given B's transform there. The body
// origin (a centred shape, the common case) skips the rotation.
inline Vec2 placeInA(const Transform& relative, const Vec2& local) {
  return local.isZero() ? relative.p : relative.apply(local);
}

std::uint16_t swapFeatures(std::uint16_t id);

Polygon transformPolygon(const Polygon& polygon, const Transform& xf);

// A capsule's core (or a segment, radius 0) as a two-sided polygon of two
// vertices: edge 0 runs point1 -> point2 with the right normal, edge 1 back.
Polygon makeTwoSidedPolygon(const Vec2& point1, const Vec2& point2, Real radius);

Vec2 closestPointOnSegment(const Vec2& p, const Vec2& s1, const Vec2& s2);

// Closest points of segments p1-q1 and p2-q2, with their fractions along each.
struct SegmentClosestPoints {
  Real fraction1 = 0;
  Real fraction2 = 0;
  Vec2 point1 = Vec2::Zero();
  Vec2 point2 = Vec2::Zero();
};
SegmentClosestPoints closestPoints(const Vec2& p1, const Vec2& q1, const Vec2& p2, const Vec2& q2);

// Distance from a point to the polygon's core boundary.
Real distanceToBoundary(const Polygon& polygon, const Vec2& p);

// Face whose plane the point lies furthest in front of (least deep behind,
// when the point is inside).
FaceQuery findMaxSeparation(const Polygon& polygon, const Vec2& p);

// Separating axis test over the reference polygon's edge normals.
FaceQuery findMaxSeparation(const Polygon& reference, const Polygon& other);

// Edge of `incident` whose normal is the most anti-parallel to the normal.
int findIncidentEdge(const Polygon& incident, const Vec2& referenceNormal);

// Clips the incident edge to the reference face (or, when it lies wholly
// beside the face, the nearest corner); separations include both radii.
EdgeContacts clipIncidentEdge(const Polygon& reference, int referenceEdge, const Polygon& incident,
                              int incidentEdge);

// A point computed in A's frame, in the world: its anchors on A and B, the
// point itself, its separation and id.
void placeInWorld(const LocalPoint& local, const Transform& xfA, const Transform& xfB, ManifoldPoint& out);

// Two circles in A's frame: the unit normal from A's centre to B's (A's
// local up when the centres coincide) and their one point, midway between
// the surfaces, with id 0.
struct CirclePoint {
  Vec2 normal = Vec2::Zero();
  LocalPoint point;
};
CirclePoint circlesInA(const Circle& a, const Transform& xfA, const Circle& b, const Transform& xfB);

// Converts contacts computed in A's frame to world, keeping only those within
// the speculative distance.
Manifold toWorld(const Vec2& localNormal, std::span<const LocalPoint> points, const Transform& xfA,
                 const Transform& xfB, Real speculativeDistance);

// The manifold of two polygons already in A's frame (localB transformed).
Manifold collideLocalPolygons(const Polygon& a, const Polygon& localB, const Transform& xfA,
                              const Transform& xfB, Real speculativeDistance);

}  // namespace impulse::narrow
