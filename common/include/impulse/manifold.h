#pragma once
/// Narrow phase: contact manifolds between pairs of shapes, as pure functions.

#include <array>
#include <cstdint>

#include "impulse/constants.h"
#include "impulse/math.h"
#include "impulse/shape.h"

namespace impulse {

/// One contact point. Geometry is written by the narrow phase; the impulses
/// are solver state that the world carries from step to step by matching ids
/// (warm starting).
struct ManifoldPoint {
  /// World point midway between the two surfaces.
  Vec2 point = Vec2::Zero();
  /// point minus the centre of mass of A, and of B (world orientation).
  Vec2 anchorA = Vec2::Zero();
  Vec2 anchorB = Vec2::Zero();
  /// Signed distance along the normal: negative when overlapping.
  Real separation = 0;
  /// Feature key (which edges/vertices produced it), stable while the
  /// configuration is stable.
  std::uint16_t id = 0;

  Real normalImpulse = 0;
  Real tangentImpulse = 0;
  /// The support pass's impulse last sub-step (solver state): the part of
  /// the load the soft rows left to it, which friction is limited by too.
  Real supportImpulse = 0;
};

/// Up to two contact points sharing one normal, which points from A to B.
struct Manifold {
  Vec2 normal = Vec2::Zero();
  int pointCount = 0;
  std::array<ManifoldPoint, 2> points{};
  /// Accumulated rolling resistance impulse (solver state).
  Real rollingImpulse = 0;
};

/// A manifold's geometry in the bodies' own frames, for updating it cheaply
/// while the bodies move only a little (contact.cpp). Solver
/// state like the impulses: a saved scene keeps it.
struct ManifoldFrame {
  bool computed = false;                               ///< false until the narrow phase first ran
  Transform relative;                                  ///< B's pose in A's frame when it ran
  Vec2 localNormal = Vec2::Zero();                     ///< in A's frame
  Vec2 localPointA[2] = {Vec2::Zero(), Vec2::Zero()};  ///< material point on A
  Vec2 localPointB[2] = {Vec2::Zero(), Vec2::Zero()};  ///< material point on B
  Real offset[2] = {0, 0};  ///< separation minus the points' gap along the normal
};

/// Feature key of a point made from feature a of shape A and feature b of B.
constexpr std::uint16_t makeFeatureId(int a, int b) {
  return static_cast<std::uint16_t>(((a & 0xFF) << 8) | (b & 0xFF));
}

// Each function returns the points whose separation is below
// `speculativeDistance` (speculative contacts), and no points otherwise. The
// world passes kSpeculativeDistance grown by how far the pair can close in a
// step (contact.cpp), so a fast approach meets its contact before it
// overlaps.
Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b,
                        const Transform& xfB, Real speculativeDistance = kSpeculativeDistance);
Manifold collidePolygonAndCircle(const Polygon& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB,
                                 Real speculativeDistance = kSpeculativeDistance);
Manifold collidePolygons(const Polygon& a, const Transform& xfA, const Polygon& b,
                         const Transform& xfB, Real speculativeDistance = kSpeculativeDistance);
Manifold collideCapsuleAndCircle(const Capsule& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB,
                                 Real speculativeDistance = kSpeculativeDistance);
/// Two points when the capsules lie along each other, one otherwise.
Manifold collideCapsules(const Capsule& a, const Transform& xfA, const Capsule& b,
                         const Transform& xfB, Real speculativeDistance = kSpeculativeDistance);
Manifold collidePolygonAndCapsule(const Polygon& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB,
                                  Real speculativeDistance = kSpeculativeDistance);
Manifold collideSegmentAndCircle(const Segment& a, const Transform& xfA, const Circle& b,
                                 const Transform& xfB,
                                 Real speculativeDistance = kSpeculativeDistance);
Manifold collideSegmentAndCapsule(const Segment& a, const Transform& xfA, const Capsule& b,
                                  const Transform& xfB,
                                  Real speculativeDistance = kSpeculativeDistance);
Manifold collideSegmentAndPolygon(const Segment& a, const Transform& xfA, const Polygon& b,
                                  const Transform& xfB,
                                  Real speculativeDistance = kSpeculativeDistance);
/// Chain segments collide on their right side only, and leave to their
/// neighbours (through the ghost vertices) the contacts that belong to them.
Manifold collideChainSegmentAndCircle(const ChainSegment& a, const Transform& xfA, const Circle& b,
                                      const Transform& xfB,
                                      Real speculativeDistance = kSpeculativeDistance);
Manifold collideChainSegmentAndCapsule(const ChainSegment& a, const Transform& xfA,
                                       const Capsule& b, const Transform& xfB,
                                       Real speculativeDistance = kSpeculativeDistance);
Manifold collideChainSegmentAndPolygon(const ChainSegment& a, const Transform& xfA,
                                       const Polygon& b, const Transform& xfB,
                                       Real speculativeDistance = kSpeculativeDistance);

/// The manifold of any two shapes, normal from a to b (dispatches on their
/// types; the world caches the function per contact instead, shape_pair.h).
Manifold collide(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                 Real speculativeDistance = kSpeculativeDistance);

}  // namespace impulse
