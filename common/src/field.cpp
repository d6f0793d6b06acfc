// The field stage: each force field sees the awake dynamic bodies and adds
// a force and torque (or an impulse) to each for this step. Without fields
// it does nothing. A body the step's single kick would carry too far off its
// path (impulse/field.h) gets its loads per sub-step instead, from the solver;
// a force that says how fast it changes is carried forward to each sub-step.

#include <algorithm>
#include <cmath>

#include "world_data.h"

namespace impulse {

namespace {

// How far one kick per step may let a body swing, as w dt (impulse/field.h):
// symplectic Euler at dt swings it about w dt / 2 of its distance, measured
// +-3 % in radius for an orbit of 100 steps per period (w dt = 0.063). Below
// 0.01 the swing stays under 0.5 % and the field keeps one call per step, so
// uniform and slow fields cost what they did.
constexpr Real kMaxSwingPerStep = Real(0.01);

bool needsSubSteps(const FieldLoad& load, Real dt) {
  return load.gradient * dt * dt > kMaxSwingPerStep * kMaxSwingPerStep;
}

/// Where a body is and how it moves, as a field is to see it.
struct Motion {
  Transform transform;
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
};

Motion motionAtStepStart(const Body& body) { return {body.transform, body.linearVelocity, body.angularVelocity}; }

// Within the solve: the step's start moved by the sub-steps so far.
Motion motionInSubStep(const WorldData& world, const Body& body) {
  const SolverState& state = world.solverStates[body.solverIndex];
  const Vec2 turned = state.deltaRotation.apply(Vec2(body.rotation0.c, body.rotation0.s));
  return {{body.center0 + state.deltaPosition, {turned.x(), turned.y()}}, state.linearVelocity,
          state.angularVelocity};
}

FieldBody fieldBodyOf(const WorldData& world, std::int32_t slot, const Motion& motion, Real mass,
                      FieldShapes& shapes) {
  const Body& body = world.bodies[slot];
  const std::size_t first = shapes.addresses.size();
  world.forEachShape(slot, [&](std::int32_t s) {
    shapes.copies.push_back(shapeOf(world.shapes[s].ref()));
    shapes.addresses.push_back(&shapes.copies.back());
  });
  return {world.idOf(slot), motion.transform, motion.linearVelocity, motion.angularVelocity, mass,
          body.mass.inertia, std::span(shapes.addresses).subspan(first), body.mass.area, body.extent};
}

void gatherMovingBodies(WorldData& world) {
  world.fieldBodies.clear();
  world.fieldBodyShapes.reset(world.liveShapes);
  for (std::int32_t slot : world.awakeBodies) {
    const Body& body = world.bodies[slot];
    world.fieldBodies.push_back(fieldBodyOf(world, slot, motionAtStepStart(body), body.mass.mass, world.fieldBodyShapes));
  }
  world.fieldLoads.assign(world.fieldBodies.size(), FieldLoad{});
}

// What a static body weighs here: its area times density, shape by shape.
Real staticMass(const WorldData& world, std::int32_t slot) {
  Real mass = 0;
  world.forEachShape(slot, [&](std::int32_t s) {
    const ShapeSlot& shape = world.shapes[s];
    mass += computeMassProperties(shape.ref(), shape.coefficients.density).mass;
  });
  return mass;
}

// Static bodies weigh their area times density here: they pull without moving.
void gatherStillBodies(WorldData& world) {
  world.fieldStillBodies.clear();
  world.fieldStillShapes.reset(world.liveShapes);
  for (std::int32_t slot = 0; slot < static_cast<std::int32_t>(world.bodies.size()); ++slot) {
    const Body& body = world.bodies[slot];
    if (!body.alive || (body.awake && !body.isStatic)) continue;
    Real mass = body.isStatic ? staticMass(world, slot) : body.mass.mass;
    world.fieldStillBodies.push_back(fieldBodyOf(world, slot, motionAtStepStart(body), mass, world.fieldStillShapes));
  }
}

bool anyFieldNeedsStillBodies(const WorldData& world) {
  return std::ranges::any_of(world.fields, [](const FieldSlot& slot) { return slot.field->needsStillBodies(); });
}

// A field is user code: a non-finite load is dropped rather than let in.
bool isFiniteLoad(const FieldLoad& load) {
  return isFinite(load.force) && std::isfinite(load.torque) && isFinite(load.impulse) &&
         std::isfinite(load.angularImpulse);
}

void addLoad(Body& body, const FieldLoad& load) {
  body.fieldForceChange.setZero();
  if (!isFiniteLoad(load) || !isFinite(load.forceChange)) return;
  body.force += load.force;
  body.fieldForceChange = load.forceChange;
  body.torque += load.torque;
  body.linearVelocity += body.invMass * load.impulse;
  body.angularVelocity += body.invInertia * load.angularImpulse;
}

// A load taken for one sub-step of length h acts within it at once.
void addSubStepLoad(const Body& body, const FieldLoad& load, Real h, SolverState& state) {
  if (!isFiniteLoad(load)) return;
  state.linearVelocity += body.invMass * (load.impulse + h * load.force);
  state.angularVelocity += body.invInertia * (load.angularImpulse + h * load.torque);
}

// The awake bodies not taken per sub-step, where the sub-step has them, then
// the still ones: the sources a field such as gravitation pulls from.
void gatherSubStepSources(WorldData& world) {
  world.fieldSources.clear();
  world.fieldSourceShapes.reset(world.liveShapes);
  for (std::int32_t slot : world.awakeBodies) {
    const Body& body = world.bodies[slot];
    if (body.fieldsPerSubStep) continue;
    world.fieldSources.push_back(
        fieldBodyOf(world, slot, motionInSubStep(world, body), body.mass.mass, world.fieldSourceShapes));
  }
  world.fieldSources.insert(world.fieldSources.end(), world.fieldStillBodies.begin(), world.fieldStillBodies.end());
}

void takePerSubStep(WorldData& world, std::int32_t slot) {
  world.bodies[slot].fieldsPerSubStep = true;
  world.bodies[slot].fieldForceChange.setZero();
  world.subSteppedFieldBodies.push_back(slot);
}

// Sub-step k starts k h into the step: what the step's force has become by
// then, beyond the force itself, kicks the body over the sub-step.
void addForceChanges(WorldData& world, int subStep, Real h) {
  if (subStep == 0) return;
  const Real kick = Real(subStep) * h * h;
  for (std::int32_t slot : world.awakeBodies) {
    const Body& body = world.bodies[slot];
    if (body.isDynamic()) {
      world.solverStates[body.solverIndex].linearVelocity += kick * body.invMass * body.fieldForceChange;
    }
  }
}

void loadSubSteppedBodies(WorldData& world, Real h) {
  world.fieldBodies.clear();
  world.fieldBodyShapes.reset(world.liveShapes);
  for (std::int32_t slot : world.subSteppedFieldBodies) {
    const Body& body = world.bodies[slot];
    world.fieldBodies.push_back(
        fieldBodyOf(world, slot, motionInSubStep(world, body), body.mass.mass, world.fieldBodyShapes));
  }
  world.fieldSources.clear();
  if (anyFieldNeedsStillBodies(world)) gatherSubStepSources(world);
  world.fieldLoads.assign(world.fieldBodies.size(), FieldLoad{});
  const FieldStep step{world.fieldBodies, world.fieldSources, world.settings.gravity, h};
  for (const FieldSlot& slot : world.fields) slot.field->apply(step, world.fieldLoads);
  for (std::size_t k = 0; k < world.fieldLoads.size(); ++k) {
    const Body& body = world.bodies[world.subSteppedFieldBodies[k]];
    addSubStepLoad(body, world.fieldLoads[k], h, world.solverStates[body.solverIndex]);
  }
}

}  // namespace

void applyFields(WorldData& world, Real dt) {
  for (std::int32_t slot : world.subSteppedFieldBodies) world.bodies[slot].fieldsPerSubStep = false;
  world.subSteppedFieldBodies.clear();
  if (world.fields.empty() || world.awakeBodies.empty()) return;
  world.fieldStillBodies.clear();
  if (anyFieldNeedsStillBodies(world)) gatherStillBodies(world);
  gatherMovingBodies(world);
  const FieldStep step{world.fieldBodies, world.fieldStillBodies, world.settings.gravity, dt};
  for (const FieldSlot& slot : world.fields) slot.field->apply(step, world.fieldLoads);
  for (std::size_t k = 0; k < world.fieldLoads.size(); ++k) {
    const std::int32_t slot = world.awakeBodies[k];
    if (needsSubSteps(world.fieldLoads[k], dt)) {
      takePerSubStep(world, slot);
    } else {
      addLoad(world.bodies[slot], world.fieldLoads[k]);
    }
  }
}

void applySubStepFields(WorldData& world, int subStep, Real h) {
  if (world.fields.empty()) return;
  addForceChanges(world, subStep, h);
  if (!world.subSteppedFieldBodies.empty()) loadSubSteppedBodies(world, h);
}

}  // namespace impulse
