#include "local_world.h"

#include <vector>

#include "impulse/field_kinds.h"
#include "impulse/wire/convert.h"
#include "impulse/wire/wire_positions.h"

namespace impulse::client {

namespace {

Vec2 worldPoint(const BodyState& state, const Vec2& local) {
  return Transform{state.position, Rot::fromAngle(state.angle)}.apply(local);
}

BodyDef bodyDefOf(const MirrorBody& body) {
  BodyDef def;
  def.shape = body.shape;
  for (const Shape& shape : body.extraShapes) {
    ShapeDef extra;
    extra.shape = shape;
    extra.material = body.material;
    extra.interaction = body.flags;
    def.extraShapes.push_back(extra);
  }
  def.position = body.state.position;
  def.angle = body.state.angle;
  def.linearVelocity = body.state.linearVelocity;
  def.angularVelocity = body.state.angularVelocity;
  def.material = body.material;
  def.interaction = body.flags;
  def.properties.isStatic = body.isStatic;
  def.properties.isKinematic = body.isKinematic;
  def.isAwake = body.state.awake && !body.isStatic;
  def.properties.ignoreGravity = body.ignoreGravity;
  return def;
}

template <class Id>
std::vector<std::uint32_t> keysOf(const std::map<std::uint32_t, Id>& map) {
  std::vector<std::uint32_t> keys;
  keys.reserve(map.size());
  for (const auto& entry : map) keys.push_back(entry.first);
  return keys;
}

template <class A, class B>
bool sameKeys(const std::map<std::uint32_t, A>& a, const std::map<std::uint32_t, B>& b) {
  return a.size() == b.size() && keysOf(a) == keysOf(b);
}

}  // namespace

void LocalWorld::rebuild(const WorldMirror& mirror) {
  world_ = World(settings_);
  // The mirror's positions are relative to the room's origin, as the
  // room's world computes them (an empty world takes any origin).
  world_.shiftOrigin(mirror.origin());
  bodies_.clear();
  joints_.clear();
  forgetPredictions();
  world_.setGravity(mirror.gravity());
  for (const auto& [id, body] : mirror.bodies()) {
    // A body this world refuses (its limits are the server's, so none
    // should be) is left out: commands naming it are not predicted.
    if (const CreateResult made = world_.createBody(bodyDefOf(body)); made.ok()) bodies_[id] = made.id;
  }
  for (const auto& [id, joint] : mirror.joints()) {
    const MirrorBody* bodyA = mirror.find(joint.bodyA);
    const MirrorBody* bodyB = joint.bodyB.isNull() ? nullptr : mirror.find(joint.bodyB);
    const auto localA = localBody(joint.bodyA.value);
    const auto localB = bodyB ? localBody(joint.bodyB.value) : std::optional<BodyId>(BodyId{});
    if (!bodyA || !localA || !localB) continue;
    const JointDef def{.bodyA = *localA,
                       .bodyB = *localB,
                       .anchorA = worldPoint(bodyA->state, joint.localAnchorA),
                       .anchorB = bodyB ? worldPoint(bodyB->state, joint.localAnchorB) : joint.localAnchorB,
                       .collideConnected = joint.collideConnected,
                       .settings = joint.settings};
    if (const JointResult made = world_.createJoint(def); made.ok()) joints_[id] = made.id;
  }
  for (const auto& [id, def] : mirror.fields()) {
    if (FieldBuild field = makeField(def); field.ok()) world_.addField(std::move(field.field));
  }
}

void LocalWorld::forgetPredictions() {
  spawns_.clear();
  taggedJoints_.clear();
}

void LocalWorld::takeStates(const WorldMirror& mirror) {
  forgetPredictions();
  for (const auto& [id, local] : bodies_) {
    const MirrorBody* body = mirror.find(BodyId{id});
    if (!body || body->isStatic) continue;
    world_.setTransform(local, body->state.position, body->state.angle);
    world_.setVelocity(local, body->state.linearVelocity, body->state.angularVelocity);
  }
  world_.setGravity(mirror.gravity());
}

bool LocalWorld::describes(const WorldMirror& mirror) const {
  return sameKeys(bodies_, mirror.bodies()) && sameKeys(joints_, mirror.joints());
}

std::optional<BodyId> LocalWorld::localBody(std::uint32_t serverBody) const {
  const auto it = bodies_.find(serverBody);
  return it == bodies_.end() ? std::nullopt : std::optional(it->second);
}

std::optional<JointId> LocalWorld::localJoint(std::uint32_t serverJoint) const {
  const auto it = joints_.find(serverJoint);
  return it == joints_.end() ? std::nullopt : std::optional(it->second);
}

std::optional<BodyId> LocalWorld::localSpawn(std::uint64_t requestId) const {
  const auto it = spawns_.find(requestId);
  return it == spawns_.end() ? std::nullopt : std::optional(it->second);
}

std::optional<JointId> LocalWorld::namedJoint(std::uint32_t serverJoint, std::uint32_t tag) const {
  if (tag == 0) return localJoint(serverJoint);
  const auto it = taggedJoints_.find(tag);
  return it == taggedJoints_.end() ? std::nullopt : std::optional(it->second);
}

bool LocalWorld::spawned(const CreateResult& made, std::uint64_t requestId) {
  if (!made.ok()) return false;
  if (requestId != 0) spawns_[requestId] = made.id;
  return true;
}

bool LocalWorld::predictsKind(const v1::ClientMessage& message) {
  switch (message.command_case()) {
    case v1::ClientMessage::kApplyImpulse:
    case v1::ClientMessage::kSetVelocity:
    case v1::ClientMessage::kSetTargetTransform:
    case v1::ClientMessage::kSpawnCircle:
    case v1::ClientMessage::kSpawnPolygon:
    case v1::ClientMessage::kCreateJoint:
    case v1::ClientMessage::kUpdateJoint:
    case v1::ClientMessage::kRemoveJoint:
      return true;
    default:
      return false;
  }
}

std::optional<std::uint32_t> LocalWorld::namedBody(const v1::ClientMessage& message) {
  switch (message.command_case()) {
    case v1::ClientMessage::kApplyImpulse: return message.apply_impulse().body_id();
    case v1::ClientMessage::kSetVelocity: return message.set_velocity().body_id();
    case v1::ClientMessage::kSetTargetTransform: return message.set_target_transform().body_id();
    case v1::ClientMessage::kCreateJoint: return message.create_joint().body_a();
    default: return std::nullopt;
  }
}

bool LocalWorld::apply(const v1::ClientMessage& command, Real dt, std::uint64_t requestId) {
  // The command's positions are from (0, 0): relative to the origin, in
  // double, before any becomes a float.
  v1::ClientMessage message = command;
  wire::shiftPositions(message, -world_.origin());
  const auto named = namedBody(message);
  const auto body = named ? localBody(*named) : std::nullopt;
  if (named && !body) return false;
  switch (message.command_case()) {
    case v1::ClientMessage::kApplyImpulse: {
      const auto& push = message.apply_impulse();
      const auto impulse = wire::vecFromWire(push.impulse(), "impulse");
      const auto point = push.has_point() ? wire::vecFromWire(push.point(), "point") : wire::Decoded<Vec2>{};
      if (!impulse.ok() || (push.has_point() && !point.ok())) return false;
      return world_.applyImpulse(*body, *impulse.value, point.value).ok();
    }
    case v1::ClientMessage::kSetVelocity: {
      const auto& set = message.set_velocity();
      const auto velocity = wire::vecFromWire(set.velocity(), "velocity");
      return velocity.ok() && world_.setVelocity(*body, *velocity.value, Real(set.angular_velocity())).ok();
    }
    case v1::ClientMessage::kSetTargetTransform: {
      const auto& target = message.set_target_transform();
      const auto position = wire::vecFromWire(target.position(), "position");
      return position.ok() && world_.setTargetTransform(*body, *position.value, Real(target.angle()), dt).ok();
    }
    case v1::ClientMessage::kSpawnCircle: {
      const auto& spawn = message.spawn_circle();
      const auto center = wire::vecFromWire(spawn.center(), "center");
      const auto options = wire::optionsFromWire(spawn.options());
      return center.ok() && options.ok() &&
             spawned(world_.createCircle(*center.value, Real(spawn.radius()), *options.value), requestId);
    }
    case v1::ClientMessage::kSpawnPolygon: {
      std::vector<Vec2> points;
      for (const auto& vertex : message.spawn_polygon().vertices()) {
        const auto point = wire::vecFromWire(vertex, "vertex");
        if (!point.ok()) return false;
        points.push_back(*point.value);
      }
      const auto options = wire::optionsFromWire(message.spawn_polygon().options());
      return options.ok() && spawned(world_.createPolygon(points, *options.value), requestId);
    }
    default:
      return applyJoint(message);
  }
}

bool LocalWorld::applyJoint(const v1::ClientMessage& message) {
  switch (message.command_case()) {
    case v1::ClientMessage::kCreateJoint: {
      auto def = wire::jointDefFromWire(message.create_joint());
      if (!def.ok()) return false;
      const auto bodyA = localBody(def.value->bodyA.value);
      const auto bodyB = def.value->bodyB.isNull() ? std::optional(BodyId{}) : localBody(def.value->bodyB.value);
      if (!bodyA || !bodyB) return false;
      def.value->bodyA = *bodyA;
      def.value->bodyB = *bodyB;
      const JointResult made = world_.createJoint(*def.value);
      if (made.ok() && message.create_joint().tag() != 0) taggedJoints_[message.create_joint().tag()] = made.id;
      return made.ok();
    }
    case v1::ClientMessage::kUpdateJoint: {
      const auto& named = message.update_joint();
      const auto joint = namedJoint(named.joint_id(), named.joint_tag());
      const auto update = wire::jointUpdateFromWire(message.update_joint());
      return joint && update.ok() && world_.updateJoint(*joint, *update.value).ok();
    }
    case v1::ClientMessage::kRemoveJoint: {
      const auto& named = message.remove_joint();
      const auto joint = namedJoint(named.joint_id(), named.joint_tag());
      return joint && world_.destroyJoint(*joint);
    }
    default:
      return false;
  }
}

}  // namespace impulse::client
