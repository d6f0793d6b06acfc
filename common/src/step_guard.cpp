// The step guard. Input limits keep every accepted number in a range where
// float cannot overflow, so this should never repair anything; it exists so
// that a solver bug or an input path nobody thought of still cannot let NaN
// or infinity out of a step (SPEC: "no NaN or infinite state, ever").

#include "step_guard.h"

#include <algorithm>
#include <limits>

namespace impulse {

namespace {

bool stateIsFinite(const Body& body) {
  return isFinite(body.transform.p) && isFinite(body.transform.q.c) &&
         isFinite(body.transform.q.s) && isFinite(body.linearVelocity) &&
         isFinite(body.angularVelocity);
}

// Warm-start impulses computed from a broken state would carry it into the
// next step through every neighbour (contacts and joints).
void forgetImpulses(WorldData& world, const Body& body) {
  forEachEdge(world.contacts, body.contactHead, [](std::int32_t, Contact& contact) {
    for (ManifoldPoint& point : contact.manifold.points) {
      point.normalImpulse = 0;
      point.tangentImpulse = 0;
      point.supportImpulse = 0;
    }
    contact.manifold.rollingImpulse = 0;
  });
  forEachEdge(world.joints, body.jointHead, [](std::int32_t, Joint& joint) {
    joint.impulses = {};
    joint.reactionForce.setZero();
    joint.reactionTorque = 0;
  });
}

void repair(WorldData& world, std::int32_t slot) {
  Body& body = world.bodies[slot];
  body.transform = {body.center0, body.rotation0};
  // center0 came out of the previous (guarded) step or a validated creation;
  // the world origin is the fallback should even that be broken.
  if (!isFinite(body.transform.p)) body.transform.p.setZero();
  if (!isFinite(body.transform.q.c) || !isFinite(body.transform.q.s)) body.transform.q = Rot{};
  body.linearVelocity.setZero();
  body.angularVelocity = 0;
  body.force.setZero();
  body.torque = 0;
  forgetImpulses(world, body);
  moveBodyProxies(world, slot);
}

// Scaling a velocity down to the limit can round its length an ulp or two
// above it; aiming a few ulps below keeps the result within.
constexpr Real kJustBelowLimit = 1 - 8 * std::numeric_limits<Real>::epsilon();

// True when the body was slowed.
bool clampSpeeds(Body& body, const InputLimits& limits) {
  bool clamped = false;
  const Real speed = body.linearVelocity.norm();
  if (speed > limits.maxSpeed) {
    body.linearVelocity *= kJustBelowLimit * limits.maxSpeed / speed;
    clamped = true;
  }
  if (std::abs(body.angularVelocity) > limits.maxAngularSpeed) {
    body.angularVelocity = std::copysign(limits.maxAngularSpeed, body.angularVelocity);
    clamped = true;
  }
  return clamped;
}

bool farOutside(const AABB& bounds, Real margin, const Vec2& p) {
  return p.x() < bounds.lower.x() - margin || p.y() < bounds.lower.y() - margin ||
         p.x() > bounds.upper.x() + margin || p.y() > bounds.upper.y() + margin;
}

// What the guard found of a moved body, a bit each.
enum GuardFinding : std::uint8_t { kBroken = 1, kClamped = 2, kEscaped = 4 };

// Reads and writes only its own body, so the moved bodies are checked side
// by side. A broken body is only reported: its repair touches its contacts
// and joints and the tree.
std::uint8_t checkBody(Body& body, const InputLimits& limits, const AABB& bounds) {
  if (!stateIsFinite(body)) return kBroken;
  std::uint8_t finding = clampSpeeds(body, limits) ? kClamped : 0;
  if (farOutside(bounds, limits.escapeMargin, body.transform.p)) finding |= kEscaped;
  return finding;
}

// Moved bodies per range of the side-by-side check: a check costs a few
// nanoseconds.
constexpr std::int32_t kBodiesPerRange = 1024;

}  // namespace

void guardStep(WorldData& world, StepGuardReport& report) {
  report.escaped.clear();
  const InputLimits& limits = world.settings.inputLimits;
  const AABB& bounds = world.settings.bounds;
  std::vector<std::uint8_t>& findings = world.guardFindings;
  findings.resize(world.movedBodies.size());
  world.tasks.forRanges(static_cast<std::int32_t>(findings.size()), kBodiesPerRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          for (std::int32_t i = begin; i < end; ++i) {
                            const std::int32_t slot = world.movedBodies[std::size_t(i)].slot();
                            findings[std::size_t(i)] = checkBody(world.bodies[slot], limits, bounds);
                          }
                        });
  for (std::size_t i = 0; i < findings.size(); ++i) {
    std::uint8_t finding = findings[i];
    if (finding == 0) continue;
    const BodyId id = world.movedBodies[i];
    if ((finding & kBroken) != 0) {
      repair(world, id.slot());
      ++report.repairedBodies;
      finding = checkBody(world.bodies[id.slot()], limits, bounds);
    }
    if ((finding & kClamped) != 0) ++report.clampedBodies;
    if ((finding & kEscaped) != 0) report.escaped.push_back(id);
  }
  if (report.escaped.empty()) return;
  std::sort(report.escaped.begin(), report.escaped.end());
  std::erase_if(world.movedBodies, [&](BodyId id) {
    return std::binary_search(report.escaped.begin(), report.escaped.end(), id);
  });
}

}  // namespace impulse
