// The solve stage: soft-step sub-stepping over all awake bodies and the
// constraints between them, every kind in turn (constraint_kind.h), then
// writing the motion back into the bodies.
//
//   prepare constraints (once per step, coloured together)
//   for each sub-step:
//     field loads of the bodies that take them per sub-step (field.cpp)
//     integrate velocities (gravity, forces, drag)
//     warm start (apply last impulses)
//     solve with soft position correction (contacts: no faster than loads need)
//     solve exactly what a kind can (joint trees)
//     push position error out through pseudo velocities (split impulse), if any
//     integrate positions
//     relax (no correction: removes the velocity the correction added)
//   restitution, store impulses, finalize bodies

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "constraint_kind.h"
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

// Awake bodies per range of a parallel body phase: a body costs a few
// nanoseconds (its state's load and write-back tens), a hand-off to a
// thread about 0.4 us, so a phase of 512 bodies or more is split. Split
// only from 2 048, crowds of 600 to 2 000 bodies integrated on one thread
// while the other waited: at two threads, rain-2000 takes 0.92 of that
// time, scaling-2000 0.94, pyramid-60 and confined 0.95.
constexpr std::int32_t kBodiesPerRange = 256;

// visit(range, first) for ranges of the awake bodies' solver states side by
// side; `first` is the range's first state (states start at 1: 0 is the
// static dummy).
template <class Visit>
void forEachStateRange(WorldData& world, Visit&& visit) {
  const std::size_t count = world.solverStates.size();
  world.tasks.forRanges(std::int32_t(count) - 1, kBodiesPerRange, [&](std::int32_t begin, std::int32_t end) {
    visit(std::span<SolverState>(world.solverStates.data() + begin + 1, std::size_t(end - begin)), std::size_t(begin + 1));
  });
}

// visit(k) for every awake body's solver state k >= 1, side by side: each
// visit writes only body k's state and the body itself.
template <class Visit>
void forEachState(WorldData& world, Visit&& visit) {
  forEachStateRange(world, [&](std::span<SolverState> range, std::size_t first) {
    for (std::size_t i = 0; i < range.size(); ++i) visit(first + i);
  });
}

void loadState(WorldData& world, std::size_t k, Real h) {
  std::int32_t slot = world.awakeBodies[k - 1];
  Body& body = world.bodies[slot];
  body.solverIndex = static_cast<std::int32_t>(k);
  body.center0 = body.transform.p;
  body.rotation0 = body.transform.q;
  SolverState& state = world.solverStates[k];
  state = SolverState{};
  state.linearVelocity = body.linearVelocity;
  state.angularVelocity = body.angularVelocity;
  SolverIntegration& in = world.solverIntegration[k];
  in.body = slot;
  in.extent = body.extent;
  in.linearAcceleration = body.invMass * body.force;
  if (body.isDynamic() && !body.ignoreGravity) in.linearAcceleration += body.gravityScale * world.settings.gravity;
  in.angularAcceleration = body.invInertia * body.torque;
  // Exact exponential decay over h: the same drag whatever the tick rate.
  const bool drags = body.isDynamic();
  in.linearDamping = drags && body.linearDrag > 0 ? std::exp(-body.linearDrag * h) : Real(1);
  in.angularDamping = drags && body.angularDrag > 0 ? std::exp(-body.angularDrag * h) : Real(1);
}

void loadStates(WorldData& world, Real h) {
  const auto count = world.awakeBodies.size() + 1;
  // Each state is cleared where it is loaded, side by side; only the
  // static dummy's here.
  world.solverStates.resize(count);
  world.solverStates[0] = SolverState{};
  world.solverIntegration.resize(count);
  forEachState(world, [&](std::size_t k) { loadState(world, k, h); });
}

