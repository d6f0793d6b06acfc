#include "impulse/server/commands.h"

#include <cmath>
#include <string>
#include <vector>

#include "impulse/wire/convert.h"

namespace impulse::server {

namespace {

using wire::Decoded;

std::string unknownBody(std::uint32_t id) { return "unknown body id " + std::to_string(id); }

class Applier {
 public:
  Applier(Simulation& simulation, const v1::ClientMessage& message, const CommandLimits& limits)
      : sim_(simulation), world_(simulation.world()), message_(message), limits_(limits) {
    result_ = outcome_.reply.mutable_command_result();
    result_->set_request_id(message.request_id());
  }

  CommandOutcome apply(const v1::ServerStats& stats) {
    using C = v1::ClientMessage;
    switch (message_.command_case()) {
      case C::kSpawnCircle:
        spawnCircle(message_.spawn_circle());
        break;
      case C::kSpawnPolygon:
        spawnPolygon(message_.spawn_polygon());
        break;
      case C::kLoadPreset:
        loadPreset(message_.load_preset());
        break;
      case C::kSetGravity:
        setGravity(message_.set_gravity());
        break;
      case C::kNudgeGravity:
        nudgeGravity(message_.nudge_gravity());
        break;
      case C::kResetGravity:
        changeGravity(kDefaultGravity, "reset_gravity");
        break;
      case C::kClear:
        clear();
        break;
      case C::kRemoveBody:
        removeBody(message_.remove_body());
        break;
      case C::kApplyImpulse:
        applyImpulse(message_.apply_impulse());
        break;
      case C::kSetPaused:
        setPaused(message_.set_paused());
        break;
      case C::kStep:
        step(message_.step());
        break;
      case C::kQueryBody:
        queryBody(message_.query_body());
        break;
      case C::kPing:
        ping(message_.ping(), stats);
        break;
      case C::kHello:
        fail("hello was already received");
        break;
      case C::COMMAND_NOT_SET:
        fail("message carries no command (unknown or missing)");
        break;
    }
    if (outcome_.reply.has_command_result()) result_->set_tick(sim_.tick());
    return std::move(outcome_);
  }

 private:
  void fail(std::string error) {
    result_->set_ok(false);
    result_->set_error(std::move(error));
  }
  void succeed() {
    result_->set_ok(true);
    outcome_.changed = true;
  }

  void created(const CreateResult& created, const char* command) {
    if (!created.ok()) return fail(std::string(command) + ": " + created.error);
    sim_.snapshots().bodyAdded(created.id);
    result_->set_body_id(created.id.value);
    succeed();
  }

  void spawnCircle(const v1::SpawnCircle& command) {
    if (!command.has_center()) return fail("spawn_circle: center is missing");
    const auto center = wire::vecFromWire(command.center(), "spawn_circle.center");
    if (!center.ok()) return fail(center.error);
    const auto radius = wire::realFromWire(command.radius(), "spawn_circle.radius");
    if (!radius.ok()) return fail(radius.error);
    const auto options = wire::optionsFromWire(command.options());
    if (!options.ok()) return fail("spawn_circle." + options.error);
    created(world_.createCircle(*center.value, *radius.value, *options.value), "spawn_circle");
  }

  void spawnPolygon(const v1::SpawnPolygon& command) {
    const int count = command.vertices_size();
    // The count is checked before anything is copied.
    if (count < kMinPolygonVertices || count > kMaxPolygonVertices) {
      return fail("spawn_polygon: " + std::to_string(count) + " vertices given: " +
                  std::string(describe(count < kMinPolygonVertices ? ShapeError::TooFewVertices
                                                                   : ShapeError::TooManyVertices)));
    }
    std::vector<Vec2> points;
    points.reserve(std::size_t(count));
    for (int i = 0; i < count; ++i) {
      const auto point = wire::vecFromWire(command.vertices(i),
                                           "spawn_polygon.vertices[" + std::to_string(i) + "]");
      if (!point.ok()) return fail(point.error);
      points.push_back(*point.value);
    }
    const auto options = wire::optionsFromWire(command.options());
    if (!options.ok()) return fail("spawn_polygon." + options.error);
    created(world_.createPolygon(points, *options.value), "spawn_polygon");
  }

