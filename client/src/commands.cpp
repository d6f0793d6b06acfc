#include "impulse/client/commands.h"

#include "impulse/wire/convert.h"
#include "impulse/wire/query_convert.h"

namespace impulse::client {

namespace {

void setPoint(Point p, v1::Vec2* out) {
  out->set_x(p.x);
  out->set_y(p.y);
}

void setOptions(const SpawnOptions& options, v1::BodyOptions* out) {
  out->set_material(wire::toWire(options.material));
  out->set_is_static(options.isStatic);
  out->set_is_kinematic(options.isKinematic);
  if (!options.isAwake) out->set_is_awake(false);
  out->set_ignore_gravity(options.ignoreGravity);
  setPoint({options.velocityX, options.velocityY}, out->mutable_velocity());
  out->set_angular_velocity(options.angularVelocity);
  if (options.density) out->set_density(*options.density);
  if (options.friction) out->set_friction(*options.friction);
  if (options.restitution) out->set_restitution(*options.restitution);
  out->set_linear_damping(options.linearDamping);
  out->set_angular_damping(options.angularDamping);
  if (options.gravityScale) out->set_gravity_scale(*options.gravityScale);
  wire::toWire(options.flags, out->mutable_shape_flags());
}

// A CreateJoint with `ends` and `kind` in the oneof field `field` selects.
template <class Kind>
v1::ClientMessage createJoint(const JointEnds& ends, const Kind& kind,
                              Kind* (v1::CreateJoint::*field)()) {
  v1::ClientMessage message;
  auto* command = message.mutable_create_joint();
  command->set_body_a(ends.bodyA);
  command->set_body_b(ends.bodyB);
  setPoint(ends.anchorA, command->mutable_anchor_a());
  setPoint(ends.anchorB, command->mutable_anchor_b());
  command->set_collide_connected(ends.collideConnected);
  *(command->*field)() = kind;
  return message;
}

}  // namespace

v1::ClientMessage spawnCircle(Point center, double radius, const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_circle();
  setPoint(center, command->mutable_center());
  command->set_radius(radius);
  setOptions(options, command->mutable_options());
  return message;
}

v1::ClientMessage spawnPolygon(std::span<const Point> vertices, const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_polygon();
  for (const Point& p : vertices) setPoint(p, command->add_vertices());
  setOptions(options, command->mutable_options());
  return message;
}

v1::ClientMessage spawnCapsule(Point center1, Point center2, double radius, const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_capsule();
  setPoint(center1, command->mutable_center1());
  setPoint(center2, command->mutable_center2());
  command->set_radius(radius);
  setOptions(options, command->mutable_options());
  return message;
}

v1::ClientMessage spawnSegment(Point point1, Point point2, const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_segment();
  setPoint(point1, command->mutable_point1());
  setPoint(point2, command->mutable_point2());
  setOptions(options, command->mutable_options());
  return message;
}

v1::ClientMessage spawnChain(std::span<const Point> points, bool loop, const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_chain();
  for (const Point& p : points) setPoint(p, command->add_points());
  command->set_loop(loop);
  setOptions(options, command->mutable_options());
  return message;
}

namespace {

void setPartShape(const BodyPart& part, v1::Shape* shape) {
  switch (part.kind) {
    case BodyPart::Kind::Circle:
      shape->mutable_circle()->set_radius(part.radius);
      setPoint(part.point1, shape->mutable_circle()->mutable_center());
      return;
    case BodyPart::Kind::Box: {
      const Point c = part.point1, h = part.point2;
      for (Point corner : {Point{c.x - h.x, c.y - h.y}, Point{c.x + h.x, c.y - h.y}, Point{c.x + h.x, c.y + h.y},
                           Point{c.x - h.x, c.y + h.y}}) {
        setPoint(corner, shape->mutable_polygon()->add_vertices());
      }
      return;
    }
    case BodyPart::Kind::Capsule:
      setPoint(part.point1, shape->mutable_capsule()->mutable_center1());
      setPoint(part.point2, shape->mutable_capsule()->mutable_center2());
      shape->mutable_capsule()->set_radius(part.radius);
      return;
  }
}

void setPart(const BodyPart& part, v1::ShapePart* out) {
  out->set_material(wire::toWire(part.material));
  setPartShape(part, out->mutable_shape());
}

// A command that names a body and a pose (SetTargetTransform,
// SetTransform), in the oneof field `field` selects.
template <class Command>
v1::ClientMessage bodyPose(std::uint32_t body, Point position, double angle,
                           Command* (v1::ClientMessage::*field)()) {
  v1::ClientMessage message;
  Command* command = (message.*field)();
  command->set_body_id(body);
  setPoint(position, command->mutable_position());
  command->set_angle(angle);
  return message;
}

}  // namespace

v1::ClientMessage spawnBody(Point position, double angle, std::span<const BodyPart> parts,
                            const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_body();
  setPoint(position, command->mutable_position());
  command->set_angle(angle);
  for (const BodyPart& part : parts) setPart(part, command->add_parts());
  setOptions(options, command->mutable_options());
  return message;
}

v1::ClientMessage rayCast(Point origin, Point translation, bool allHits, const QueryFilter& filter,
                          std::uint32_t maxHits) {
  v1::ClientMessage message;
  auto* command = message.mutable_ray_cast();
  setPoint(origin, command->mutable_origin());
  setPoint(translation, command->mutable_translation());
  wire::toWire(filter, command->mutable_filter());
  command->set_all_hits(allHits);
  command->set_max_hits(maxHits);
  return message;
}

v1::ClientMessage shapeCast(Point position, double angle, const BodyPart& shape, Point translation,
                            const QueryFilter& filter) {
  v1::ClientMessage message;
  auto* command = message.mutable_shape_cast();
  setPartShape(shape, command->mutable_shape());
  setPoint(position, command->mutable_position());
  command->set_angle(angle);
  setPoint(translation, command->mutable_translation());
  wire::toWire(filter, command->mutable_filter());
  return message;
}

v1::ClientMessage queryAabb(Point lower, Point upper, const QueryFilter& filter, std::uint32_t maxResults) {
  v1::ClientMessage message;
  auto* command = message.mutable_query_aabb();
  setPoint(lower, command->mutable_lower());
  setPoint(upper, command->mutable_upper());
  wire::toWire(filter, command->mutable_filter());
  command->set_max_results(maxResults);
  return message;
}

v1::ClientMessage setTargetTransform(std::uint32_t body, Point position, double angle) {
  return bodyPose(body, position, angle, &v1::ClientMessage::mutable_set_target_transform);
}

v1::ClientMessage setTransform(std::uint32_t body, Point position, double angle) {
  return bodyPose(body, position, angle, &v1::ClientMessage::mutable_set_transform);
}

v1::ClientMessage setMaterial(std::uint32_t body, Material material) {
  v1::ClientMessage message;
  message.mutable_set_material()->set_body_id(body);
  message.mutable_set_material()->set_material(wire::toWire(material));
  return message;
}

v1::ClientMessage setBodyType(std::uint32_t body, BodyType type) {
  v1::ClientMessage message;
  message.mutable_set_body_type()->set_body_id(body);
  message.mutable_set_body_type()->set_type(wire::toWire(type));
  return message;
}

v1::ClientMessage loadPreset(int preset, Material material) {
  v1::ClientMessage message;
  message.mutable_load_preset()->set_preset(preset);
  message.mutable_load_preset()->set_material(wire::toWire(material));
  return message;
}

v1::ClientMessage setGravity(Point gravity) {
  v1::ClientMessage message;
  setPoint(gravity, message.mutable_set_gravity()->mutable_gravity());
  return message;
}

v1::ClientMessage nudgeGravity(Point delta) {
  v1::ClientMessage message;
  setPoint(delta, message.mutable_nudge_gravity()->mutable_delta());
  return message;
}

v1::ClientMessage resetGravity() {
  v1::ClientMessage message;
  message.mutable_reset_gravity();
  return message;
}

v1::ClientMessage clearWorld() {
  v1::ClientMessage message;
  message.mutable_clear();
  return message;
}

v1::ClientMessage removeBody(std::uint32_t id) {
  v1::ClientMessage message;
  message.mutable_remove_body()->set_body_id(id);
  return message;
}

v1::ClientMessage applyImpulse(std::uint32_t id, Point impulse, std::optional<Point> point) {
  v1::ClientMessage message;
  auto* command = message.mutable_apply_impulse();
  command->set_body_id(id);
  setPoint(impulse, command->mutable_impulse());
  if (point) setPoint(*point, command->mutable_point());
  return message;
}

v1::ClientMessage setVelocity(std::uint32_t id, Point velocity, double angular) {
  v1::ClientMessage message;
  auto* command = message.mutable_set_velocity();
  command->set_body_id(id);
  setPoint(velocity, command->mutable_velocity());
  command->set_angular_velocity(angular);
  return message;
}

v1::ClientMessage setShapeFlags(std::uint32_t id, const ShapeInteraction& flags) {
  v1::ClientMessage message;
  auto* command = message.mutable_set_shape_flags();
  command->set_body_id(id);
  wire::toWire(flags, command->mutable_flags());
  return message;
}

v1::ClientMessage subscribeEvents(bool enabled) {
  v1::ClientMessage message;
  message.mutable_subscribe_events()->set_enabled(enabled);
  return message;
}

v1::ClientMessage setPaused(bool paused) {
  v1::ClientMessage message;
  message.mutable_set_paused()->set_paused(paused);
  return message;
}

v1::ClientMessage step(std::uint32_t ticks) {
  v1::ClientMessage message;
  message.mutable_step()->set_ticks(ticks);
  return message;
}

v1::ClientMessage queryBody(std::uint32_t id) {
  v1::ClientMessage message;
  message.mutable_query_body()->set_body_id(id);
  return message;
}

v1::ClientMessage distanceJoint(const JointEnds& ends, const v1::DistanceJoint& kind) {
  return createJoint(ends, kind, &v1::CreateJoint::mutable_distance);
}

v1::ClientMessage ropeJoint(const JointEnds& ends, const v1::RopeJoint& kind) {
  return createJoint(ends, kind, &v1::CreateJoint::mutable_rope);
}

v1::ClientMessage revoluteJoint(const JointEnds& ends, const v1::RevoluteJoint& kind) {
  return createJoint(ends, kind, &v1::CreateJoint::mutable_revolute);
}

v1::ClientMessage prismaticJoint(const JointEnds& ends, const v1::PrismaticJoint& kind) {
  return createJoint(ends, kind, &v1::CreateJoint::mutable_prismatic);
}

v1::ClientMessage weldJoint(const JointEnds& ends, const v1::WeldJoint& kind) {
  return createJoint(ends, kind, &v1::CreateJoint::mutable_weld);
}

v1::ClientMessage wheelJoint(const JointEnds& ends, const v1::WheelJoint& kind) {
  return createJoint(ends, kind, &v1::CreateJoint::mutable_wheel);
}

v1::ClientMessage mouseJoint(std::uint32_t body, Point point, const v1::MouseJoint& kind) {
  return createJoint(JointEnds{body, 0, point, point, false}, kind,
                     &v1::CreateJoint::mutable_mouse);
}

v1::ClientMessage setJointTarget(std::uint32_t joint, Point target) {
  v1::ClientMessage message;
  message.mutable_update_joint()->set_joint_id(joint);
  setPoint(target, message.mutable_update_joint()->mutable_target());
  return message;
}

v1::ClientMessage setJointMotor(std::uint32_t joint, double speed, std::optional<double> maxForce) {
  v1::ClientMessage message;
  auto* command = message.mutable_update_joint();
  command->set_joint_id(joint);
  command->set_motor_speed(speed);
  if (maxForce) command->set_max_motor_force(*maxForce);
  return message;
}

v1::ClientMessage removeJoint(std::uint32_t joint) {
  v1::ClientMessage message;
  message.mutable_remove_joint()->set_joint_id(joint);
  return message;
}

v1::ClientMessage tagJoint(v1::ClientMessage createJoint, std::uint32_t tag) {
  createJoint.mutable_create_joint()->set_tag(tag);
  return createJoint;
}

namespace {

/// An UpdateJoint or RemoveJoint naming its joint by `id` or by `tag`.
v1::ClientMessage namingJoint(v1::ClientMessage jointCommand, std::uint32_t id, std::uint32_t tag) {
  if (jointCommand.has_update_joint()) {
    jointCommand.mutable_update_joint()->set_joint_id(id);
    jointCommand.mutable_update_joint()->set_joint_tag(tag);
  } else {
    jointCommand.mutable_remove_joint()->set_joint_id(id);
    jointCommand.mutable_remove_joint()->set_joint_tag(tag);
  }
  return jointCommand;
}

}  // namespace

v1::ClientMessage byJointTag(v1::ClientMessage jointCommand, std::uint32_t tag) {
  return namingJoint(std::move(jointCommand), 0, tag);
}

v1::ClientMessage byJointId(v1::ClientMessage jointCommand, std::uint32_t joint) {
  return namingJoint(std::move(jointCommand), joint, 0);
}

v1::ClientMessage queryJoint(std::uint32_t joint) {
  v1::ClientMessage message;
  message.mutable_query_joint()->set_joint_id(joint);
  return message;
}

v1::ClientMessage saveScene() {
  v1::ClientMessage message;
  message.mutable_save_scene();
  return message;
}

v1::ClientMessage loadScene(std::string data) {
  v1::ClientMessage message;
  message.mutable_load_scene()->set_data(std::move(data));
  return message;
}

v1::ClientMessage gravitationField(double constant) {
  v1::ClientMessage message;
  message.mutable_add_field()->mutable_gravitation()->set_constant(constant);
  return message;
}

v1::ClientMessage fluidField(const v1::FluidRegion& fluid) {
  v1::ClientMessage message;
  *message.mutable_add_field()->mutable_fluid() = fluid;
  return message;
}

v1::ClientMessage fanField(const v1::Fan& fan) {
  v1::ClientMessage message;
  *message.mutable_add_field()->mutable_fan() = fan;
  return message;
}

v1::ClientMessage removeField(std::uint32_t field) {
  v1::ClientMessage message;
  message.mutable_remove_field()->set_field_id(field);
  return message;
}

v1::ClientMessage ping(std::uint64_t clientTimeUs, bool wantStateHash) {
  v1::ClientMessage message;
  message.mutable_ping()->set_client_time_us(clientTimeUs);
  message.mutable_ping()->set_want_state_hash(wantStateHash);
  return message;
}

v1::ClientMessage setTimeScale(double scale) {
  v1::ClientMessage message;
  message.mutable_set_time_scale()->set_scale(scale);
  return message;
}

v1::ClientMessage listRooms() {
  v1::ClientMessage message;
  message.mutable_list_rooms();
  return message;
}

v1::ClientMessage setInterestArea(std::optional<Box> area) {
  v1::ClientMessage message;
  auto* command = message.mutable_set_interest_area();
  if (area) {
    command->mutable_min()->set_x(area->min.x);
    command->mutable_min()->set_y(area->min.y);
    command->mutable_max()->set_x(area->max.x);
    command->mutable_max()->set_y(area->max.y);
  }
  return message;
}

v1::ClientMessage setBandwidthBudget(std::optional<double> bytesPerSecond) {
  v1::ClientMessage message;
  auto* command = message.mutable_set_bandwidth_budget();
  if (bytesPerSecond) command->set_bytes_per_second(*bytesPerSecond);
  return message;
}

v1::ClientMessage forTick(v1::ClientMessage message, std::uint64_t tick) {
  message.set_for_tick(tick);
  return message;
}

}  // namespace impulse::client
