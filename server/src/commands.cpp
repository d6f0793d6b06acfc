#include "impulse/server/commands.h"

#include <algorithm>
#include <array>

#include "impulse/server/command_handlers.h"

namespace impulse::server {

namespace {

using Case = v1::ClientMessage::CommandCase;

struct ServerCommand {
  Case wireCase;
  std::string_view wireName;
  CommandRole role;
  void (*apply)(CommandContext& context);
  CommandTargets (*targets)(const v1::ClientMessage& message);
};

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
  ServerCommand{                                                                             \
      v1::ClientMessage::k##Case, #field, CommandRole::role,                                 \
      [](CommandContext& context) { handlers::handler(context, context.message.field()); }, \
      [](const v1::ClientMessage& message) {                                                 \
        using Command = IMPULSE_COMMAND_MESSAGE(field);                                      \
        static_assert(CommandRole::role != CommandRole::Owner || NamesABody<Command> ||      \
                          NamesAJoint<Command>,                                              \
                      "an Owner command must name a body or a joint");                       \
        return targetsOf(message.field());                                                   \
      }},
constexpr std::array kServerCommands{IMPULSE_COMMAND_TABLE(IMPULSE_SERVER_COMMAND)};
#undef IMPULSE_SERVER_COMMAND

const ServerCommand* find(Case wireCase) {
  const auto it = std::find_if(kServerCommands.begin(), kServerCommands.end(),
                               [&](const ServerCommand& row) { return row.wireCase == wireCase; });
  return it == kServerCommands.end() ? nullptr : &*it;
}

}  // namespace

CommandOutcome applyCommand(Simulation& simulation, const v1::ClientMessage& message,
                            const CommandLimits& limits) {
  CommandContext context(simulation, message, limits);
  if (const ServerCommand* command = find(message.command_case())) {
    command->apply(context);
  } else if (message.has_hello()) {
    context.fail("hello was already received");
  } else {
    context.fail("message carries no command (unknown or missing)");
  }
  if (context.outcome.reply.has_command_result()) {
    context.outcome.reply.mutable_command_result()->set_tick(simulation.tick());
  }
  return std::move(context.outcome);
}

std::string_view commandName(const v1::ClientMessage& message) {
  if (const ServerCommand* command = find(message.command_case())) return command->wireName;
  return message.has_hello() ? "hello" : "(no command)";
}

CommandRole commandRole(const v1::ClientMessage& message) {
  // A message without a known command is refused by applyCommand anyway.
  const ServerCommand* command = find(message.command_case());
  return command != nullptr ? command->role : CommandRole::Anyone;
}

CommandTargets commandTargets(const v1::ClientMessage& message) {
  const ServerCommand* command = find(message.command_case());
  return command != nullptr ? command->targets(message) : CommandTargets{};
}

}  // namespace impulse::server
