#include "impulse/server/command_handlers.h"

#include <string>
#include <vector>

#include "impulse/wire/convert.h"
#include "impulse/wire/scene_convert.h"
#include "impulse/wire/field_convert.h"
#include "impulse/wire/query_convert.h"

namespace impulse::server {

CommandContext::CommandContext(Simulation& simulation_, const v1::ClientMessage& message_,
                               const CommandLimits& limits_)
    : simulation(simulation_), message(message_), limits(limits_) {
  // A CommandResult unless the handler answers with another message.
  result();
}

void CommandContext::fail(std::string error) {
  result().set_ok(false);
  result().set_error(std::move(error));
}

void CommandContext::succeed() { result().set_ok(true); }

namespace handlers {

namespace {

std::string unknownBody(std::uint32_t id) { return "unknown body id " + std::to_string(id); }

std::string unknownJoint(std::uint32_t id) { return "unknown joint id " + std::to_string(id); }

void created(CommandContext& context, const CreateResult& created, const char* command) {
  if (!created.ok()) return context.fail(std::string(command) + ": " + created.error);
  context.result().set_body_id(created.id.value);
  context.succeed();
}

void changeGravity(CommandContext& context, const Vec2& gravity, const char* command) {
  if (InputResult changed = context.simulation.setGravity(gravity); !changed) {
    return context.fail(std::string(command) + ": " + changed.error);
  }
  context.succeed();
}

}  // namespace

void spawnCircle(CommandContext& context, const v1::SpawnCircle& command) {
  if (!command.has_center()) return context.fail("spawn_circle: center is missing");
  const auto center = wire::vecFromWire(command.center(), "spawn_circle.center");
  if (!center.ok()) return context.fail(center.error);
  const auto radius = wire::realFromWire(command.radius(), "spawn_circle.radius");
  if (!radius.ok()) return context.fail(radius.error);
  const auto options = wire::optionsFromWire(command.options());
  if (!options.ok()) return context.fail("spawn_circle." + options.error);
  created(context, context.simulation.createCircle(*center.value, *radius.value, *options.value),
          "spawn_circle");
}

void spawnPolygon(CommandContext& context, const v1::SpawnPolygon& command) {
  const int count = command.vertices_size();
  // The count is checked before anything is copied.
  if (count < kMinPolygonVertices || count > kMaxPolygonVertices) {
    return context.fail(
        "spawn_polygon: " + std::to_string(count) + " vertices given: " +
        std::string(describe(count < kMinPolygonVertices ? ShapeError::TooFewVertices
                                                         : ShapeError::TooManyVertices)));
  }
  std::vector<Vec2> points;
  points.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i) {
    const auto point =
        wire::vecFromWire(command.vertices(i), "spawn_polygon.vertices[" + std::to_string(i) + "]");
    if (!point.ok()) return context.fail(point.error);
    points.push_back(*point.value);
  }
  const auto options = wire::optionsFromWire(command.options());
  if (!options.ok()) return context.fail("spawn_polygon." + options.error);
  created(context, context.simulation.createPolygon(points, *options.value), "spawn_polygon");
}

namespace {

// The points of a repeated Vec2 field, each checked, or the first error.
std::optional<std::vector<Vec2>> pointsOf(CommandContext& context,
                                          const google::protobuf::RepeatedPtrField<v1::Vec2>& wirePoints,
                                          const std::string& field, int maxCount) {
  if (wirePoints.size() > maxCount) {
    context.fail(field + ": " + std::to_string(wirePoints.size()) + " points given, at most " +
                 std::to_string(maxCount));
    return std::nullopt;
  }
  std::vector<Vec2> points;
  points.reserve(std::size_t(wirePoints.size()));
  for (int i = 0; i < wirePoints.size(); ++i) {
    const auto point = wire::vecFromWire(wirePoints[i], field + "[" + std::to_string(i) + "]");
    if (!point.ok()) {
      context.fail(point.error);
      return std::nullopt;
    }
    points.push_back(*point.value);
  }
  return points;
}

// A required vector field: its value, or the failure naming it.
std::optional<Vec2> requiredPoint(CommandContext& context, bool present, const v1::Vec2& value,
                                  const std::string& field) {
  if (!present) {
    context.fail(field + " is missing");
    return std::nullopt;
  }
  const auto point = wire::vecFromWire(value, field);
  if (!point.ok()) {
    context.fail(point.error);
    return std::nullopt;
  }
  return *point.value;
}

std::optional<BodyOptions> optionsOf(CommandContext& context, const v1::BodyOptions& options,
                                     const std::string& command) {
  auto decoded = wire::optionsFromWire(options);
  if (!decoded.ok()) {
    context.fail(command + "." + decoded.error);
    return std::nullopt;
  }
  return *decoded.value;
}

}  // namespace

void spawnCapsule(CommandContext& context, const v1::SpawnCapsule& command) {
  const auto center1 = requiredPoint(context, command.has_center1(), command.center1(), "spawn_capsule.center1");
  if (!center1) return;
  const auto center2 = requiredPoint(context, command.has_center2(), command.center2(), "spawn_capsule.center2");
  if (!center2) return;
  const auto radius = wire::realFromWire(command.radius(), "spawn_capsule.radius");
  if (!radius.ok()) return context.fail(radius.error);
  const auto options = optionsOf(context, command.options(), "spawn_capsule");
  if (!options) return;
  created(context, context.simulation.createCapsule(*center1, *center2, *radius.value, *options), "spawn_capsule");
}

void spawnSegment(CommandContext& context, const v1::SpawnSegment& command) {
  const auto point1 = requiredPoint(context, command.has_point1(), command.point1(), "spawn_segment.point1");
  if (!point1) return;
  const auto point2 = requiredPoint(context, command.has_point2(), command.point2(), "spawn_segment.point2");
  if (!point2) return;
  const auto options = optionsOf(context, command.options(), "spawn_segment");
  if (!options) return;
  created(context, context.simulation.createSegment(*point1, *point2, *options), "spawn_segment");
}

void spawnChain(CommandContext& context, const v1::SpawnChain& command) {
  const auto points = pointsOf(context, command.points(), "spawn_chain.points", kMaxChainPoints);
  if (!points) return;
  const auto options = optionsOf(context, command.options(), "spawn_chain");
  if (!options) return;
  created(context, context.simulation.createChain(*points, command.loop(), *options), "spawn_chain");
}

void spawnBody(CommandContext& context, const v1::SpawnBody& command) {
  if (command.parts_size() == 0 || command.parts_size() > kMaxShapesPerBody) {
    return context.fail("spawn_body: " + std::to_string(command.parts_size()) + " parts given: a body has 1 to " +
                        std::to_string(kMaxShapesPerBody));
  }
  const auto position = requiredPoint(context, command.has_position(), command.position(), "spawn_body.position");
  if (!position) return;
  const auto angle = wire::realFromWire(command.angle(), "spawn_body.angle");
  if (!angle.ok()) return context.fail(angle.error);
  const auto options = optionsOf(context, command.options(), "spawn_body");
  if (!options) return;
  std::vector<ShapeDef> parts;
  for (int i = 0; i < command.parts_size(); ++i) {
    const std::string name = "spawn_body.parts[" + std::to_string(i) + "]";
    const auto shape = wire::shapeFromWire(command.parts(i).shape());
    if (!shape.ok()) return context.fail(name + "." + shape.error);
    const auto material = wire::materialFromWire(command.parts(i).material());
    if (!material) return context.fail(name + ".material is not a material " + wire::materialRange());
    parts.push_back({*shape.value, *material, options->materialOverride, options->interaction});
  }
  BodyDef def = makeBodyDef(parts.front().shape, *position, *options);
  def.angle = *angle.value;
  def.material = parts.front().material;
  def.extraShapes.assign(parts.begin() + 1, parts.end());
  created(context, context.simulation.createBody(def), "spawn_body");
}

void setTargetTransform(CommandContext& context, const v1::SetTargetTransform& command) {
  const auto position =
      requiredPoint(context, command.has_position(), command.position(), "set_target_transform.position");
  if (!position) return;
  const auto angle = wire::realFromWire(command.angle(), "set_target_transform.angle");
  if (!angle.ok()) return context.fail(angle.error);
  const BodyId id{command.body_id()};
  if (InputResult moved = context.simulation.setTargetTransform(id, *position, *angle.value); !moved) {
    return context.fail("set_target_transform: " + moved.error);
  }
  context.succeed();
}

void setTransform(CommandContext& context, const v1::SetTransform& command) {
  const auto position = requiredPoint(context, command.has_position(), command.position(), "set_transform.position");
  if (!position) return;
  const auto angle = wire::realFromWire(command.angle(), "set_transform.angle");
  if (!angle.ok()) return context.fail(angle.error);
  const BodyId id{command.body_id()};
  if (InputResult moved = context.simulation.setTransform(id, *position, *angle.value); !moved) {
    return context.fail("set_transform: " + moved.error);
  }
  context.succeed();
}

void setMaterial(CommandContext& context, const v1::SetMaterial& command) {
  const auto material = wire::materialFromWire(command.material());
  if (!material) {
    return context.fail("set_material.material " + std::to_string(command.material()) + " is not a material " +
                        wire::materialRange());
  }
  if (InputResult set = context.simulation.setMaterial(BodyId{command.body_id()}, *material); !set) {
    return context.fail("set_material: " + set.error);
  }
  context.succeed();
}

void setBodyType(CommandContext& context, const v1::SetBodyType& command) {
  const auto type = wire::bodyTypeFromWire(command.type());
  if (!type) {
    return context.fail("set_body_type.type " + std::to_string(command.type()) +
                        " is not a body type (1 static, 2 kinematic, 3 dynamic)");
  }
  if (InputResult set = context.simulation.setBodyType(BodyId{command.body_id()}, *type); !set) {
    return context.fail("set_body_type: " + set.error);
  }
  context.succeed();
}

void loadPreset(CommandContext& context, const v1::LoadPreset& command) {
  const auto material = wire::materialFromWire(command.material());
  if (!material) {
    return context.fail("load_preset.material " + std::to_string(command.material()) +
                        " is not a material " + wire::materialRange());
  }
  if (InputResult loaded = context.simulation.loadPreset(command.preset(), *material); !loaded) {
    return context.fail(loaded.error);
  }
  context.succeed();
}

void setGravity(CommandContext& context, const v1::SetGravity& command) {
  if (!command.has_gravity()) return context.fail("set_gravity: gravity is missing");
  const auto gravity = wire::vecFromWire(command.gravity(), "set_gravity.gravity");
  if (!gravity.ok()) return context.fail(gravity.error);
  changeGravity(context, *gravity.value, "set_gravity");
}

void nudgeGravity(CommandContext& context, const v1::NudgeGravity& command) {
  if (!command.has_delta()) return context.fail("nudge_gravity: delta is missing");
  const auto delta = wire::vecFromWire(command.delta(), "nudge_gravity.delta");
  if (!delta.ok()) return context.fail(delta.error);
  changeGravity(context, context.simulation.world().gravity() + *delta.value, "nudge_gravity");
}

void resetGravity(CommandContext& context, const v1::ResetGravity&) {
  changeGravity(context, kDefaultGravity, "reset_gravity");
}

void clear(CommandContext& context, const v1::ClearWorld&) {
  context.simulation.clear();
  context.succeed();
}

void removeBody(CommandContext& context, const v1::RemoveBody& command) {
  const BodyId id{command.body_id()};
  if (!context.simulation.removeBody(id)) {
    return context.fail("remove_body: " + unknownBody(id.value));
  }
  context.succeed();
}

void applyImpulse(CommandContext& context, const v1::ApplyImpulse& command) {
  if (!command.has_impulse()) return context.fail("apply_impulse: impulse is missing");
  const auto impulse = wire::vecFromWire(command.impulse(), "apply_impulse.impulse");
  if (!impulse.ok()) return context.fail(impulse.error);
  std::optional<Vec2> point;
  if (command.has_point()) {
    const auto p = wire::vecFromWire(command.point(), "apply_impulse.point");
    if (!p.ok()) return context.fail(p.error);
    point = *p.value;
  }
  const BodyId id{command.body_id()};
  if (InputResult applied = context.simulation.applyImpulse(id, *impulse.value, point); !applied) {
    return context.fail("apply_impulse: " + applied.error);
  }
  context.succeed();
}

void setVelocity(CommandContext& context, const v1::SetVelocity& command) {
  if (!command.has_velocity()) return context.fail("set_velocity: velocity is missing");
  const auto velocity = wire::vecFromWire(command.velocity(), "set_velocity.velocity");
  if (!velocity.ok()) return context.fail(velocity.error);
  const BodyId id{command.body_id()};
  const Real angular = Real(command.angular_velocity());
  if (InputResult set = context.simulation.setVelocity(id, *velocity.value, angular); !set) {
    return context.fail("set_velocity: " + set.error);
  }
  context.succeed();
}

void setShapeFlags(CommandContext& context, const v1::SetShapeFlags& command) {
  const BodyId id{command.body_id()};
  const ShapeInteraction flags = wire::shapeFlagsFromWire(command.flags());
  if (InputResult set = context.simulation.setShapeFlags(id, flags); !set) {
    return context.fail("set_shape_flags: " + set.error);
  }
  context.succeed();
}

void subscribeEvents(CommandContext& context, const v1::SubscribeEvents& command) {
  context.result().set_ok(true);
  context.outcome.eventSubscription = command.enabled();
}

void setInterestArea(CommandContext& context, const v1::SetInterestArea& command) {
  InterestAreaRequest request = interestAreaFromWire(command);
  if (!request.error.empty()) return context.fail(request.error);
  context.result().set_ok(true);
  context.outcome.interestArea = std::move(request);
}

void setBandwidthBudget(CommandContext& context, const v1::SetBandwidthBudget& command) {
  BudgetRequest request = budgetFromWire(command);
  if (!request.error.empty()) return context.fail(request.error);
  context.result().set_ok(true);
  context.outcome.budget = std::move(request);
}

void setPaused(CommandContext& context, const v1::SetPaused& command) {
  context.simulation.setPaused(command.paused());
  context.succeed();
}

void step(CommandContext& context, const v1::Step& command) {
  if (!context.simulation.paused()) {
    return context.fail("step: the server is running; pause it first");
  }
  const std::uint32_t maxTicks = context.limits.maxStepTicks;
  if (command.ticks() < 1 || command.ticks() > maxTicks) {
    return context.fail("step: ticks must be 1.." + std::to_string(maxTicks) + ", got " +
                        std::to_string(command.ticks()));
  }
  context.succeed();
  context.outcome.ticksToStep = command.ticks();
}

void queryBody(CommandContext& context, const v1::QueryBody& command) {
  const BodyId id{command.body_id()};
  const World& world = context.simulation.world();
  const auto description = world.bodyDescription(id);
  const auto state = world.bodyState(id);
  if (!description || !state) return context.fail("query_body: " + unknownBody(id.value));
  wire::toWire(*description, *state, context.outcome.reply.mutable_body_info());
}

namespace {

v1::QueryResult& queryReply(CommandContext& context) { return *context.outcome.reply.mutable_query_result(); }

// The wire's "0 means the most" result count.
int resultLimit(std::uint32_t asked) {
  return asked == 0 ? kMaxQueryResults : int(std::min<std::uint32_t>(asked, std::uint32_t(kMaxQueryResults) + 1));
}

}  // namespace

void rayCast(CommandContext& context, const v1::RayCast& command) {
  const auto origin = requiredPoint(context, command.has_origin(), command.origin(), "ray_cast.origin");
  if (!origin) return;
  const auto translation =
      requiredPoint(context, command.has_translation(), command.translation(), "ray_cast.translation");
  if (!translation) return;
  const QueryFilter filter = wire::queryFilterFromWire(command.filter());
  const World& world = context.simulation.world();
  if (!command.all_hits()) {
    const CastResult cast = world.castRayClosest(*origin, *translation, filter);
    if (!cast.ok()) return context.fail("ray_cast: " + cast.error);
    v1::QueryResult& reply = queryReply(context);
    if (cast.hit) wire::toWire(*cast.hit, reply.add_hits());
    return;
  }
  const QueryResult<CastHit> cast = world.castRay(*origin, *translation, filter, resultLimit(command.max_hits()));
  if (!cast.ok()) return context.fail("ray_cast: " + cast.error);
  v1::QueryResult& reply = queryReply(context);
  for (const CastHit& hit : cast.results) wire::toWire(hit, reply.add_hits());
  reply.set_truncated(cast.truncated);
}

void shapeCast(CommandContext& context, const v1::ShapeCast& command) {
  const auto shape = wire::shapeFromWire(command.shape());
  if (!shape.ok()) return context.fail("shape_cast." + shape.error);
  const auto position = requiredPoint(context, command.has_position(), command.position(), "shape_cast.position");
  if (!position) return;
  const auto angle = wire::realFromWire(command.angle(), "shape_cast.angle");
  if (!angle.ok()) return context.fail(angle.error);
  const auto translation =
      requiredPoint(context, command.has_translation(), command.translation(), "shape_cast.translation");
  if (!translation) return;
  const Transform start{*position, Rot::fromAngle(*angle.value)};
  const CastResult cast = context.simulation.world().castShape(*shape.value, start, *translation,
                                                               wire::queryFilterFromWire(command.filter()));
  if (!cast.ok()) return context.fail("shape_cast: " + cast.error);
  v1::QueryResult& reply = queryReply(context);
  if (cast.hit) wire::toWire(*cast.hit, reply.add_hits());
}

void queryAabb(CommandContext& context, const v1::QueryAABB& command) {
  const auto lower = requiredPoint(context, command.has_lower(), command.lower(), "query_aabb.lower");
  if (!lower) return;
  const auto upper = requiredPoint(context, command.has_upper(), command.upper(), "query_aabb.upper");
  if (!upper) return;
  const World& world = context.simulation.world();
  const QueryResult<ShapeId> found = world.overlapAABB(AABB{*lower, *upper}, wire::queryFilterFromWire(command.filter()),
                                                       resultLimit(command.max_results()));
  if (!found.ok()) return context.fail("query_aabb: " + found.error);
  v1::QueryResult& reply = queryReply(context);
  for (const ShapeId shape : found.results) {
    reply.add_shape_ids(shape.value);
    reply.add_body_ids(world.shapeBody(shape).value_or(BodyId{}).value);
  }
  reply.set_truncated(found.truncated);
}

void ping(CommandContext& context, const v1::Ping& command) {
  // The room adds its statistics (Room::answerPing): the world knows none.
  auto* pong = context.outcome.reply.mutable_pong();
  pong->set_client_time_us(command.client_time_us());
  pong->set_server_tick(context.simulation.tick());
}

void createJoint(CommandContext& context, const v1::CreateJoint& command) {
  const auto def = wire::jointDefFromWire(command);
  if (!def.ok()) return context.fail(def.error);
  const auto created = context.simulation.createJoint(*def.value);
  if (!created.ok()) return context.fail("create_joint: " + created.error);
  context.result().set_joint_id(created.id.value);
  context.succeed();
}

void updateJoint(CommandContext& context, const v1::UpdateJoint& command) {
  const auto update = wire::jointUpdateFromWire(command);
  if (!update.ok()) return context.fail(update.error);
  const JointId id{command.joint_id()};
  if (InputResult updated = context.simulation.updateJoint(id, *update.value); !updated) {
    return context.fail("update_joint: " + updated.error);
  }
  context.succeed();
}

void removeJoint(CommandContext& context, const v1::RemoveJoint& command) {
  if (!context.simulation.removeJoint(JointId{command.joint_id()})) {
    return context.fail("remove_joint: " + unknownJoint(command.joint_id()));
  }
  context.succeed();
}

void queryJoint(CommandContext& context, const v1::QueryJoint& command) {
  const JointId id{command.joint_id()};
  const World& world = context.simulation.world();
  const auto description = world.jointDescription(id);
  const auto state = world.jointState(id);
  if (!description || !state) return context.fail("query_joint: " + unknownJoint(id.value));
  wire::toWire(*description, *state, context.outcome.reply.mutable_joint_info());
}

void setTimeScale(CommandContext& context, const v1::SetTimeScale& command) {
  if (InputResult changed = context.simulation.setTimeScale(command.scale()); !changed) {
    return context.fail("set_time_scale: " + changed.error);
  }
  context.succeed();
}

void addField(CommandContext& context, const v1::AddField& command) {
  const auto def = wire::fieldDefFromWire(command);
  if (!def.ok()) return context.fail(def.error);
  const FieldResult added = context.simulation.addField(*def.value);
  if (!added.ok()) return context.fail("add_field: " + added.error);
  context.result().set_field_id(added.id.value);
  context.succeed();
}

void removeField(CommandContext& context, const v1::RemoveField& command) {
  if (!context.simulation.removeField(FieldId{command.field_id()})) {
    return context.fail("remove_field: unknown field id " + std::to_string(command.field_id()));
  }
  context.succeed();
}

void saveScene(CommandContext& context, const v1::SaveScene&) {
  context.outcome.reply.mutable_scene_data()->set_data(wire::saveScene(context.simulation.world()));
}

void loadScene(CommandContext& context, const v1::LoadScene& command) {
  if (InputResult loaded = context.simulation.loadScene(command.data()); !loaded) {
    return context.fail("load_scene: " + loaded.error);
  }
  context.succeed();
}

void listRooms(CommandContext& context, const v1::ListRooms&) {
  // The server fills the list in (Server::deliver): a room knows only itself.
  context.outcome.reply.mutable_room_list();
}

}  // namespace handlers

}  // namespace impulse::server
