// The solve phase: soft-step sub-stepping over all awake bodies and their
// touching contacts, then writing the motion back into the bodies.
//
//   prepare contacts (once per step)
//   for each sub-step:
//     integrate velocities (gravity, forces, drag)
//     warm start (apply last impulses)
//     solve contacts with soft position bias (no faster than loads need)
//     push intrusions out through pseudo velocities (split impulse), if any
//     integrate positions
//     relax contacts (no bias: removes the velocity the bias added)
//   restitution, store impulses, finalize bodies

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "contact_solver.h"
#include "contact_solver_wide.h"
#include "world_data.h"

namespace impulse {

namespace {

// Caps keep a body from crossing more than a fraction of the world or
// spinning past a quarter turn per sub-step, whatever the input: no
// infinities can grow from a bad impulse.
constexpr Real kMaxLinearSpeed = 1000;
constexpr Real kMaxRotationPerSubStep = Real(0.25) * std::numbers::pi_v<Real>;
constexpr int kRestitutionIterations = 4;

void loadStates(WorldData& world, Real h) {
  const auto count = world.awakeBodies.size();
  world.solverStates.assign(count + 1, SolverState{});
  world.solverIntegration.resize(count + 1);
  for (std::size_t k = 0; k < count; ++k) {
    std::int32_t slot = world.awakeBodies[k];
    Body& body = world.bodies[slot];
    body.solverIndex = static_cast<std::int32_t>(k + 1);
    body.center0 = body.transform.p;
    body.rotation0 = body.transform.q;
    SolverState& state = world.solverStates[k + 1];
    state.linearVelocity = body.linearVelocity;
    state.angularVelocity = body.angularVelocity;
    SolverIntegration& in = world.solverIntegration[k + 1];
    in.body = slot;
    in.linearAcceleration = body.invMass * body.force;
    if (!body.ignoreGravity) in.linearAcceleration += world.settings.gravity;
    in.angularAcceleration = body.invInertia * body.torque;
    // Exact exponential decay over h: the same drag whatever the tick rate.
    in.linearDamping = body.linearDrag > 0 ? std::exp(-body.linearDrag * h) : Real(1);
    in.angularDamping = body.angularDrag > 0 ? std::exp(-body.angularDrag * h) : Real(1);
  }
}

// The touching contacts the step solves, each once: those of awake bodies
// (a pair of awake bodies taken by the lower slot), in awake-list order.
void collectConstraints(WorldData& world) {
  world.constraintRefs.clear();
  for (std::int32_t slot : world.awakeBodies) {
    for (std::int32_t key = world.bodies[slot].contactHead; key != kNullIndex;) {
      const Contact& contact = world.contacts[edgeContact(key)];
      std::int32_t other = otherBody(contact, key);
      if (contact.touching && (!world.bodies[other].awake || slot < other)) {
        // Anything not awake (static) shares the dummy state 0 and gets zero
        // inverse mass, so the dummy's velocity stays zero without checks.
        const Body& a = world.bodies[contact.bodyA];
        const Body& b = world.bodies[contact.bodyB];
        world.constraintRefs.push_back(
            {edgeContact(key), a.awake ? a.solverIndex : 0, b.awake ? b.solverIndex : 0});
      }
      key = contact.edgeNext[edgeSide(key)];
    }
  }
}

ContactSoftness contactSoftness(const WorldSettings& settings, Real h) {
  Real hertz = std::min(settings.contactHertz, Real(0.25) / h);
  return {makeSoftness(hertz, settings.contactDampingRatio, h),
          makeSoftness(2 * hertz, settings.contactDampingRatio, h)};
}

void integrateVelocities(WorldData& world, Real h) {
  const Real maxAngularSpeed = kMaxRotationPerSubStep / h;
  for (std::size_t k = 1; k < world.solverStates.size(); ++k) {
    SolverState& state = world.solverStates[k];
    const SolverIntegration& in = world.solverIntegration[k];
    Vec2 v = in.linearDamping * (state.linearVelocity + h * in.linearAcceleration);
    Real w = in.angularDamping * (state.angularVelocity + h * in.angularAcceleration);
    Real speedSquared = v.squaredNorm();
    if (speedSquared > kMaxLinearSpeed * kMaxLinearSpeed) v *= kMaxLinearSpeed / std::sqrt(speedSquared);
    state.linearVelocity = v;
    state.angularVelocity = std::clamp(w, -maxAngularSpeed, maxAngularSpeed);
  }
}

void integratePositions(WorldData& world, Real h) {
  for (std::size_t k = 1; k < world.solverStates.size(); ++k) {
    SolverState& state = world.solverStates[k];
    state.deltaRotation = integrateRotation(state.deltaRotation, h * state.angularVelocity);
    state.deltaPosition += h * state.linearVelocity;
  }
}

// A body being pushed out of an overlap moves without velocity; it must not
// fall asleep halfway out.
void keepAwakeWhilePushed(Body& body, const SolverState& pseudo, const WorldSettings& settings) {
  Real pushSpeed = std::max(pseudo.linearVelocity.norm(), body.extent * std::abs(pseudo.angularVelocity));
  if (pushSpeed > settings.linearSleepTolerance) body.sleepTime = 0;
}

// Split impulse for intrusions: the push pass runs on pseudo velocities that
// move the bodies this sub-step and are then dropped, so pushing overlap out
// never becomes real velocity. The real velocities are parked meanwhile.
void pushThenIntegratePositions(WorldData& world, const WideContactKernels& kernels,
                                const ContactSolverContext& context, WideContactSet& wide, Real h) {
  const std::size_t count = world.solverStates.size();
  world.parkedVelocities.resize(count);
  for (std::size_t k = 1; k < count; ++k) {
    SolverState& state = world.solverStates[k];
    world.parkedVelocities[k] = {state.linearVelocity, state.angularVelocity};
    state.linearVelocity.setZero();
    state.angularVelocity = 0;
  }
  kernels.push(context, wide);
  for (std::size_t k = 1; k < count; ++k) {
    SolverState& state = world.solverStates[k];
    keepAwakeWhilePushed(world.bodies[world.solverIntegration[k].body], state, world.settings);
    const ParkedVelocity& real = world.parkedVelocities[k];
    state.linearVelocity += real.linear;
    state.angularVelocity += real.angular;
  }
  integratePositions(world, h);
  for (std::size_t k = 1; k < count; ++k) {
    SolverState& state = world.solverStates[k];
    state.linearVelocity = world.parkedVelocities[k].linear;
    state.angularVelocity = world.parkedVelocities[k].angular;
  }
}

Rot compose(const Rot& delta, const Rot& q) {
  Rot r{delta.c * q.c - delta.s * q.s, delta.s * q.c + delta.c * q.s};
  Real length = std::sqrt(r.c * r.c + r.s * r.s);
  return {r.c / length, r.s / length};
}

void finalizeBodies(WorldData& world) {
  for (std::size_t k = 1; k < world.solverStates.size(); ++k) {
    const SolverState& state = world.solverStates[k];
    Body& body = world.bodies[world.solverIntegration[k].body];
    body.linearVelocity = state.linearVelocity;
    body.angularVelocity = state.angularVelocity;
    body.transform.p = body.center0 + state.deltaPosition;
    body.transform.q = compose(state.deltaRotation, body.rotation0);
    body.force.setZero();
    body.torque = 0;
  }
}

}  // namespace

void solve(WorldData& world, Real dt) {
  if (world.awakeBodies.empty()) return;
  const int subSteps = std::max(1, world.settings.subSteps);
  const Real h = dt / Real(subSteps);
  loadStates(world, h);
  collectConstraints(world);

  ContactSolverContext context{world.solverStates, {}, 1 / h,
                               world.settings.maxContactPushSpeed,
                               world.settings.restitutionThreshold};
  WideContactSet& wide = world.wideContacts;
  const WideContactKernels& kernels = wideContactKernels(world.settings.simdWidth);
  const bool intrusion = kernels.build(world, contactSoftness(world.settings, h), wide);
  for (int i = 0; i < subSteps; ++i) {
    context.reversePointOrder = i % 2 == 1;
    integrateVelocities(world, h);
    kernels.warmStart(context, wide);
    kernels.solve(context, wide, true);
    if (intrusion) {
      pushThenIntegratePositions(world, kernels, context, wide, h);
    } else {
      integratePositions(world, h);
    }
    for (int r = 0; r < world.settings.relaxIterations; ++r) kernels.solve(context, wide, false);
  }
  // A flat face meeting a wall bounces on two points; one pass solves them
  // one after the other and leaves a spurious spin, a few converge.
  for (int i = 0; i < kRestitutionIterations; ++i) kernels.restitution(context, wide);
  kernels.store(wide, world);
  finalizeBodies(world);
}

}  // namespace impulse
