// Contact lifetime: creation from broad-phase pairs, manifold updates with
// warm-start matching, and destruction. Contacts live in one array with a
// free list and are threaded through both bodies' edge lists.

#include <algorithm>
#include <utility>

#include "world_data.h"

namespace impulse {

namespace {

Real rollingRadius(const Shape& shape) {
  // Only round shapes roll; a polygon's resistance to tipping is geometric.
  return shape.type == ShapeType::Circle ? shape.circle.radius : Real(0);
}

std::int32_t allocateContact(WorldData& world) {
  std::int32_t index = world.freeContacts.acquire(world.contacts.size());
  if (index == static_cast<std::int32_t>(world.contacts.size())) world.contacts.emplace_back();
  return index;
}

// Threads the contact through both bodies' contact lists.
void linkContact(WorldData& world, std::int32_t index) {
  for (int side = 0; side < 2; ++side) {
    Body& body = world.bodies[world.contacts[index].edges.body(side)];
    linkEdge(world.contacts, body.contactHead, index, side);
  }
}

void createContact(WorldData& world, std::int32_t a, std::int32_t b) {
  // The collide table is filled for shape A's type >= shape B's type.
  if (collideFunction(world.shapes[a].type, world.shapes[b].type) == nullptr) std::swap(a, b);
  const MaterialProperties& ma = world.bodies[a].coefficients;
  const MaterialProperties& mb = world.bodies[b].coefficients;

  std::int32_t index = allocateContact(world);
  Contact& contact = world.contacts[index];
  contact = Contact{};
  contact.edges.bodyA = a;
  contact.edges.bodyB = b;
  contact.collide = collideFunction(world.shapes[a].type, world.shapes[b].type);
  contact.staticFriction = mixCoefficient(ma.staticFriction, mb.staticFriction);
  contact.dynamicFriction = mixCoefficient(ma.dynamicFriction, mb.dynamicFriction);
  contact.restitution = mixCoefficient(ma.restitution, mb.restitution);
  contact.rollingResistance =
      mixCoefficient(ma.rollingResistance, mb.rollingResistance) *
      std::max(rollingRadius(world.shapes[a]), rollingRadius(world.shapes[b]));
  contact.pairKey = contactPairKey(a, b);
  linkContact(world, index);
  world.contactByPair.emplace(contact.pairKey, index);
}

// Carries impulses of points that persist (same feature id) into the new
// manifold, so the solver starts from last step's answer.
void matchWarmStart(const Manifold& previous, Manifold& next) {
  for (int i = 0; i < next.pointCount; ++i) {
    ManifoldPoint& point = next.points[i];
    for (int j = 0; j < previous.pointCount; ++j) {
      const ManifoldPoint& old = previous.points[j];
      if (old.id != point.id) continue;
      point.normalImpulse = old.normalImpulse;
      point.tangentImpulse = old.tangentImpulse;
      point.supportImpulse = old.supportImpulse;
      break;
    }
  }
  if (next.pointCount > 0) next.rollingImpulse = previous.rollingImpulse;
}

// Contacts that involve at least one awake body, each once, in a
// deterministic order (awake list order, then edge order).
void gatherActiveContacts(WorldData& world) {
  world.activeContacts.clear();
  for (std::int32_t slot : world.awakeBodies) {
    forEachEdge(world.contacts, world.bodies[slot].contactHead, [&](std::int32_t key, const Contact& contact) {
      std::int32_t other = contact.edges.otherBody(key);
      // A contact between two awake bodies is taken by the lower slot.
      if (!world.bodies[other].awake || slot < other) world.activeContacts.push_back(edgeElement(key));
    });
  }
}

// B's pose in A's frame.
Transform relativePose(const Body& a, const Body& b) {
  return {a.transform.q.applyInverse(b.transform.p - a.transform.p), relativeRotation(a.transform.q, b.transform.q)};
}

// A contact's manifold is recomputed only once its bodies have moved relative
// to each other since it was computed: slid along the contact or turned by
// more than half a millimetre (at B's rim), or closed or opened by more than
// 5 mm (which stays well inside the 2 cm speculative band the narrow phase
// keeps points for). Until then the manifold's points are carried along with
// the bodies (refreshManifold), exact to first order: a resting or sinking
// stack, or bodies falling together, skip the narrow phase.
constexpr Real kSlideTolerance = Real(5e-4);
constexpr Real kApproachTolerance = Real(5e-3);

bool manifoldIsCurrent(const Contact& contact, const Body& a, const Body& b) {
  const ManifoldFrame& frame = contact.frame;
  if (!frame.computed) return false;
  Transform now = relativePose(a, b);
  Vec2 shift = now.p - frame.relative.p;
  Real approach = shift.dot(frame.localNormal);
  Real slide = (shift - approach * frame.localNormal).norm();
  // Chord a point of B at distance `extent` sweeps under the turn since.
  Real cosine = now.q.c * frame.relative.q.c + now.q.s * frame.relative.q.s;
  Real rimShift = b.extent * std::sqrt(std::max(2 - 2 * cosine, Real(0)));
  return std::abs(approach) <= kApproachTolerance && slide + rimShift <= kSlideTolerance;
}

void recordFrame(Contact& contact, const Body& a, const Body& b) {
  const Manifold& manifold = contact.manifold;
  ManifoldFrame& frame = contact.frame;
  frame.computed = true;
  frame.relative = relativePose(a, b);
  frame.localNormal = a.transform.q.applyInverse(manifold.normal);
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ManifoldPoint& point = manifold.points[i];
    frame.localPointA[i] = a.transform.q.applyInverse(point.anchorA);
    frame.localPointB[i] = b.transform.q.applyInverse(point.anchorB);
    Vec2 gap = (b.transform.p + point.anchorB) - (a.transform.p + point.anchorA);
    frame.offset[i] = point.separation - gap.dot(manifold.normal);
  }
}

// Moves the manifold's points with the bodies: each point's material points
// on A and B, their gap along A's rotated normal, the contact point midway.
void refreshManifold(Contact& contact, const Body& a, const Body& b) {
  Manifold& manifold = contact.manifold;
  const ManifoldFrame& frame = contact.frame;
  manifold.normal = a.transform.q.apply(frame.localNormal);
  for (int i = 0; i < manifold.pointCount; ++i) {
    ManifoldPoint& point = manifold.points[i];
    Vec2 onA = a.transform.p + a.transform.q.apply(frame.localPointA[i]);
    Vec2 onB = b.transform.p + b.transform.q.apply(frame.localPointB[i]);
    point.separation = (onB - onA).dot(manifold.normal) + frame.offset[i];
    point.point = Real(0.5) * (onA + onB);
    point.anchorA = point.point - a.transform.p;
    point.anchorB = point.point - b.transform.p;
  }
}

// Two circles' manifold is one distance and a normal: cheaper to compute
// than to check whether it is still current.
bool carriesManifold(const Contact& contact) {
  static const CollideFunction circles = collideFunction(ShapeType::Circle, ShapeType::Circle);
  return contact.collide != circles;
}

void updateManifold(WorldData& world, std::int32_t index) {
  Contact& contact = world.contacts[index];
  const Body& a = world.bodies[contact.edges.bodyA];
  const Body& b = world.bodies[contact.edges.bodyB];
  const bool carried = carriesManifold(contact);
  if (carried && manifoldIsCurrent(contact, a, b)) {
    refreshManifold(contact, a, b);
    return;
  }
  ++world.profile.manifoldUpdates;
  Manifold next = contact.collide(world.shapes[contact.edges.bodyA], a.transform,
                                  world.shapes[contact.edges.bodyB], b.transform);
  if (world.settings.enableWarmStarting) matchWarmStart(contact.manifold, next);
  contact.manifold = next;
  contact.touching = next.pointCount > 0;
  if (carried) recordFrame(contact, a, b);
}

}  // namespace

