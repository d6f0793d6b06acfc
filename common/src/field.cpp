// The field stage: each force field sees the awake dynamic bodies and adds
// a force and torque to each for this step. Without fields it does nothing.

#include "world_data.h"

namespace impulse {

namespace {

void gatherFieldBodies(WorldData& world) {
  world.fieldBodies.clear();
  for (std::int32_t slot : world.awakeBodies) {
    const Body& body = world.bodies[slot];
    world.fieldBodies.push_back({world.idOf(slot), body.transform, body.linearVelocity, body.angularVelocity,
                                 body.mass.mass, body.mass.inertia, &world.shapes[slot], body.material});
  }
  world.fieldLoads.assign(world.fieldBodies.size(), FieldLoad{});
}

}  // namespace

void applyFields(WorldData& world, Real /*dt*/) {
  if (world.fields.empty() || world.awakeBodies.empty()) return;
  gatherFieldBodies(world);
  for (const FieldSlot& slot : world.fields) slot.field->apply(world.fieldBodies, world.fieldLoads);
  for (std::size_t k = 0; k < world.fieldLoads.size(); ++k) {
    const FieldLoad& load = world.fieldLoads[k];
    // A field is user code: a non-finite load is dropped rather than let in.
    if (!isFinite(load.force) || !isFinite(load.torque)) continue;
    Body& body = world.bodies[world.awakeBodies[k]];
    body.force += load.force;
    body.torque += load.torque;
  }
}

}  // namespace impulse
