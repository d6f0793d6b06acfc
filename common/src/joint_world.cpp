// World's joint API: validation, creation and removal (edge lists, islands,
// the contacts a joint suppresses), and what a joint reports.

#include <cmath>
#include <numbers>
#include <string>

#include "input_limits.h"
#include "world_data.h"

namespace impulse {

namespace {

// Ranges that keep every quantity a joint forms far inside float's range
// (docs/engine.md, "Input limits").
constexpr Real kMaxLength = 1e4;       // m
constexpr Real kMaxStiffness = 1e9;    // N/m or N*m/rad
constexpr Real kMaxDamping = 1e9;      // N*s/m or N*m*s/rad
constexpr Real kMaxMotorSpeed = 1e3;   // rad/s or m/s
constexpr Real kMaxMotorForce = 1e10;  // N or N*m
constexpr Real kPi = std::numbers::pi_v<Real>;

/// The first of several checks that failed, or empty.
template <class... Errors>
std::string firstError(const Errors&... errors) {
  std::string result;
  ((result.empty() ? void(result = errors) : void()), ...);
  return result;
}

std::string checkSpring(const char* stiffness, Real k, const char* damping, Real c) {
  return firstError(checkRange(stiffness, k, 0, kMaxStiffness),
                    checkRange(damping, c, 0, kMaxDamping));
}

std::string checkMotor(const char* speed, Real v, const char* force, Real f) {
  return firstError(checkRange(speed, v, -kMaxMotorSpeed, kMaxMotorSpeed),
                    checkRange(force, f, 0, kMaxMotorForce));
}

std::string checkLimits(const char* lower, Real lo, const char* upper, Real hi, Real bound) {
  std::string error =
      firstError(checkRange(lower, lo, -bound, bound), checkRange(upper, hi, -bound, bound));
  if (error.empty() && lo > hi) error = std::string(lower) + " must not exceed " + upper;
  return error;
}

std::string checkAxis(const Vec2& axis) {
  if (isFinite(axis) && axis.norm() > Real(1e-6) && axis.norm() < Real(1e6)) return {};
  return "axis must be a finite, non-zero vector";
}

std::string checkSettings(const DistanceJointSettings& s) {
  return firstError(checkRange("length", s.length, 0, kMaxLength),
                    checkSpring("stiffness", s.stiffness, "damping", s.damping));
}
std::string checkSettings(const RopeJointSettings& s) {
  return checkRange("maxLength", s.maxLength, 0, kMaxLength);
}
std::string checkSettings(const RevoluteJointSettings& s) {
  return firstError(checkLimits("lowerAngle", s.lowerAngle, "upperAngle", s.upperAngle, kPi),
                    checkMotor("motorSpeed", s.motorSpeed, "maxMotorTorque", s.maxMotorTorque),
                    checkSpring("stiffness", s.stiffness, "damping", s.damping));
}
std::string checkSettings(const PrismaticJointSettings& s) {
  return firstError(checkAxis(s.axis), checkLimits("lower", s.lower, "upper", s.upper, kMaxLength),
                    checkMotor("motorSpeed", s.motorSpeed, "maxMotorForce", s.maxMotorForce),
                    checkSpring("stiffness", s.stiffness, "damping", s.damping));
}
std::string checkSettings(const WeldJointSettings& s) {
  return firstError(checkRange("linearStiffness", s.linearStiffness, 0, kMaxStiffness),
                    checkRange("angularStiffness", s.angularStiffness, 0, kMaxStiffness));
}
std::string checkSettings(const WheelJointSettings& s) {
  return firstError(checkAxis(s.axis),
                    checkMotor("motorSpeed", s.motorSpeed, "maxMotorTorque", s.maxMotorTorque),
                    checkSpring("stiffness", s.stiffness, "damping", s.damping));
}
std::string checkSettings(const MouseJointSettings& s) {
  return firstError(checkRange("maxForce", s.maxForce, 0, kMaxMotorForce),
                    checkSpring("stiffness", s.stiffness, "damping", s.damping));
}

// Anchors and targets may lie where a push may act (limits.h).
std::string checkPoint(const WorldData& world, const char* field, const Vec2& p) {
  return checkApplicationPoint(world.settings.inputLimits, world.settings.bounds, world.origin, p,
                               field);
}

std::string validateJoint(const WorldData& world, const JointDef& def) {
  const Body* a = world.find(def.bodyA);
  const Body* b = world.find(def.bodyB);
  if (def.bodyA.isNull()) return "bodyA must be a body; only bodyB may be the world (null)";
  if (a == nullptr) return "bodyA is not a live body (unknown or removed)";
  if (!def.bodyB.isNull() && b == nullptr) return "bodyB is not a live body (unknown or removed)";
  if (def.bodyA == def.bodyB) return "bodyA and bodyB are the same body";
  if (!a->isDynamic() && (b == nullptr || !b->isDynamic()))
    return "a joint needs a dynamic body (both ends are static, kinematic or the world)";
  if (std::holds_alternative<MouseJointSettings>(def.settings) && !a->isDynamic())
    return "a mouse joint pulls bodyA, which is static or kinematic";
  return firstError(checkPoint(world, "anchorA", def.anchorA),
                    checkPoint(world, "anchorB", def.anchorB),
                    checkJointSettings(def.settings));
}

}  // namespace

std::string checkJointSettings(const JointSettings& settings) {
  return std::visit([](const auto& s) { return checkSettings(s); }, settings);
}

namespace {

Transform frameOf(const WorldData& world, std::int32_t slot) {
  return slot == kNullIndex ? Transform{} : world.bodies[slot].transform;
}

std::int32_t slotOf(BodyId id) { return id.isNull() ? kNullIndex : id.slot(); }

// The settings as the joint keeps them: lengths resolved, axes unit.
JointSettings resolved(JointSettings settings, Real anchorDistance) {
  if (auto* s = std::get_if<DistanceJointSettings>(&settings); s && s->length == 0)
    s->length = anchorDistance;
  if (auto* s = std::get_if<RopeJointSettings>(&settings); s && s->maxLength == 0)
    s->maxLength = anchorDistance;
  if (auto* s = std::get_if<PrismaticJointSettings>(&settings)) s->axis.normalize();
  if (auto* s = std::get_if<WheelJointSettings>(&settings)) s->axis.normalize();
  return settings;
}

Real jointLength(const JointSettings& settings) {
  if (auto* s = std::get_if<DistanceJointSettings>(&settings)) return s->length;
  if (auto* s = std::get_if<RopeJointSettings>(&settings)) return s->maxLength;
  return 0;
}

Vec2 jointAxis(const JointSettings& settings) {
  if (auto* s = std::get_if<PrismaticJointSettings>(&settings)) return s->axis;
  if (auto* s = std::get_if<WheelJointSettings>(&settings)) return s->axis;
  return Vec2(1, 0);
}

void initJoint(const WorldData& world, Joint& joint, const JointDef& def) {
  std::int32_t a = slotOf(def.bodyA);
  std::int32_t b = slotOf(def.bodyB);
  Transform ta = frameOf(world, a);
  Transform tb = frameOf(world, b);
  joint.edges = EdgeLinks{};
  joint.edges.bodyA = a;
  joint.edges.bodyB = b;
  joint.settings = resolved(def.settings, (def.anchorB - def.anchorA).norm());
  joint.localAnchorA = ta.applyInverse(def.anchorA);
  joint.localAnchorB = tb.applyInverse(def.anchorB);
  joint.referenceAngle = relativeRotation(ta.q, tb.q).angle();
  Vec2 axis = jointAxis(joint.settings);
  joint.localAxisA = ta.q.applyInverse(axis);
  Vec2 offset = def.anchorB - def.anchorA;
  joint.referenceTranslation = axis.dot(offset);
  joint.referencePerpendicular = leftPerp(axis).dot(offset);
  joint.length = jointLength(joint.settings);
  joint.target = def.anchorB;
  joint.impulses = {};
  joint.reactionForce.setZero();
  joint.reactionTorque = 0;
  joint.collideConnected = def.collideConnected;
  joint.alive = true;
}

void linkJoint(WorldData& world, std::int32_t index) {
  ++world.jointLinkChanges;
  for (int side = 0; side < 2; ++side) {
    std::int32_t body = world.joints[index].edges.body(side);
    if (body != kNullIndex) linkEdge(world.joints, world.bodies[body].jointHead, index, side);
  }
}

void unlinkJoint(WorldData& world, std::int32_t index) {
  ++world.jointLinkChanges;
  for (int side = 0; side < 2; ++side) {
    std::int32_t body = world.joints[index].edges.body(side);
    if (body != kNullIndex) unlinkEdge(world.joints, world.bodies[body].jointHead, index, side);
  }
}

void wakeJointBodies(WorldData& world, const Joint& joint) {
  for (int side = 0; side < 2; ++side) {
    if (joint.edges.body(side) != kNullIndex) wakeIsland(world, joint.edges.body(side));
  }
}

// A joint made or destroyed by a call wakes its bodies: a reader gets their
// states (awake now) with the joint.
void markJointBodiesMoved(WorldData& world, const Joint& joint) {
  for (int side = 0; side < 2; ++side) {
    if (joint.edges.body(side) != kNullIndex)
      world.changes.mark(BodyChange::Moved, world.idOf(joint.edges.body(side)));
  }
}

void destroyContactsBetween(WorldData& world, std::int32_t a, std::int32_t b) {
  if (a == kNullIndex || b == kNullIndex) return;
  std::int32_t key = world.bodies[a].contactHead;
  while (key != kNullIndex) {
    std::int32_t index = edgeElement(key);
    std::int32_t next = world.contacts[index].edges.next[edgeSide(key)];
    if (world.contacts[index].edges.otherBody(key) == b) destroyContact(world, index);
    key = next;
  }
}

// The pair's contacts were held back; let the broad phase look again.
void rediscoverPair(WorldData& world, const Joint& joint) {
  if (joint.collideConnected || joint.edges.bodyB == kNullIndex) return;
  for (int side = 0; side < 2; ++side) {
    const std::int32_t body = joint.edges.body(side);
    if (!world.bodies[body].isStatic) touchBodyProxies(world, body);
  }
}

JointId idOf(const WorldData& world, std::int32_t index) {
  return JointId::make(index, world.joints[index].generation);
}

void removeJoint(WorldData& world, std::int32_t index) {
  Joint& joint = world.joints[index];
  world.changes.mark(JointChange::Destroyed, idOf(world, index));
  wakeJointBodies(world, joint);
  unlinkJoint(world, index);
  rediscoverPair(world, joint);
  joint.alive = false;
  ++joint.generation;
  world.freeJoints.release(index);
  --world.liveJoints;
}

}  // namespace

bool jointBlocksContact(const WorldData& world, std::int32_t bodyA, std::int32_t bodyB) {
  bool blocked = false;
  forEachEdge(
      world.joints, world.bodies[bodyA].jointHead, [&](std::int32_t key, const Joint& joint) {
        blocked = blocked || (!joint.collideConnected && joint.edges.otherBody(key) == bodyB);
      });
  return blocked;
}

void destroyBodyJoints(WorldData& world, std::int32_t body) {
  while (world.bodies[body].jointHead != kNullIndex) {
    removeJoint(world, edgeElement(world.bodies[body].jointHead));
  }
}

JointResult World::createJoint(const JointDef& def) {
  WorldData& w = *impl_;
  if (std::string error = validateJoint(w, def); !error.empty()) return {{}, error};
  std::int32_t index = w.freeJoints.acquire(w.joints.size());
  if (index == static_cast<std::int32_t>(w.joints.size())) w.joints.emplace_back();
  initJoint(w, w.joints[index], def);
  linkJoint(w, index);
  ++w.liveJoints;
  const Joint& joint = w.joints[index];
  if (!joint.collideConnected) destroyContactsBetween(w, joint.edges.bodyA, joint.edges.bodyB);
  wakeJointBodies(w, joint);
  w.changes.mark(JointChange::Created, idOf(w, index));
  markJointBodiesMoved(w, joint);
  return {idOf(w, index), {}};
}

bool World::destroyJoint(JointId id) {
  const Joint* joint = findLive(impl_->joints, id);
  if (joint == nullptr) return false;
  markJointBodiesMoved(*impl_, *joint);
  removeJoint(*impl_, id.slot());
  return true;
}

namespace {

std::string applyUpdate(Joint& joint, const JointUpdate& update) {
  auto* mouse = std::get_if<MouseJointSettings>(&joint.settings);
  if (update.target && mouse == nullptr) return "target: only a mouse joint has a target";
  if (update.target) joint.target = *update.target;
  auto setMotor = [&](Real& speed, Real& force, const char* forceName) {
    std::string error = firstError(
        update.motorSpeed
            ? checkRange("motorSpeed", *update.motorSpeed, -kMaxMotorSpeed, kMaxMotorSpeed)
            : "",
        update.maxMotorForce ? checkRange(forceName, *update.maxMotorForce, 0, kMaxMotorForce)
                             : "");
    if (!error.empty()) return error;
    speed = update.motorSpeed.value_or(speed);
    force = update.maxMotorForce.value_or(force);
    return error;
  };
  if (auto* s = std::get_if<RevoluteJointSettings>(&joint.settings))
    return setMotor(s->motorSpeed, s->maxMotorTorque, "maxMotorForce");
  if (auto* s = std::get_if<PrismaticJointSettings>(&joint.settings))
    return setMotor(s->motorSpeed, s->maxMotorForce, "maxMotorForce");
  if (auto* s = std::get_if<WheelJointSettings>(&joint.settings))
    return setMotor(s->motorSpeed, s->maxMotorTorque, "maxMotorForce");
  if (update.motorSpeed || update.maxMotorForce)
    return "motorSpeed, maxMotorForce: this joint kind has no motor";
  return {};
}

}  // namespace

InputResult World::updateJoint(JointId id, const JointUpdate& update) {
  WorldData& w = *impl_;
  Joint* joint = findLive(w.joints, id);
  if (joint == nullptr) return {"joint is not a live joint (unknown or removed)"};
  if (update.target) {
    if (std::string error = checkPoint(w, "target", *update.target); !error.empty()) return {error};
  }
  // Checked on a copy, so a refused update changes nothing.
  Joint changed = *joint;
  if (std::string error = applyUpdate(changed, update); !error.empty()) return {error};
  *joint = changed;
  wakeJointBodies(w, *joint);
  w.changes.mark(JointChange::Updated, id);
  return {};
}

std::optional<JointDescription> World::jointDescription(JointId id) const {
  const WorldData& w = *impl_;
  const Joint* joint = findLive(w.joints, id);
  if (joint == nullptr) return std::nullopt;
  auto bodyId = [&](std::int32_t slot) { return slot == kNullIndex ? BodyId{} : w.idOf(slot); };
  return JointDescription{id,
                          bodyId(joint->edges.bodyA),
                          bodyId(joint->edges.bodyB),
                          joint->localAnchorA,
                          joint->localAnchorB,
                          joint->collideConnected,
                          joint->settings};
}

std::optional<JointState> World::jointState(JointId id) const {
  const WorldData& w = *impl_;
  const Joint* joint = findLive(w.joints, id);
  if (joint == nullptr) return std::nullopt;
  Transform ta = frameOf(w, joint->edges.bodyA);
  Transform tb = frameOf(w, joint->edges.bodyB);
  Vec2 anchorA = ta.apply(joint->localAnchorA);
  bool mouse = std::holds_alternative<MouseJointSettings>(joint->settings);
  Vec2 offset = (mouse ? joint->target : tb.apply(joint->localAnchorB)) - anchorA;
  Vec2 axis = ta.q.apply(joint->localAxisA);
  JointState state;
  state.reactionForce = joint->reactionForce;
  state.reactionTorque = joint->reactionTorque;
  state.length = offset.norm();
  state.angle = jointAngle(*joint, ta.q, tb.q);
  state.translation = axis.dot(offset) - joint->referenceTranslation;
  return state;
}

std::vector<JointId> World::jointIds() const { return liveIds<JointId>(impl_->joints, impl_->liveJoints); }

int World::jointCount() const { return impl_->liveJoints; }

}  // namespace impulse
