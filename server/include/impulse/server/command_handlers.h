#pragma once
/// The server's handler of each command of the table, declared from the
/// table itself: a row without a handler does not compile.

#include <string>
#include <type_traits>
#include <utility>

#include "impulse.pb.h"
#include "impulse/server/commands.h"
#include "impulse/server/simulation.h"
#include "impulse/wire/command_table.h"

namespace impulse::server {

/// What a handler works with: the world to change, the limits, and the reply
/// it fills in (a CommandResult unless it answers with another message).
/// What every reply carries (request id, tick) is added by completeReply.
struct CommandContext {
  CommandContext(Simulation& simulation, const v1::ClientMessage& message,
                 const CommandLimits& limits);

  Simulation& simulation;
  const v1::ClientMessage& message;
  const CommandLimits& limits;
  CommandOutcome outcome;

  void fail(std::string error);
  /// The command was accepted (what it changed, the Simulation recorded).
  void succeed();
  /// The reply as a CommandResult.
  v1::CommandResult& result() { return *outcome.reply.mutable_command_result(); }
};

/// The message type of a ClientMessage field (`clear` is a ClearWorld).
#define IMPULSE_COMMAND_MESSAGE(field) \
  std::remove_cvref_t<decltype(std::declval<const v1::ClientMessage&>().field())>

#define IMPULSE_DECLARE_HANDLER(Case, field, role, handler, ...) \
  void handler(CommandContext& context, const IMPULSE_COMMAND_MESSAGE(field) & command);
namespace handlers {
IMPULSE_COMMAND_TABLE(IMPULSE_DECLARE_HANDLER)
}  // namespace handlers
#undef IMPULSE_DECLARE_HANDLER

}  // namespace impulse::server