// Every kind of constraint the solver runs, in the order each stage visits
// them. A new kind adds itself here.
// Joints come first: they take their colours before the contacts do.
std::array<ConstraintKind*, 2> constraintKinds(WorldData& world) {
  return {&world.jointConstraints, &world.contactConstraints};
}

// The prepared kinds that have constraints this step, in their order (kept
// at the front of `kinds`): a lone falling body runs no contact pass.
std::span<ConstraintKind* const> kindsWithConstraints(std::array<ConstraintKind*, 2>& kinds) {
  const auto none = [](const ConstraintKind* kind) { return kind->empty(); };
  return {kinds.begin(), std::remove_if(kinds.begin(), kinds.end(), none)};
}

void integrateVelocities(WorldData& world, Real h) {
  const Real maxAngularSpeed = kMaxRotationPerSubStep / h;
  forEachState(world, [&](std::size_t k) {
    SolverState& state = world.solverStates[k];
    const SolverIntegration& in = world.solverIntegration[k];
    Vec2 v = in.linearDamping * (state.linearVelocity + h * in.linearAcceleration);
    Real w = in.angularDamping * (state.angularVelocity + h * in.angularAcceleration);
    Real speedSquared = v.squaredNorm();
    if (speedSquared > kMaxLinearSpeed * kMaxLinearSpeed) v *= kMaxLinearSpeed / std::sqrt(speedSquared);
    state.linearVelocity = v;
    state.angularVelocity = std::clamp(w, -maxAngularSpeed, maxAngularSpeed);
  });
}

void integratePosition(SolverState& state, Real h) {
  state.deltaRotation = integrateRotation(state.deltaRotation, h * state.angularVelocity);
  state.deltaPosition += h * state.linearVelocity;
}

// Whole bundles of states side by side (WideContactKernels::integratePositions),
// the few left over one at a time.
void integrateRange(const WideContactKernels& kernels, std::span<SolverState> range, Real h) {
  for (std::size_t k = kernels.integratePositions(range, h); k < range.size(); ++k) integratePosition(range[k], h);
}

void integratePositions(WorldData& world, Real h) {
  const WideContactKernels& kernels = wideContactKernels(world.settings.simdWidth);
  forEachStateRange(world, [&](std::span<SolverState> range, std::size_t) { integrateRange(kernels, range, h); });
}

// A body being pushed out of an overlap moves without velocity; it must not
// fall asleep halfway out. Only a pushed body is read (most are not).
void keepAwakeWhilePushed(WorldData& world, const SolverIntegration& in, const SolverState& pseudo) {
  Real pushSpeed = std::max(pseudo.linearVelocity.norm(), in.extent * std::abs(pseudo.angularVelocity));
  if (pushSpeed > world.settings.linearSleepTolerance) world.bodies[in.body].sleepTime = 0;
}

// Split impulse for intrusions: the push pass runs on pseudo velocities that
// move the bodies this sub-step and are then dropped, so pushing overlap out
// never becomes real velocity. The real velocities are parked meanwhile.
// Each range of bodies ends in one hand-off (a pass over the bodies costs
// one between threads): moved by both velocities, whole bundles of them at
// once as integratePositions moves them, then given back the real one.
void pushThenIntegratePositions(WorldData& world, std::span<ConstraintKind* const> kinds,
                                const SubStep& sub, Real h) {
  const std::size_t count = world.solverStates.size();
  world.parkedVelocities.resize(count);
  forEachState(world, [&](std::size_t k) {
    SolverState& state = world.solverStates[k];
    world.parkedVelocities[k] = {state.linearVelocity, state.angularVelocity};
    state.linearVelocity.setZero();
    state.angularVelocity = 0;
  });
  for (ConstraintKind* kind : kinds) kind->push(sub);
  for (ConstraintKind* kind : kinds) kind->pushExact(sub);
  const WideContactKernels& kernels = wideContactKernels(world.settings.simdWidth);
  forEachStateRange(world, [&](std::span<SolverState> range, std::size_t first) {
    for (std::size_t i = 0; i < range.size(); ++i) {
      SolverState& state = range[i];
      keepAwakeWhilePushed(world, world.solverIntegration[first + i], state);
      const ParkedVelocity& real = world.parkedVelocities[first + i];
      state.linearVelocity += real.linear;
      state.angularVelocity += real.angular;
    }
    integrateRange(kernels, range, h);
    for (std::size_t i = 0; i < range.size(); ++i) {
      const ParkedVelocity& real = world.parkedVelocities[first + i];
      range[i].linearVelocity = real.linear;
      range[i].angularVelocity = real.angular;
    }
  });
}