  void loadPreset(const v1::LoadPreset& command) {
    const auto material = wire::materialFromWire(command.material());
    if (!material) {
      return fail("load_preset.material " + std::to_string(command.material()) +
                  " is not a material (0-5)");
    }
    if (command.preset() < 0 || command.preset() >= kPresetCount) {
      return fail("load_preset: preset " + std::to_string(command.preset()) +
                  " does not exist (0-" + std::to_string(kPresetCount - 1) + ")");
    }
    if (!sim_.loadPreset(command.preset(), *material)) {
      return fail("load_preset: preset " + std::to_string(command.preset()) + " failed to load");
    }
    succeed();
  }

  void changeGravity(const Vec2& gravity, const char* command) {
    if (InputResult changed = world_.setGravity(gravity); !changed) {
      return fail(std::string(command) + ": " + changed.error);
    }
    sim_.snapshots().worldChanged();
    succeed();
  }

  void setGravity(const v1::SetGravity& command) {
    if (!command.has_gravity()) return fail("set_gravity: gravity is missing");
    const auto gravity = wire::vecFromWire(command.gravity(), "set_gravity.gravity");
    if (!gravity.ok()) return fail(gravity.error);
    changeGravity(*gravity.value, "set_gravity");
  }

  void nudgeGravity(const v1::NudgeGravity& command) {
    if (!command.has_delta()) return fail("nudge_gravity: delta is missing");
    const auto delta = wire::vecFromWire(command.delta(), "nudge_gravity.delta");
    if (!delta.ok()) return fail(delta.error);
    changeGravity(world_.gravity() + *delta.value, "nudge_gravity");
  }

  void clear() {
    sim_.clear();
    succeed();
  }

  void removeBody(const v1::RemoveBody& command) {
    const BodyId id{command.body_id()};
    if (!world_.destroyBody(id)) return fail("remove_body: " + unknownBody(id.value));
    sim_.snapshots().bodyRemoved(id);
    succeed();
  }

  void applyImpulse(const v1::ApplyImpulse& command) {
    const BodyId id{command.body_id()};
    if (!command.has_impulse()) return fail("apply_impulse: impulse is missing");
    const auto impulse = wire::vecFromWire(command.impulse(), "apply_impulse.impulse");
    if (!impulse.ok()) return fail(impulse.error);
    std::optional<Vec2> point;
    if (command.has_point()) {
      const auto p = wire::vecFromWire(command.point(), "apply_impulse.point");
      if (!p.ok()) return fail(p.error);
      point = *p.value;
    }
    if (InputResult applied = world_.applyImpulse(id, *impulse.value, point); !applied) {
      return fail("apply_impulse: " + applied.error);
    }
    sim_.snapshots().bodyChanged(id);
    succeed();
  }

  void setPaused(const v1::SetPaused& command) {
    sim_.setPaused(command.paused());
    succeed();
  }

  void step(const v1::Step& command) {
    if (!sim_.paused()) return fail("step: the server is running; pause it first");
    if (command.ticks() < 1 || command.ticks() > limits_.maxStepTicks) {
      return fail("step: ticks must be 1.." + std::to_string(limits_.maxStepTicks) + ", got " +
                  std::to_string(command.ticks()));
    }
    for (std::uint32_t i = 0; i < command.ticks(); ++i) sim_.step();
    result_->set_state_hash(world_.stateHash());
    succeed();
    outcome_.stepped = true;
  }

  void queryBody(const v1::QueryBody& command) {
    const BodyId id{command.body_id()};
    const auto description = world_.bodyDescription(id);
    const auto state = world_.bodyState(id);
    if (!description || !state) return fail("query_body: " + unknownBody(id.value));
    v1::ServerMessage reply;
    auto* info = reply.mutable_body_info();
    info->set_request_id(message_.request_id());
    wire::toWire(*description, *state, info);
    outcome_.reply = std::move(reply);
  }

  void ping(const v1::Ping& command, const v1::ServerStats& stats) {
    v1::ServerMessage reply;
    auto* pong = reply.mutable_pong();
    pong->set_client_time_us(command.client_time_us());
    pong->set_server_tick(sim_.tick());
    pong->set_request_id(message_.request_id());
    *pong->mutable_stats() = stats;
    outcome_.reply = std::move(reply);
  }

  Simulation& sim_;
  World& world_;
  const v1::ClientMessage& message_;
  const CommandLimits& limits_;
  CommandOutcome outcome_;
  v1::CommandResult* result_ = nullptr;
};

}  // namespace

CommandOutcome applyCommand(Simulation& simulation, const v1::ClientMessage& message,
                            const CommandLimits& limits, const v1::ServerStats& stats) {
  return Applier(simulation, message, limits).apply(stats);
}

}  // namespace impulse::server
