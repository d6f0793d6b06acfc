#pragma once
// A contact: a pair of shapes whose fat boxes overlap, its manifold and the
// coefficients mixed from the two materials (contact.cpp keeps them).

#include <algorithm>
#include <cstdint>

#include "edge_list.h"
#include "impulse/manifold.h"
#include "shape_data.h"
#include "shape_pair.h"

namespace impulse {

/// The key of a pair of shape slots in WorldData::contactByPair, either order.
inline std::uint64_t contactPairKey(std::int32_t a, std::int32_t b) {
  auto lo = static_cast<std::uint64_t>(std::min(a, b));
  auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

/// What preparing the solver reads of a contact: its manifold and the
/// coefficients mixed from the two materials. A contact begins with it, on
/// the first two cache lines of an aligned contact, which the solver fetches
/// ahead of filling the contact's bundle lane (contact_solver_wide_impl.h).
struct ContactSolverPart {
  Manifold manifold;
  Real staticFriction = 0;
  Real dynamicFriction = 0;
  Real restitution = 0;
  /// Rolling resistance as a length: c_rr times the rolling radius.
  Real rollingResistance = 0;
};
static_assert(sizeof(ContactSolverPart) <= 128, "the solver's part of a contact fits two cache lines");

struct alignas(64) Contact : ContactSolverPart {
  /// The two bodies and this contact's place in their edge lists.
  EdgeLinks edges;
  /// The two shapes (slots), A's on edges.bodyA.
  std::int32_t shapeA = -1;
  std::int32_t shapeB = -1;
  /// Either shape is round (ShapeSlot::rolls): read by the support pass's
  /// second levelling only, off the refs' lines.
  bool rolls = false;
  /// Either shape is a chain segment: continuous collision looks among
  /// these alone for bodies pressed into a static chain.
  bool onChain = false;
  ManifoldFrame frame;
  CollideFunction collide = nullptr;
  std::uint64_t pairKey = 0;
  bool touching = false;
  /// Either shape asked for touch events, or for hit events.
  bool reportsTouch = false;
  bool reportsHits = false;
};

/// A contact's two shapes (slots a and b, A's first) and what it keeps of
/// them: how they collide, whether either rolls, and the pair's key.
inline void setContactShapes(Contact& contact, std::int32_t a, const ShapeSlot& shapeA, std::int32_t b,
                             const ShapeSlot& shapeB) {
  contact.shapeA = a;
  contact.shapeB = b;
  contact.rolls = shapeA.rolls() || shapeB.rolls();
  contact.onChain = shapeA.type() == ShapeType::ChainSegment || shapeB.type() == ShapeType::ChainSegment;
  contact.collide = collideFunction(shapeA.type(), shapeB.type());
  contact.pairKey = contactPairKey(a, b);
}

}  // namespace impulse