Rot compose(const Rot& delta, const Rot& q) {
  Rot r{delta.c * q.c - delta.s * q.s, delta.s * q.c + delta.c * q.s};
  Real length = std::sqrt(r.c * r.c + r.s * r.s);
  return {r.c / length, r.s / length};
}

void finalizeBodies(WorldData& world) {
  forEachState(world, [&](std::size_t k) {
    const SolverState& state = world.solverStates[k];
    Body& body = world.bodies[world.solverIntegration[k].body];
    body.linearVelocity = state.linearVelocity;
    body.angularVelocity = state.angularVelocity;
    body.transform.p = body.center0 + state.deltaPosition;
    body.transform.q = compose(state.deltaRotation, body.rotation0);
    body.force.setZero();
    body.torque = 0;
  });
}

}  // namespace

Softness makeSoftness(Real hertz, Real dampingRatio, Real h) {
  if (hertz == 0) return {0, 1, 0};
  Real omega = 2 * std::numbers::pi_v<Real> * hertz;
  Real a1 = 2 * dampingRatio + h * omega;
  Real a2 = h * omega * a1;
  Real a3 = 1 / (1 + a2);
  return {omega / a1, a2 * a3, a3};
}

void solve(WorldData& world, Real dt) {
  world.profile.passes = {};
  if (world.awakeBodies.empty()) return;
  const int subSteps = std::max(1, world.settings.subSteps);
  const SolveStep step{dt / Real(subSteps), subSteps};
  const Real h = step.h;
  loadStates(world, h);

  auto allKinds = constraintKinds(world);
  world.contactConstraints.collect(world);
  world.coloring.reset(world.solverStates.size());
  bool needsPush = false;
  for (ConstraintKind* kind : allKinds) needsPush = kind->prepare(world, step, world.coloring) || needsPush;
  const std::span<ConstraintKind* const> kinds = kindsWithConstraints(allKinds);
  for (const ConstraintKind* kind : kinds) kind->countPasses(world.profile.passes);
  for (int i = 0; i < step.subSteps; ++i) {
    const SubStep sub{world.solverStates, i, &world.tasks};
    applySubStepFields(world, i, h);
    integrateVelocities(world, h);
    for (ConstraintKind* kind : kinds) kind->warmStart(sub);
    for (ConstraintKind* kind : kinds) kind->solve(sub);
    for (ConstraintKind* kind : kinds) kind->solveExact(sub);
    if (needsPush) {
      pushThenIntegratePositions(world, kinds, sub, h);
    } else {
      integratePositions(world, h);
    }
    for (int r = 0; r < world.settings.relaxIterations; ++r) {
      for (ConstraintKind* kind : kinds) kind->relax(sub);
    }
    for (ConstraintKind* kind : kinds) kind->relaxExact(sub);
  }
  // A flat face meeting a wall bounces on two points; one pass solves them
  // one after the other and leaves a spurious spin, a few converge.
  const SubStep last{world.solverStates, step.subSteps - 1, &world.tasks};
  for (int i = 0; i < kRestitutionIterations; ++i) {
    for (ConstraintKind* kind : kinds) kind->restitution(last);
  }
  for (ConstraintKind* kind : kinds) kind->store(world);
  finalizeBodies(world);
}

}  // namespace impulse
