#include "impulse/server/commands.h"

#include <algorithm>
#include <array>

#include "impulse/server/command_handlers.h"
#include "impulse/server/user_words.h"

namespace impulse::server {

namespace {

// The bodies and joints a command names, read from its fields by their
// names: a new command acting on a body or joint is checked without a line
// written for it.
template <class Command>
concept NamesABody = requires(const Command& command) { command.body_id(); } ||
                     requires(const Command& command) { command.body_a(); };
template <class Command>
concept NamesAJoint = requires(const Command& command) { command.joint_id(); };

template <class Command>
CommandTargets targetsOf(const Command& command) {
  CommandTargets targets;
  auto addBody = [&](std::uint32_t id) {
    if (id != 0) targets.bodies.push_back(id);
  };
  if constexpr (requires { command.body_id(); }) addBody(command.body_id());
  if constexpr (requires { command.body_a(); }) addBody(command.body_a());
  if constexpr (requires { command.body_b(); }) addBody(command.body_b());
  if constexpr (NamesAJoint<Command>) targets.joints.push_back(command.joint_id());
  return targets;
}

#define IMPULSE_SERVER_COMMAND(Case, field, role, handler, ...)                              \
  CommandRow{                                                                                \
      v1::ClientMessage::k##Case, #field, CommandRole::role,                                 \
      [](CommandContext& context) { handlers::handler(context, context.message.field()); }, \
      [](const v1::ClientMessage& message) {                                                 \
        using Command = IMPULSE_COMMAND_MESSAGE(field);                                      \
        static_assert(CommandRole::role != CommandRole::Owner || NamesABody<Command> ||      \
                          NamesAJoint<Command>,                                              \
                      "an Owner command must name a body or a joint");                       \
        return targetsOf(message.field());                                                   \
      }},
constexpr std::array kCommandRows{IMPULSE_COMMAND_TABLE(IMPULSE_SERVER_COMMAND)};
#undef IMPULSE_SERVER_COMMAND

// Every answer to a command names its request: this is the one place the
// id is set, whichever message answers.
void setRequestId(v1::ServerMessage& reply, std::uint64_t id) {
  using Answer = v1::ServerMessage;
  switch (reply.message_case()) {
    case Answer::kCommandResult: return reply.mutable_command_result()->set_request_id(id);
    case Answer::kPong: return reply.mutable_pong()->set_request_id(id);
    case Answer::kBodyInfo: return reply.mutable_body_info()->set_request_id(id);
    case Answer::kJointInfo: return reply.mutable_joint_info()->set_request_id(id);
    case Answer::kRoomList: return reply.mutable_room_list()->set_request_id(id);
    case Answer::kSceneData: return reply.mutable_scene_data()->set_request_id(id);
    case Answer::kQueryResult: return reply.mutable_query_result()->set_request_id(id);
    // Not answers to a command.
    case Answer::kWelcome:
    case Answer::kError:
    case Answer::kSnapshot:
    case Answer::kEvents:
    case Answer::MESSAGE_NOT_SET: return;
  }
}

}  // namespace

const CommandRow* findCommand(const v1::ClientMessage& message) {
  const auto it = std::find_if(kCommandRows.begin(), kCommandRows.end(), [&](const CommandRow& row) {
    return row.wireCase == message.command_case();
  });
  return it == kCommandRows.end() ? nullptr : &*it;
}

std::string noCommandError(const v1::ClientMessage& message) {
  return message.has_hello() ? "hello was already received"
                             : "message carries no command (unknown or missing)";
}

CommandOutcome applyCommand(Simulation& simulation, const CommandRow& row,
                            const v1::ClientMessage& message, const CommandLimits& limits) {
  CommandContext context(simulation, message, limits);
  const std::uint64_t versionBefore = simulation.version();
  row.apply(context);
  context.outcome.changed = simulation.version() != versionBefore;
  completeReply(message, simulation.tick(), context.outcome.reply);
  return std::move(context.outcome);
}

CommandOutcome applyCommand(Simulation& simulation, const v1::ClientMessage& message,
                            const CommandLimits& limits) {
  if (const CommandRow* row = findCommand(message)) return applyCommand(simulation, *row, message, limits);
  CommandOutcome refused;
  refused.reply = refusal(message, noCommandError(message), simulation.tick());
  return refused;
}

v1::ServerMessage refusal(const v1::ClientMessage& message, std::string error, std::uint64_t tick) {
  v1::ServerMessage reply;
  auto* result = reply.mutable_command_result();
  result->set_ok(false);
  result->set_error(std::move(error));
  completeReply(message, tick, reply);
  return reply;
}

void completeReply(const v1::ClientMessage& message, std::uint64_t tick, v1::ServerMessage& reply) {
  setRequestId(reply, message.request_id());
  if (!reply.has_command_result()) return;
  auto* result = reply.mutable_command_result();
  result->set_tick(tick);
  // A stamp already past: the command arrived late, or a paused Step ran over its tick.
  if (message.has_for_tick() && message.for_tick() < tick) result->set_late(true);
  if (!result->ok()) result->set_error(inUserWords(message, result->error()));
}

std::string_view commandName(const v1::ClientMessage& message) {
  if (const CommandRow* row = findCommand(message)) return row->name;
  return message.has_hello() ? "hello" : "(no command)";
}

}  // namespace impulse::server
