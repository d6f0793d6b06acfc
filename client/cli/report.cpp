#include "report.h"

#include <chrono>
#include <cstdio>

#include "impulse/wire/convert.h"

namespace impulse::cli {

namespace {

std::string_view materialText(int material) {
  const auto m = wire::materialFromWire(material);
  return m ? wire::materialName(*m) : std::string_view("UNKNOWN");
}

Json bodyJson(const v1::BodyDescriptor& descriptor, const v1::BodyState& state) {
  Json body = Json::object();
  body.member("id", descriptor.id());
  if (descriptor.shape().has_circle()) {
    body.member("shape", "circle").member("radius", descriptor.shape().circle().radius());
  } else {
    Json vertices = Json::array();
    for (const auto& v : descriptor.shape().polygon().vertices()) vertices.pair(v.x(), v.y());
    body.member("shape", "polygon").key("vertices").raw(vertices.close());
  }
  body.member("material", materialText(descriptor.material()))
      .member("static", descriptor.is_static())
      .member("ignore_gravity", descriptor.ignore_gravity());
  body.key("position").pair(state.position().x(), state.position().y());
  body.member("angle", state.angle());
  body.key("velocity").pair(state.velocity().x(), state.velocity().y());
  body.member("angular_velocity", state.angular_velocity()).member("awake", state.awake());
  return body;
}

std::string hex(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

Json lineReport(std::size_t line, std::string_view command) {
  Json report = Json::object();
  report.member("line", std::uint64_t(line)).member("command", command);
  return report;
}

std::string errorReport(std::size_t line, std::string_view command, std::string_view problem) {
  return lineReport(line, command)
      .member("ok", false)
      .member("error", "line " + std::to_string(line) + ": " + std::string(problem))
      .close()
      .str();
}

std::string welcomeReport(const v1::Welcome& welcome) {
  Json report = lineReport(0, "connect");
  report.member("ok", true)
      .member("client_id", welcome.client_id())
      .member("protocol_version", welcome.protocol_version())
      .member("tick", welcome.tick())
      .member("paused", welcome.paused())
      .member("tick_hz", welcome.tick_hz())
      .member("snapshot_hz", welcome.snapshot_hz());
  report.key("world_min").pair(welcome.world_min().x(), welcome.world_min().y());
  report.key("world_max").pair(welcome.world_max().x(), welcome.world_max().y());
  return report.close().str();
}

std::string replyReport(std::size_t line, std::string_view command,
                        const v1::ServerMessage& reply) {
  Json report = lineReport(line, command);
  if (reply.has_command_result()) {
    const auto& result = reply.command_result();
    report.member("ok", result.ok());
    if (!result.ok()) {
      report.member("error", "line " + std::to_string(line) + ": " + result.error());
    }
    if (result.body_id() != 0) report.member("body_id", result.body_id());
    report.member("tick", result.tick());
    if (result.state_hash() != 0) report.member("state_hash", hex(result.state_hash()));
  } else if (reply.has_body_info()) {
    const auto& info = reply.body_info();
    Json body = bodyJson(info.descriptor(), info.state());
    body.member("mass", info.mass())
        .member("inertia", info.inertia())
        .member("area", info.area())
        .member("restitution", info.restitution())
        .member("static_friction", info.static_friction())
        .member("dynamic_friction", info.dynamic_friction());
    report.member("ok", true).key("body").raw(body.close());
  } else if (reply.has_pong()) {
    const auto& pong = reply.pong();
    const auto& s = pong.stats();
    Json stats = Json::object();
    stats.member("uptime_s", double(s.uptime_us()) / 1e6)
        .member("clock_ticks", s.clock_ticks())
        .member("ticks_skipped", s.ticks_skipped())
        .member("last_tick_ms", s.last_tick_ms())
        .member("mean_tick_ms", s.mean_tick_ms())
        .member("max_tick_ms", s.max_tick_ms())
        .member("last_step_ms", s.last_step_ms())
        .member("mean_step_ms", s.mean_step_ms())
        .member("bodies", s.bodies())
        .member("awake_bodies", s.awake_bodies())
        .member("clients", s.clients())
        .member("last_snapshot_bytes", s.last_snapshot_bytes())
        .member("snapshots_skipped", s.snapshots_skipped())
        .member("bodies_left_world", s.bodies_left_world())
        .member("guard_repairs", s.guard_repairs())
        .member("commands_rate_limited", s.commands_rate_limited());
    report.member("ok", true)
        .member("server_tick", pong.server_tick())
        .key("stats")
        .raw(stats.close());
  } else {
    report.member("ok", false).member("error", "unexpected reply");
  }
  return report.close().str();
}

std::string bodiesReport(std::size_t line, const client::WorldMirror& mirror) {
  Json bodies = Json::array();
  for (const auto& [id, body] : mirror.bodies()) {
    BodyDescription description;
    description.id = body.id;
    description.shape = body.shape;
    description.material = body.material;
    description.isStatic = body.isStatic;
    description.ignoreGravity = body.ignoreGravity;
    v1::BodyDescriptor descriptor;
    wire::toWire(description, &descriptor);
    v1::BodyState state;
    wire::toWire(body.state, &state);
    bodies.raw(bodyJson(descriptor, state).close());
  }
  Json report = lineReport(line, "bodies");
  report.member("ok", true)
      .member("tick", mirror.tick())
      .member("count", std::uint64_t(mirror.bodies().size()))
      .key("bodies")
      .raw(bodies.close());
  return report.close().str();
}

std::string snapshotReport(std::size_t line, const v1::Snapshot& snapshot, std::size_t frameBytes) {
  Json report = lineReport(line, "wait-snapshot");
  report.member("ok", true)
      .member("tick", snapshot.tick())
      .member("full", snapshot.full())
      .member("added", snapshot.added_size())
      .member("removed", snapshot.removed_size())
      .member("states", snapshot.bodies_size())
      .member("bytes", std::uint64_t(frameBytes));
  report.key("gravity").pair(snapshot.gravity().x(), snapshot.gravity().y());
  if (snapshot.has_preset()) {
    report.member("preset", snapshot.preset().id()).member("title", snapshot.preset().title());
  }
  return report.close().str();
}

}  // namespace impulse::cli