void updatePairs(WorldData& world, Real /*dt*/) {
  world.broadPhase.findNewPairs(world.newPairs, [&](std::int32_t first, std::int32_t second) {
    return world.contactByPair.contains(contactPairKey(first, second));
  });
  for (const ProxyPair& pair : world.newPairs) {
    const Body& a = world.bodies[pair.first];
    const Body& b = world.bodies[pair.second];
    if (a.isStatic && b.isStatic) continue;
    if (jointBlocksContact(world, pair.first, pair.second)) continue;
    createContact(world, pair.first, pair.second);
  }
}

void collideContacts(WorldData& world, Real /*dt*/) {
  world.profile.manifoldUpdates = 0;
  gatherActiveContacts(world);
  world.touchingContacts.clear();
  const std::size_t awakeCount = world.awakeBodies.size();
  for (std::int32_t index : world.activeContacts) {
    Contact& contact = world.contacts[index];
    const Body& a = world.bodies[contact.edges.bodyA];
    const Body& b = world.bodies[contact.edges.bodyB];
    if (!world.broadPhase.fatAABBsOverlap(a.proxyKey, b.proxyKey)) {
      destroyContact(world, index);
      continue;
    }
    updateManifold(world, index);
    // A touch from an awake body wakes a sleeping one, with its island.
    if (contact.touching) {
      world.touchingContacts.push_back(index);
      wakeIsland(world, contact.edges.bodyA);
      wakeIsland(world, contact.edges.bodyB);
    }
  }
  // Unchanged when nothing woke: then the list is what the solver would
  // collect, in the same order.
  world.touchingForAwakeCount = awakeCount;
}

void destroyContact(WorldData& world, std::int32_t index) {
  for (int side = 0; side < 2; ++side) {
    Body& body = world.bodies[world.contacts[index].edges.body(side)];
    unlinkEdge(world.contacts, body.contactHead, index, side);
  }
  world.contactByPair.erase(world.contacts[index].pairKey);
  world.freeContacts.release(index);
}

void destroyBodyContacts(WorldData& world, std::int32_t body) {
  while (world.bodies[body].contactHead != kNullIndex) {
    std::int32_t key = world.bodies[body].contactHead;
    const Contact& contact = world.contacts[edgeElement(key)];
    if (contact.touching) wakeIsland(world, contact.edges.otherBody(key));
    destroyContact(world, edgeElement(key));
  }
}

}  // namespace impulse
