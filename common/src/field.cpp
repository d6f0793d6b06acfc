// The field stage: each force field sees the awake dynamic bodies and adds
// a force and torque (or an impulse) to each for this step. Without fields
// it does nothing.

#include <algorithm>

#include "world_data.h"

namespace impulse {

namespace {

// `shapes` was reserved for every live shape, so the spans handed out stay
// valid while it fills.
FieldBody fieldBodyOf(const WorldData& world, std::int32_t slot, Real mass, std::vector<const Shape*>& shapes) {
  const Body& body = world.bodies[slot];
  const std::size_t first = shapes.size();
  world.forEachShape(slot, [&](std::int32_t s) { shapes.push_back(&world.shapes[s].shape); });
  return {world.idOf(slot), body.transform, body.linearVelocity, body.angularVelocity, mass,
          body.mass.inertia, std::span(shapes).subspan(first), body.mass.area, body.extent};
}

void gatherMovingBodies(WorldData& world) {
  world.fieldBodies.clear();
  world.fieldBodyShapes.clear();
  world.fieldBodyShapes.reserve(std::size_t(world.liveShapes));
  for (std::int32_t slot : world.awakeBodies) {
    world.fieldBodies.push_back(fieldBodyOf(world, slot, world.bodies[slot].mass.mass, world.fieldBodyShapes));
  }
  world.fieldLoads.assign(world.fieldBodies.size(), FieldLoad{});
}

// What a static body weighs here: its area times density, shape by shape.
Real staticMass(const WorldData& world, std::int32_t slot) {
  Real mass = 0;
  world.forEachShape(slot, [&](std::int32_t s) {
    const ShapeSlot& shape = world.shapes[s];
    mass += computeMassProperties(shape.shape, shape.coefficients.density).mass;
  });
  return mass;
}

// Static bodies weigh their area times density here: they pull without moving.
void gatherStillBodies(WorldData& world) {
  world.fieldStillBodies.clear();
  world.fieldStillShapes.clear();
  world.fieldStillShapes.reserve(std::size_t(world.liveShapes));
  for (std::int32_t slot = 0; slot < static_cast<std::int32_t>(world.bodies.size()); ++slot) {
    const Body& body = world.bodies[slot];
    if (!body.alive || (body.awake && !body.isStatic)) continue;
    Real mass = body.isStatic ? staticMass(world, slot) : body.mass.mass;
    world.fieldStillBodies.push_back(fieldBodyOf(world, slot, mass, world.fieldStillShapes));
  }
}

bool anyFieldNeedsStillBodies(const WorldData& world) {
  return std::ranges::any_of(world.fields, [](const FieldSlot& slot) { return slot.field->needsStillBodies(); });
}

void addLoad(Body& body, const FieldLoad& load) {
  // A field is user code: a non-finite load is dropped rather than let in.
  if (!isFinite(load.force) || !isFinite(load.torque) || !isFinite(load.impulse) || !isFinite(load.angularImpulse)) {
    return;
  }
  body.force += load.force;
  body.torque += load.torque;
  body.linearVelocity += body.invMass * load.impulse;
  body.angularVelocity += body.invInertia * load.angularImpulse;
}

}  // namespace

void applyFields(WorldData& world, Real dt) {
  if (world.fields.empty() || world.awakeBodies.empty()) return;
  gatherMovingBodies(world);
  world.fieldStillBodies.clear();
  if (anyFieldNeedsStillBodies(world)) gatherStillBodies(world);
  const FieldStep step{world.fieldBodies, world.fieldStillBodies, world.settings.gravity, dt};
  for (const FieldSlot& slot : world.fields) slot.field->apply(step, world.fieldLoads);
  for (std::size_t k = 0; k < world.fieldLoads.size(); ++k) {
    addLoad(world.bodies[world.awakeBodies[k]], world.fieldLoads[k]);
  }
}

}  // namespace impulse
