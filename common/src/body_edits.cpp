// Editing a live body (World::setTransform, setMaterial, setBodyType): each
// checks everything before it changes anything, then keeps the contacts,
// the broad phase and the islands consistent with the edited body.

#include <algorithm>
#include <string>
#include <variant>

#include "body_shapes.h"
#include "input_limits.h"
#include "world_data.h"

namespace impulse {

namespace {

std::string unknownBody(BodyId id) { return "unknown body id " + std::to_string(id.value); }

bool isBodyType(BodyType type) {
  return type == BodyType::Static || type == BodyType::Kinematic || type == BodyType::Dynamic;
}

// Wakes the bodies touching this one where it is now: a body that leaves,
// turns static or changes its surface must not leave a sleeping pile
// resting on nothing or on stale contacts.
void wakeTouchingBodies(WorldData& world, std::int32_t body) {
  forEachEdge(world.contacts, world.bodies[body].contactHead, [&](std::int32_t key, const Contact& contact) {
    if (contact.touching) wakeIsland(world, contact.edges.otherBody(key));
  });
}

void wakeJointedBodies(WorldData& world, std::int32_t body) {
  forEachEdge(world.joints, world.bodies[body].jointHead, [&](std::int32_t key, const Joint& joint) {
    if (joint.edges.otherBody(key) != kNullIndex) wakeIsland(world, joint.edges.otherBody(key));
  });
}

void wakeBodiesUnderShapes(WorldData& world, std::int32_t body) {
  world.forEachShape(body, [&](std::int32_t s) { wakeBodiesUnder(world, shapeAABB(world, s)); });
}

// Drops the body's contacts (waking what they held) and has its proxies
// look for pairs again: the next step's broad phase makes the contacts its
// new type or surface calls for.
void rebuildContacts(WorldData& world, std::int32_t body) {
  destroyBodyContacts(world, body);
  touchBodyProxies(world, body);
}

// Every joint keeps a dynamic body at one end, and a mouse joint pulls a
// dynamic body (World::createJoint's rules), whatever this body becomes.
std::string checkJointsAllowType(const WorldData& world, std::int32_t body, BodyType type) {
  if (type == BodyType::Dynamic) return {};
  std::string error;
  forEachEdge(world.joints, world.bodies[body].jointHead, [&](std::int32_t key, const Joint& joint) {
    if (!error.empty()) return;
    const std::string jointName = "joint " + std::to_string(JointId::make(edgeElement(key), joint.generation).value);
    const std::int32_t other = joint.edges.otherBody(key);
    if (std::holds_alternative<MouseJointSettings>(joint.settings) && edgeSide(key) == 0) {
      error = jointName + " (a mouse joint) pulls this body, which must stay dynamic: remove the joint first";
    } else if (other == kNullIndex || !world.bodies[other].isDynamic()) {
      error = jointName + " joins this body to " +
              std::string(other == kNullIndex ? "the world" : "a body that is not dynamic") +
              ": a joint needs a dynamic body at one end; remove the joint first";
    }
  });
  return error;
}

// The broad phase keeps static and moving proxies in separate trees: a
// body that turns static, or stops being static, changes tree.
void moveProxiesToTypeTree(WorldData& world, std::int32_t body) {
  world.forEachShape(body, [&](std::int32_t s) {
    world.broadPhase.destroyProxy(world.shapes[s].proxyKey);
    createShapeProxy(world, s);
  });
}

// A static body has no velocity, no pending force and never wakes.
void stopAndSleep(WorldData& world, std::int32_t slot) {
  Body& body = world.bodies[slot];
  body.linearVelocity.setZero();
  body.angularVelocity = 0;
  body.sleepTime = 0;
  if (body.awake) {
    body.awake = false;
    std::erase(world.awakeBodies, slot);
  }
}

}  // namespace

InputResult World::setTransform(BodyId id, const Vec2& position, Real angle) {
  WorldData& w = *impl_;
  if (!isFinite(position) || !isFinite(angle)) return {"position and angle must be finite numbers"};
  Body* body = w.find(id);
  if (body == nullptr) return {unknownBody(id)};
  if (std::string error = checkInsideBounds(w, position); !error.empty()) return {error};
  const std::int32_t slot = id.slot();
  wakeTouchingBodies(w, slot);
  body->transform = {position, Rot::fromAngle(angle)};
  // A teleport sweeps nothing: continuous collision starts from here.
  body->center0 = body->transform.p;
  body->rotation0 = body->transform.q;
  forgetManifoldFrames(w, slot);
  moveBodyProxies(w, slot);
  touchBodyProxies(w, slot);
  if (body->isStatic) {
    wakeBodiesUnderShapes(w, slot);
  } else {
    wakeIsland(w, slot);
  }
  w.changes.mark(BodyChange::Moved, id);
  return {};
}

InputResult World::setMaterial(BodyId id, Material material) {
  WorldData& w = *impl_;
  if (static_cast<int>(material) >= kMaterialCount) {
    return {"unknown material " + std::to_string(static_cast<int>(material))};
  }
  if (w.find(id) == nullptr) return {unknownBody(id)};
  const std::int32_t slot = id.slot();
  w.forEachShape(slot, [&](std::int32_t s) {
    w.shapes[s].material = material;
    w.shapes[s].coefficients = materialProperties(material);
  });
  // Contacts mix their coefficients when they are made.
  rebuildContacts(w, slot);
  // One density over every shape keeps the shapes where they are and gives
  // a mass with area wherever there was one: nothing for the check to refuse.
  reshapeBody(w, slot);
  w.changes.mark(BodyChange::Redescribed, id);
  return {};
}

InputResult World::setBodyType(BodyId id, BodyType type) {
  WorldData& w = *impl_;
  Body* body = w.find(id);
  if (body == nullptr) return {unknownBody(id)};
  if (!isBodyType(type)) return {"unknown body type " + std::to_string(static_cast<int>(type))};
  if (body->type() == type) return {};
  const std::int32_t slot = id.slot();
  const std::string name = "body " + std::to_string(id.value) + ": ";
  if (std::string error = checkShapesSuitType(w, slot, type); !error.empty()) return {name + error};
  if (std::string error = checkJointsAllowType(w, slot, type); !error.empty()) return {name + error};

  const bool treeChanges = body->isStatic || type == BodyType::Static;
  rebuildContacts(w, slot);
  wakeJointedBodies(w, slot);
  body->setType(type);
  if (!body->isDynamic()) {
    body->force.setZero();
    body->torque = 0;
  }
  // The shapes are already centred on the union's centroid whatever the
  // type, so only the mass and its inverse change.
  setMassFromShapes(w, slot);
  if (treeChanges) moveProxiesToTypeTree(w, slot);
  touchBodyProxies(w, slot);
  if (type == BodyType::Static) {
    stopAndSleep(w, slot);
    wakeBodiesUnderShapes(w, slot);
  } else {
    body->center0 = body->transform.p;
    body->rotation0 = body->transform.q;
    wakeIsland(w, slot);
  }
  w.changes.mark(BodyChange::Redescribed, id);
  return {};
}

}  // namespace impulse
