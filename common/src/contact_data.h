#pragma once
// A contact: a pair of bodies whose fat boxes overlap, its manifold and the
// coefficients mixed from the two materials (contact.cpp keeps them).

#include <cstdint>

#include "edge_list.h"
#include "impulse/manifold.h"

namespace impulse {

/// A manifold's geometry in the bodies' own frames, for updating it cheaply
/// while the bodies move only a little (contact.cpp).
struct ManifoldFrame {
  bool computed = false;  ///< false until the narrow phase first ran
  Transform relative;     ///< B's pose in A's frame when it ran
  Vec2 localNormal = Vec2::Zero();  ///< in A's frame
  Vec2 localPointA[2] = {Vec2::Zero(), Vec2::Zero()};  ///< material point on A
  Vec2 localPointB[2] = {Vec2::Zero(), Vec2::Zero()};  ///< material point on B
  Real offset[2] = {0, 0};  ///< separation minus the points' gap along the normal
};

struct Contact {
  /// The two bodies and this contact's place in their edge lists.
  EdgeLinks edges;
  Manifold manifold;
  ManifoldFrame frame;
  CollideFunction collide = nullptr;
  Real staticFriction = 0;
  Real dynamicFriction = 0;
  Real restitution = 0;
  /// Rolling resistance as a length: c_rr times the rolling radius.
  Real rollingResistance = 0;
  std::uint64_t pairKey = 0;
  bool touching = false;
};

}  // namespace impulse
