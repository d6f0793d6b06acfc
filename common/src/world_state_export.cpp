// World::exportState: the world's private data copied out as plain data
// (impulse/world_state.h), slot by slot, lists in their order.

#include "world_data.h"

namespace impulse {

namespace {

SolverSettingsState solverSettingsOf(const WorldSettings& s) {
  return {s.gravity,
          s.subSteps,
          s.relaxIterations,
          s.contactHertz,
          s.contactDampingRatio,
          s.maxContactPushSpeed,
          s.restitutionThreshold,
          s.stickSpeed,
          s.enableWarmStarting,
          s.enableSleep,
          s.linearSleepTolerance,
          s.timeToSleep,
          s.enableContinuous,
          s.hitEventThreshold};
}

template <class Elements>
std::vector<std::int32_t> edgeKeys(const Elements& elements, std::int32_t head) {
  std::vector<std::int32_t> keys;
  forEachEdge(elements, head, [&](std::int32_t key, const auto&) { keys.push_back(key); });
  return keys;
}

BodySlotState exportBody(const WorldData& world, std::int32_t slot) {
  const Body& body = world.bodies[std::size_t(slot)];
  BodySlotState out;
  out.alive = body.alive;
  out.generation = body.generation;
  if (!body.alive) return out;
  world.forEachShape(slot, [&](std::int32_t s) { out.shapes.push_back(s); });
  out.transform = body.transform;
  out.linearVelocity = body.linearVelocity;
  out.angularVelocity = body.angularVelocity;
  out.force = body.force;
  out.torque = body.torque;
  out.properties = body.properties();
  out.sleepTime = body.sleepTime;
  out.center0 = body.center0;
  out.rotation0 = body.rotation0;
  out.creationOrder = body.creationOrder;
  out.awake = body.awake;
  out.contactEdges = edgeKeys(world.contacts, body.contactHead);
  out.jointEdges = edgeKeys(world.joints, body.jointHead);
  return out;
}

ShapeSlotState exportShape(const ShapeSlot& shape) {
  ShapeSlotState out;
  out.alive = shape.alive;
  out.generation = shape.generation;
  if (!shape.alive) return out;
  out.body = shape.body;
  out.shape = shapeOf(shape.ref());
  out.material = shape.material;
  out.density = shape.coefficients.density;
  out.restitution = shape.coefficients.restitution;
  out.staticFriction = shape.coefficients.staticFriction;
  out.dynamicFriction = shape.coefficients.dynamicFriction;
  out.rollingResistance = shape.coefficients.rollingResistance;
  out.interaction = shape.interaction;
  out.proxyKey = shape.proxyKey;
  return out;
}

// Contact slots carry no alive flag: a slot is free when it is on the free list.
std::vector<bool> liveContactSlots(const WorldData& world) {
  std::vector<bool> live(world.contacts.size(), true);
  for (std::int32_t slot : world.freeContacts.slots()) live[std::size_t(slot)] = false;
  return live;
}

ContactSlotState exportContact(const Contact& contact) {
  ContactSlotState out;
  out.alive = true;
  out.shapeA = contact.shapeA;
  out.shapeB = contact.shapeB;
  out.bodyA = contact.edges.bodyA;
  out.bodyB = contact.edges.bodyB;
  out.manifold = contact.manifold;
  out.frame = contact.frame;
  out.staticFriction = contact.staticFriction;
  out.dynamicFriction = contact.dynamicFriction;
  out.restitution = contact.restitution;
  out.rollingResistance = contact.rollingResistance;
  out.touching = contact.touching;
  return out;
}

JointSlotState exportJoint(const Joint& joint) {
  JointSlotState out;
  out.alive = joint.alive;
  out.generation = joint.generation;
  if (!joint.alive) return out;
  out.bodyA = joint.edges.bodyA;
  out.bodyB = joint.edges.bodyB;
  out.settings = joint.settings;
  out.localAnchorA = joint.localAnchorA;
  out.localAnchorB = joint.localAnchorB;
  out.localAxisA = joint.localAxisA;
  out.referenceAngle = joint.referenceAngle;
  out.referenceTranslation = joint.referenceTranslation;
  out.referencePerpendicular = joint.referencePerpendicular;
  out.length = joint.length;
  out.target = joint.target;
  out.impulses = joint.impulses;
  out.reactionForce = joint.reactionForce;
  out.reactionTorque = joint.reactionTorque;
  out.collideConnected = joint.collideConnected;
  return out;
}

}  // namespace

WorldState World::exportState() const {
  const WorldData& w = *impl_;
  WorldState state;
  state.settings = solverSettingsOf(w.settings);
  state.origin = w.origin;
  for (std::size_t slot = 0; slot < w.bodies.size(); ++slot) {
    state.bodies.push_back(exportBody(w, std::int32_t(slot)));
  }
  state.freeBodies = w.freeBodies.slots();
  state.nextCreationOrder = w.nextCreationOrder;
  for (const ShapeSlot& shape : w.shapes) state.shapes.push_back(exportShape(shape));
  state.freeShapes = w.freeShapes.slots();
  const std::vector<bool> liveContacts = liveContactSlots(w);
  for (std::size_t slot = 0; slot < w.contacts.size(); ++slot) {
    state.contacts.push_back(liveContacts[slot] ? exportContact(w.contacts[slot])
                                                : ContactSlotState{});
  }
  state.freeContacts = w.freeContacts.slots();
  for (const Joint& joint : w.joints) state.joints.push_back(exportJoint(joint));
  state.freeJoints = w.freeJoints.slots();
  for (const FieldSlot& slot : w.fields) {
    if (auto def = describeField(*slot.field)) state.fields.push_back({slot.id, std::move(*def)});
  }
  state.nextFieldId = w.nextFieldId;
  state.broadPhase = w.broadPhase.state();
  state.awakeBodies = w.awakeBodies;
  state.stepCount = w.stepCount;
  state.time = w.time;
  return state;
}

}  // namespace impulse
