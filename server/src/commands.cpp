#include "impulse/server/commands.h"

#include <algorithm>
#include <array>

#include "impulse/server/command_handlers.h"

namespace impulse::server {

namespace {

using Case = v1::ClientMessage::CommandCase;
enum class Role { Anyone, Admin };

struct ServerCommand {
  Case wireCase;
  std::string_view wireName;
  Role role;
  void (*apply)(CommandContext& context);
};

#define IMPULSE_SERVER_COMMAND(Case, field, role, handler, ...)                               \
  ServerCommand{v1::ClientMessage::k##Case, #field, Role::role, [](CommandContext& context) { \
                  handlers::handler(context, context.message.field());                        \
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

bool changesEveryonesWorld(const v1::ClientMessage& message) {
  const ServerCommand* command = find(message.command_case());
  return command != nullptr && command->role == Role::Admin;
}

}  // namespace impulse::server
