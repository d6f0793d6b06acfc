#include "contact_solver.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include "edge_list.h"
#include "support_pass.h"

namespace impulse {

namespace {

Vec2 pointVelocity(const SolverState& state, const Vec2& anchor) {
  return state.linearVelocity + cross(state.angularVelocity, anchor);
}

// Relative velocity of B's anchor over A's along the normal (positive:
// separating).
Real normalVelocity(const SolverState& a, const SolverState& b, const ContactConstraint& c,
                    const ConstraintPoint& cp) {
  return (pointVelocity(b, cp.anchorB) - pointVelocity(a, cp.anchorA)).dot(c.normal);
}

void applyImpulse(SolverState& a, SolverState& b, const ContactConstraint& c, const Vec2& anchorA,
                  const Vec2& anchorB, const Vec2& impulse) {
  a.linearVelocity -= c.invMassA * impulse;
  a.angularVelocity -= c.invInertiaA * cross(anchorA, impulse);
  b.linearVelocity += c.invMassB * impulse;
  b.angularVelocity += c.invInertiaB * cross(anchorB, impulse);
}

// A soft contact carries a steady impulse L per sub-step at the overlap where
// its spring pushes L back: impulseScale * L = normalMass * massScale *
// biasRate * overlap. That overlap is the contact's load, not an intrusion.
Real overlapForLoad(const Softness& softness, Real normalMass, Real impulse) {
  Real stiffness = normalMass * softness.massScale * softness.biasRate;
  return stiffness > 0 ? softness.impulseScale * impulse / stiffness : Real(0);
}

Real effectiveMass(const ContactConstraint& c, const Vec2& anchorA, const Vec2& anchorB,
                   const Vec2& direction) {
  Real ra = cross(anchorA, direction);
  Real rb = cross(anchorB, direction);
  Real k = c.invMassA + c.invMassB + c.invInertiaA * ra * ra + c.invInertiaB * rb * rb;
  return k > 0 ? Real(1) / k : Real(0);
}

void solveNormalRows(ContactConstraint& c, SolverState& a, SolverState& b, const Vec2& deltaPosition,
                     const ContactSolverContext& context, bool useBias, Real& totalNormalImpulse) {
  for (int k = 0; k < c.pointCount; ++k) {
    ConstraintPoint& cp = c.points[context.reversePointOrder ? c.pointCount - 1 - k : k];
    // Current separation from the start-of-step value and the motion since:
    // anchors are fixed in the bodies, rotated by the accumulated rotation.
    Vec2 moved = deltaPosition + b.deltaRotation.apply(cp.anchorB) - a.deltaRotation.apply(cp.anchorA);
    Real separation = cp.baseSeparation + moved.dot(c.normal);

    Real bias = 0;
    Real massScale = 1;
    Real impulseScale = 0;
    if (separation > 0) {
      bias = separation * context.inverseSubStep;  // speculative: close the gap exactly
    } else if (useBias) {
      bias = std::max(c.softness.biasRate * separation, -cp.pushCap) - cp.holdSpeed;
      massScale = c.softness.massScale;
      impulseScale = c.softness.impulseScale;
    }

    Real vn = normalVelocity(a, b, c, cp);
    Real impulse = -cp.normalMass * massScale * (vn + bias) - impulseScale * cp.normalImpulse;
    Real accumulated = std::max(cp.normalImpulse + impulse, Real(0));
    impulse = accumulated - cp.normalImpulse;
    cp.normalImpulse = accumulated;
    cp.totalNormalImpulse += impulse;
    totalNormalImpulse += accumulated;
    applyImpulse(a, b, c, cp.anchorA, cp.anchorB, impulse * c.normal);
  }
}

void solveFrictionRows(ContactConstraint& c, SolverState& a, SolverState& b) {
  Vec2 tangent = rightPerp(c.normal);
  for (int j = 0; j < c.pointCount; ++j) {
    ConstraintPoint& cp = c.points[j];
    Real vt = (pointVelocity(b, cp.anchorB) - pointVelocity(a, cp.anchorA)).dot(tangent);
    Real limit = cp.friction * (cp.normalImpulse + cp.supportImpulse);
    Real accumulated = std::clamp(cp.tangentImpulse - cp.tangentMass * vt, -limit, limit);
    Real impulse = accumulated - cp.tangentImpulse;
    cp.tangentImpulse = accumulated;
    applyImpulse(a, b, c, cp.anchorA, cp.anchorB, impulse * tangent);
  }
}

void solveRollingRow(ContactConstraint& c, SolverState& a, SolverState& b, Real totalNormalImpulse) {
  if (c.rollingResistance == 0) return;
  Real limit = c.rollingResistance * totalNormalImpulse;
  Real previous = c.rollingImpulse;
  c.rollingImpulse = std::clamp(previous - c.rollingMass * (b.angularVelocity - a.angularVelocity),
                                -limit, limit);
  Real impulse = c.rollingImpulse - previous;
  a.angularVelocity -= c.invInertiaA * impulse;
  b.angularVelocity += c.invInertiaB * impulse;
}

bool intrudes(Real separation, Real loadOverlap) { return separation + loadOverlap < -kIntrusionSlop; }

// The push that holds a share of a point's load with no overlap, by the
// load in weights of the lighter body (kHold's ramp, contact_solver.h;
// kHangingHold's where a body hangs), on a contact off level between two
// moving bodies without joints, not intruding.
Real holdSpeedFor(const ConstraintRef& ref, const ContactConstraint& c, const ConstraintPoint& cp, Real load,
                  bool intruding, Real weightPerMass) {
  if (weightPerMass == 0 || !mayHoldAsWedge(ref) || intruding) return 0;
  const Real weights = load * std::max(c.invMassA, c.invMassB) / weightPerMass;
  const HoldRamp& ramp = ref.hangs ? kHangingHold : kHold;
  const Real share = ramp.share * std::clamp((weights - ramp.fromWeights) / (ramp.fullWeights - ramp.fromWeights),
                                             Real(0), Real(1));
  return std::min(share * c.softness.biasRate * cp.loadOverlap, kHoldSpeedSubSteps * weightPerMass);
}

}  // namespace

Real pushCapForLoad(Real biasRate, Real loadOverlap, bool heldToLoad, Real maxPushSpeed) {
  const Real fastest = std::max(maxPushSpeed, kMinPushSpeed);
  if (heldToLoad) return std::min(biasRate * loadOverlap, fastest);
  return std::clamp(kLoadPushMargin * biasRate * loadOverlap, kMinPushSpeed, fastest);
}

void prepareContact(const WorldData& world, const ConstraintRef& ref, const ContactSoftness& softness,
                    Real startImpulse, ContactConstraint& c) {
  const Contact& contact = world.contacts[ref.contact];
  const Body& bodyA = world.bodies[contact.edges.bodyA];
  const Body& bodyB = world.bodies[contact.edges.bodyB];
  const Manifold& manifold = contact.manifold;
  c.stateA = ref.stateA;
  c.stateB = ref.stateB;
  c.contact = ref.contact;
  c.pointCount = manifold.pointCount;
  c.normal = manifold.normal;
  c.invMassA = bodyA.awake ? bodyA.invMass : 0;
  c.invInertiaA = bodyA.awake ? bodyA.invInertia : 0;
  c.invMassB = bodyB.awake ? bodyB.invMass : 0;
  c.invInertiaB = bodyB.awake ? bodyB.invInertia : 0;
  c.restitution = contact.restitution;
  c.rollingResistance = contact.rollingResistance;
  c.rollingImpulse = manifold.rollingImpulse;
  Real rollingK = c.invInertiaA + c.invInertiaB;
  c.rollingMass = rollingK > 0 ? Real(1) / rollingK : Real(0);
  c.softness = (c.stateA == 0 || c.stateB == 0) ? softness.statics : softness.dynamic;

  const SolverState& a = world.solverStates[c.stateA];
  const SolverState& b = world.solverStates[c.stateB];
  Vec2 tangent = rightPerp(c.normal);
  Real stickSpeed = world.settings.stickSpeed;
  for (int j = 0; j < c.pointCount; ++j) {
    const ManifoldPoint& mp = manifold.points[j];
    ConstraintPoint& cp = c.points[j];
    cp.anchorA = mp.anchorA;
    cp.anchorB = mp.anchorB;
    cp.normalImpulse = mp.normalImpulse + (mp.separation <= kStartTouch ? startImpulse : Real(0));
    cp.tangentImpulse = mp.tangentImpulse;
    cp.supportImpulse = ref.holdsUp ? mp.supportImpulse : Real(0);
    cp.totalNormalImpulse = 0;
    cp.baseSeparation = mp.separation - (mp.anchorB - mp.anchorA).dot(c.normal);
    cp.normalMass = effectiveMass(c, cp.anchorA, cp.anchorB, c.normal);
    cp.tangentMass = effectiveMass(c, cp.anchorA, cp.anchorB, tangent);
    Vec2 relative = pointVelocity(b, cp.anchorB) - pointVelocity(a, cp.anchorA);
    cp.relativeVelocity = relative.dot(c.normal);
    // The load includes what the support pass carried, or a held-up body's
    // resting overlap would read as an intrusion to push out.
    const Real load = mp.normalImpulse + cp.supportImpulse;
    cp.loadOverlap = overlapForLoad(c.softness, cp.normalMass, load);
    const bool intruding = intrudes(mp.separation, cp.loadOverlap);
    const bool heldToLoad = c.stateA != 0 && c.stateB != 0 && intruding;
    cp.pushCap = pushCapForLoad(c.softness.biasRate, cp.loadOverlap, heldToLoad,
                                world.settings.maxContactPushSpeed);
    cp.holdSpeed = holdSpeedFor(ref, c, cp, load, intruding, softness.weightPerMass);
    // Coulomb with two coefficients: a contact that is not slipping is held
    // by static friction; once it slips, dynamic friction opposes it.
    cp.friction = std::abs(relative.dot(tangent)) < stickSpeed ? contact.staticFriction
                                                                 : contact.dynamicFriction;
  }
}

void warmStartContacts(const ContactSolverContext& context) {
  for (ContactConstraint& c : context.constraints) {
    SolverState& a = context.states[c.stateA];
    SolverState& b = context.states[c.stateB];
    Vec2 tangent = rightPerp(c.normal);
    for (int j = 0; j < c.pointCount; ++j) {
      ConstraintPoint& cp = c.points[j];
      cp.totalNormalImpulse += cp.normalImpulse;
      applyImpulse(a, b, c, cp.anchorA, cp.anchorB,
                   cp.normalImpulse * c.normal + cp.tangentImpulse * tangent);
    }
    a.angularVelocity -= c.invInertiaA * c.rollingImpulse;
    b.angularVelocity += c.invInertiaB * c.rollingImpulse;
  }
}

void solveContacts(const ContactSolverContext& context, bool useBias) {
  for (ContactConstraint& c : context.constraints) {
    SolverState& a = context.states[c.stateA];
    SolverState& b = context.states[c.stateB];
    Vec2 deltaPosition = b.deltaPosition - a.deltaPosition;
    Real totalNormalImpulse = 0;
    solveNormalRows(c, a, b, deltaPosition, context, useBias, totalNormalImpulse);
    solveFrictionRows(c, a, b);
    solveRollingRow(c, a, b, totalNormalImpulse);
  }
}

namespace {

// Gives the bodies jointed to one at `ring`, and theirs, the same mark: the
// joint tree pass carries a push through a jointed group as a whole, and a
// limb pushed into a contact the pass left out would end the step inside it.
void markJointedAlike(const WorldData& world, std::uint8_t ring, WideContactSet& set) {
  std::vector<std::uint8_t>& zone = set.pushZone;
  std::vector<std::int32_t>& queue = set.pushQueue;
  queue.clear();
  for (std::size_t state = 1; state < zone.size(); ++state) {
    if (zone[state] == ring) queue.push_back(std::int32_t(state));
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t slot = world.solverIntegration[std::size_t(queue[head])].body;
    forEachEdge(world.joints, world.bodies[slot].jointHead, [&](std::int32_t key, const Joint& joint) {
      const std::int32_t other = joint.edges.otherBody(key);
      if (other == kNullIndex || !world.bodies[other].awake) return;  // the world, or asleep: state 0
      const std::int32_t state = world.bodies[other].solverIndex;
      if (state == 0 || zone[std::size_t(state)] != 0) return;
      zone[std::size_t(state)] = ring;
      queue.push_back(state);
    });
  }
}

// Refs per range of a ring's marking: a ref costs a few nanoseconds.
constexpr std::int32_t kRefsPerMarkRange = 1024;

// Marks the bodies a contact from one of `ring` with the next ring, over
// zeros only, the refs side by side. Two ranges may mark one body: both
// write the same mark over a zero, and a mark being written reads as zero
// or as the next ring, neither of which is `ring`; so the marks are the
// same for any order and split of the refs (relaxed atomics, plain moves
// on x86). Without a branch: a mark that is not made goes to a byte of the
// range's own (in a crowd, whether a ref marks is a coin toss, which the
// branches mispredicted).
void markNextRing(const TaskRunner& tasks, std::span<const ConstraintRef> refs, std::uint8_t ring,
                  std::vector<std::uint8_t>& zone) {
  const auto markOf = [&](std::int32_t state) { return std::atomic_ref<std::uint8_t>(zone[std::size_t(state)]); };
  tasks.forRanges(std::int32_t(refs.size()), kRefsPerMarkRange, [&](std::int32_t begin, std::int32_t end) {
    std::uint8_t unmade = 0;
    const auto markNext = [&](std::int32_t from, std::int32_t to) {
      const bool marks = (int(to != 0) & int(markOf(from).load(std::memory_order_relaxed) == ring) &
                          int(markOf(to).load(std::memory_order_relaxed) == 0)) != 0;
      std::uint8_t& mark = marks ? zone[std::size_t(to)] : unmade;
      std::atomic_ref<std::uint8_t>(mark).store(std::uint8_t(ring - 1), std::memory_order_relaxed);
    };
    for (const ConstraintRef& ref : refs.subspan(std::size_t(begin), std::size_t(end - begin))) {
      markNext(ref.stateA, ref.stateB);
      markNext(ref.stateB, ref.stateA);
    }
  });
}

}  // namespace

void markNearIntrusions(const WorldData& world, std::span<const ConstraintRef> refs, WideContactSet& set) {
  const bool jointed = !world.jointConstraints.empty();
  // Ring by ring outwards; each pass reads one ring and writes the next
  // over zeros only, so the marks do not depend on the contacts' order.
  for (std::uint8_t ring = kIntrudingBody;; --ring) {
    if (jointed) markJointedAlike(world, ring, set);
    if (ring == kNearIntrusion) break;
    markNextRing(world.tasks, refs, ring, set.pushZone);
  }
}

bool hasIntrusion(const ContactConstraint& c, const Manifold& manifold) {
  for (int j = 0; j < c.pointCount; ++j) {
    if (intrudes(manifold.points[j].separation, c.points[j].loadOverlap)) return true;
  }
  return false;
}

void pushOverlap(const ContactSolverContext& context, ContactConstraint& c) {
  SolverState& a = context.states[c.stateA];
  SolverState& b = context.states[c.stateB];
  Vec2 deltaPosition = b.deltaPosition - a.deltaPosition;
  for (int j = 0; j < c.pointCount; ++j) {
    ConstraintPoint& cp = c.points[j];
    Vec2 moved = deltaPosition + b.deltaRotation.apply(cp.anchorB) - a.deltaRotation.apply(cp.anchorA);
    Real intrusion = cp.baseSeparation + moved.dot(c.normal) + cp.loadOverlap;
    if (intrusion >= 0) continue;
    Real bias = std::max(c.softness.biasRate * intrusion, -context.maxPushSpeed);
    Real vn = normalVelocity(a, b, c, cp);
    Real impulse = std::max(-cp.normalMass * c.softness.massScale * (vn + bias), Real(0));
    applyImpulse(a, b, c, cp.anchorA, cp.anchorB, impulse * c.normal);
  }
}

void applyRestitution(const ContactSolverContext& context) {
  for (ContactConstraint& c : context.constraints) {
    if (c.restitution == 0) continue;
    SolverState& a = context.states[c.stateA];
    SolverState& b = context.states[c.stateB];
    for (int j = 0; j < c.pointCount; ++j) {
      ConstraintPoint& cp = c.points[j];
      // Only points that were approaching fast and actually pushed bounce;
      // slow ones rest (no jitter on stacks).
      if (cp.relativeVelocity > -context.restitutionThreshold || cp.totalNormalImpulse == 0) continue;
      Real vn = normalVelocity(a, b, c, cp);
      Real impulse = -cp.normalMass * (vn + c.restitution * cp.relativeVelocity);
      Real accumulated = std::max(cp.normalImpulse + impulse, Real(0));
      impulse = accumulated - cp.normalImpulse;
      cp.normalImpulse = accumulated;
      cp.totalNormalImpulse += impulse;
      applyImpulse(a, b, c, cp.anchorA, cp.anchorB, impulse * c.normal);
    }
  }
}

void storeImpulses(std::span<const ContactConstraint> constraints, WorldData& world) {
  for (const ContactConstraint& c : constraints) {
    Manifold& manifold = world.contacts[c.contact].manifold;
    for (int j = 0; j < c.pointCount; ++j) {
      manifold.points[j].normalImpulse = c.points[j].normalImpulse;
      manifold.points[j].tangentImpulse = c.points[j].tangentImpulse;
      manifold.points[j].supportImpulse = c.points[j].supportImpulse;
    }
    manifold.rollingImpulse = c.rollingImpulse;
  }
}

void BundleSlices::cut(std::span<const std::int32_t> runStarts, int width, std::span<std::int32_t> runBundleStart) {
  first.clear();
  lanes.clear();
  for (std::size_t run = 0; run + 1 < runStarts.size(); ++run) {
    runBundleStart[run] = count();
    for (std::int32_t entry = runStarts[run]; entry < runStarts[run + 1]; entry += width) {
      first.push_back(entry);
      lanes.push_back(static_cast<std::uint8_t>(std::min(width, runStarts[run + 1] - entry)));
    }
  }
  runBundleStart[runStarts.size() - 1] = count();
}

}  // namespace impulse
