#include "report.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "impulse/wire/convert.h"
#include "impulse/wire/parse_number.h"

namespace impulse::cli {

namespace {

std::string_view materialText(int material) {
  const auto m = wire::materialFromWire(material);
  return m ? wire::materialName(*m) : std::string_view("UNKNOWN");
}

Json pair(const v1::Vec2& v) { return Json::array({number(v.x()), number(v.y())}); }

Json bodyJson(const v1::BodyDescriptor& descriptor, const v1::BodyState& state) {
  Json body = {{"id", descriptor.id()}};
  if (descriptor.shape().has_circle()) {
    body["shape"] = "circle";
    body["radius"] = number(descriptor.shape().circle().radius());
  } else {
    Json vertices = Json::array();
    for (const auto& v : descriptor.shape().polygon().vertices()) vertices.push_back(pair(v));
    body["shape"] = "polygon";
    body["vertices"] = std::move(vertices);
  }
  body["material"] = materialText(descriptor.material());
  body["static"] = descriptor.is_static();
  body["ignore_gravity"] = descriptor.ignore_gravity();
  body["position"] = pair(state.position());
  body["angle"] = number(state.angle());
  body["velocity"] = pair(state.velocity());
  body["angular_velocity"] = number(state.angular_velocity());
  body["awake"] = state.awake();
  return body;
}

Json jointJson(const v1::JointInfo& info) {
  const auto& d = info.descriptor();
  Json joint = {{"id", d.id()}, {"body_a", d.body_a()}, {"body_b", d.body_b()}};
  const auto description = wire::jointFromWire(d);
  joint["kind"] = description ? wire::jointKindName(description->settings) : "unknown";
  joint["local_anchor_a"] = pair(d.local_anchor_a());
  joint["local_anchor_b"] = pair(d.local_anchor_b());
  joint["collide_connected"] = d.collide_connected();
  joint["reaction_force"] = pair(info.reaction_force());
  joint["reaction_torque"] = number(info.reaction_torque());
  joint["length"] = number(info.length());
  joint["angle"] = number(info.angle());
  joint["translation"] = number(info.translation());
  return joint;
}

std::string hex(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

Json number(double value) {
  if (!std::isfinite(value)) return nullptr;
  // Integral values below 2^53 are exact as integers.
  if (std::trunc(value) == value && std::abs(value) < 9007199254740992.0) {
    return std::int64_t(value);
  }
  const float single = float(value);
  if (double(single) != value) return value;
  // The float's shortest decimal, read back as the double nearest to it: a
  // reader gets the same float, a person reads what the engine meant.
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, single).ptr;
  return wire::parseNumber<double>(std::string_view(text, std::size_t(end - text))).value_or(value);
}

void printReport(const std::string& json) {
  std::fputs(json.c_str(), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);
}

Json lineReport(std::size_t line, std::string_view command) {
  return {{"line", line}, {"command", command}};
}

std::string errorReport(std::size_t line, std::string_view command, std::string_view problem) {
  Json report = lineReport(line, command);
  report["ok"] = false;
  report["error"] = "line " + std::to_string(line) + ": " + std::string(problem);
  return report.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string welcomeReport(const v1::Welcome& welcome) {
  Json report = lineReport(0, "connect");
  report["ok"] = true;
  report["client_id"] = welcome.client_id();
  report["protocol_version"] = welcome.protocol_version();
  report["tick"] = welcome.tick();
  report["paused"] = welcome.paused();
  report["tick_hz"] = number(welcome.tick_hz());
  report["snapshot_hz"] = number(welcome.snapshot_hz());
  report["world_min"] = pair(welcome.world_min());
  report["world_max"] = pair(welcome.world_max());
  // Every position on the wire is from (0, 0); the origin says where the
  // room computes (docs/networked-play.md, "Far from (0, 0)").
  report["world_origin"] = pair(welcome.world_origin());
  return report.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string sceneSavedReport(std::size_t line, std::string_view command, const std::string& file,
                             std::size_t bytes, const std::string& error) {
  Json report = lineReport(line, command);
  report["ok"] = error.empty();
  report["file"] = file;
  report["bytes"] = bytes;
  if (!error.empty()) report["error"] = "line " + std::to_string(line) + ": " + error;
  return report.dump(-1, ' ', false, Json::error_handler_t::replace);
}

namespace {

// A query's answer: hits (ray and shape casts) or shapes (overlap).
Json queryJson(const v1::QueryResult& result, bool listsShapes) {
  Json out = Json::object();
  if (!listsShapes) {
    Json hits = Json::array();
    for (const auto& hit : result.hits()) {
      hits.push_back({{"shape", hit.shape_id()},
                      {"body", hit.body_id()},
                      {"point", {number(hit.point().x()), number(hit.point().y())}},
                      {"normal", {number(hit.normal().x()), number(hit.normal().y())}},
                      {"fraction", number(hit.fraction())}});
    }
    out["hits"] = std::move(hits);
  }
  if (listsShapes) {
    Json shapes = Json::array();
    for (int i = 0; i < result.shape_ids_size(); ++i) {
      shapes.push_back({{"shape", result.shape_ids(i)}, {"body", result.body_ids(i)}});
    }
    out["shapes"] = std::move(shapes);
  }
  if (result.truncated()) out["truncated"] = true;
  return out;
}

}  // namespace

std::string replyReport(std::size_t line, std::string_view command,
                        const v1::ServerMessage& reply) {
  Json report = lineReport(line, command);
  if (reply.has_command_result()) {
    const auto& result = reply.command_result();
    report["ok"] = result.ok();
    if (!result.ok()) {
      report["error"] = "line " + std::to_string(line) + ": " + result.error();
    }
    if (result.body_id() != 0) report["body_id"] = result.body_id();
    if (result.joint_id() != 0) report["joint_id"] = result.joint_id();
    if (result.field_id() != 0) report["field_id"] = result.field_id();
    report["tick"] = result.tick();
    if (result.state_hash() != 0) report["state_hash"] = hex(result.state_hash());
  } else if (reply.has_body_info()) {
    const auto& info = reply.body_info();
    Json body = bodyJson(info.descriptor(), info.state());
    body["mass"] = number(info.mass());
    body["inertia"] = number(info.inertia());
    body["area"] = number(info.area());
    body["restitution"] = number(info.restitution());
    body["static_friction"] = number(info.static_friction());
    body["dynamic_friction"] = number(info.dynamic_friction());
    body["density"] = number(info.density());
    body["linear_damping"] = number(info.linear_damping());
    body["angular_damping"] = number(info.angular_damping());
    body["gravity_scale"] = number(info.gravity_scale());
    body["rolling_resistance"] = number(info.rolling_resistance());
    report["ok"] = true;
    report["body"] = std::move(body);
  } else if (reply.has_query_result()) {
    report["ok"] = true;
    report.update(queryJson(reply.query_result(), command == "overlap"));
  } else if (reply.has_joint_info()) {
    report["ok"] = true;
    report["joint"] = jointJson(reply.joint_info());
  } else if (reply.has_room_list()) {
    Json rooms = Json::array();
    for (const auto& room : reply.room_list().rooms()) {
      rooms.push_back({{"name", room.name()},
                       {"clients", room.clients()},
                       {"bodies", room.bodies()},
                       {"tick", room.tick()},
                       {"world_min", pair(room.world_min())},
                       {"world_max", pair(room.world_max())},
                       {"world_origin", pair(room.world_origin())}});
    }
    report["ok"] = true;
    report["rooms"] = std::move(rooms);
  } else if (reply.has_pong()) {
    const auto& pong = reply.pong();
    const auto& s = pong.stats();
    // Timings to the microsecond: more digits are noise.
    auto ms = [](double value) { return number(std::round(value * 1000) / 1000); };
    report["ok"] = true;
    report["server_tick"] = pong.server_tick();
    report["stats"] = {{"uptime_s", number(std::round(double(s.uptime_us()) / 1e3) / 1e3)},
                       {"clock_ticks", s.clock_ticks()},
                       {"ticks_skipped", s.ticks_skipped()},
                       {"last_tick_ms", ms(s.last_tick_ms())},
                       {"mean_tick_ms", ms(s.mean_tick_ms())},
                       {"max_tick_ms", ms(s.max_tick_ms())},
                       {"last_step_ms", ms(s.last_step_ms())},
                       {"mean_step_ms", ms(s.mean_step_ms())},
                       {"bodies", s.bodies()},
                       {"awake_bodies", s.awake_bodies()},
                       {"clients", s.clients()},
                       {"last_snapshot_bytes", s.last_snapshot_bytes()},
                       {"snapshots_skipped", s.snapshots_skipped()},
                       {"bodies_left_world", s.bodies_left_world()},
                       {"guard_repairs", s.guard_repairs()},
                       {"commands_rate_limited", s.commands_rate_limited()},
                       {"scaled_steps_dropped", s.scaled_steps_dropped()}};
  } else {
    report["ok"] = false;
    report["error"] = "unexpected reply";
  }
  return report.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string bodiesReport(std::size_t line, const client::WorldMirror& mirror) {
  Json bodies = Json::array();
  for (const auto& [id, body] : mirror.bodies()) {
    BodyDescription description;
    description.id = body.id;
    description.shape = body.shape;
    description.material = body.material;
    description.properties.isStatic = body.isStatic;
    description.properties.ignoreGravity = body.ignoreGravity;
    v1::BodyDescriptor descriptor;
    wire::toWire(description, &descriptor);
    v1::BodyState state;
    wire::toWire(body.state, &state);
    // Reported from (0, 0), as the wire gives positions.
    const Vec2d position = mirror.toGlobal(body.state.position);
    state.mutable_position()->set_x(position.x());
    state.mutable_position()->set_y(position.y());
    bodies.push_back(bodyJson(descriptor, state));
  }
  Json report = lineReport(line, "bodies");
  report["ok"] = true;
  report["tick"] = mirror.tick();
  report["count"] = mirror.bodies().size();
  report["bodies"] = std::move(bodies);
  return report.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string snapshotReport(std::size_t line, const v1::Snapshot& snapshot, std::size_t frameBytes) {
  Json report = lineReport(line, "wait-snapshot");
  report["ok"] = true;
  report["tick"] = snapshot.tick();
  report["full"] = snapshot.full();
  report["added"] = snapshot.added_size();
  report["removed"] = snapshot.removed_size();
  report["states"] = snapshot.bodies_size();
  report["bytes"] = frameBytes;
  report["gravity"] = pair(snapshot.gravity());
  if (snapshot.has_preset()) {
    report["preset"] = snapshot.preset().id();
    report["title"] = snapshot.preset().title();
  }
  return report.dump(-1, ' ', false, Json::error_handler_t::replace);
}

namespace {

Json pointJson(const v1::Vec2& v) { return {number(v.x()), number(v.y())}; }

Json contactJson(const v1::ContactEvent& e) {
  return {{"body_a", e.body_a()}, {"body_b", e.body_b()}, {"shape_a", e.shape_a()}, {"shape_b", e.shape_b()}};
}

Json hitJson(const v1::HitEvent& e) {
  return {{"body_a", e.body_a()},        {"body_b", e.body_b()},           {"shape_a", e.shape_a()},
          {"shape_b", e.shape_b()},      {"point", pointJson(e.point())}, {"normal", pointJson(e.normal())},
          {"speed", number(e.approach_speed())}};
}

Json sensorJson(const v1::SensorEvent& e) {
  return {{"sensor_body", e.sensor_body()},
          {"visitor_body", e.visitor_body()},
          {"sensor_shape", e.sensor_shape()},
          {"visitor_shape", e.visitor_shape()}};
}

template <class List, class ToJson>
void addList(Json& out, const char* name, const List& list, ToJson toJson) {
  if (list.empty()) return;
  Json items = Json::array();
  for (const auto& item : list) items.push_back(toJson(item));
  out[name] = std::move(items);
}

}  // namespace

std::string eventsReport(const v1::Events& events) {
  Json body = {{"tick", events.tick()}, {"sequence", events.sequence()}};
  addList(body, "contact_begins", events.contact_begins(), contactJson);
  addList(body, "contact_ends", events.contact_ends(), contactJson);
  addList(body, "hits", events.hits(), hitJson);
  addList(body, "sensor_begins", events.sensor_begins(), sensorJson);
  addList(body, "sensor_ends", events.sensor_ends(), sensorJson);
  if (events.truncated()) body["truncated"] = true;
  return Json{{"events", std::move(body)}}.dump();
}

}  // namespace impulse::cli
