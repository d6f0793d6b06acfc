#pragma once
/// Applying one client command to a simulation, through the command table
/// (impulse/wire/command_table.h). Every command is validated completely
/// before anything changes, and produces exactly one reply.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impulse.pb.h"
#include "impulse/server/interest_area.h"
#include "impulse/server/simulation.h"

namespace impulse::server {

struct CommandLimits {
  /// Step.ticks range: ten seconds of simulated time at 60 Hz. A Step runs
  /// in bounded pieces across ticks (StepJob), so its length costs latency
  /// to its own client only.
  std::uint32_t maxStepTicks = 600;
};

struct CommandOutcome {
  /// CommandResult, BodyInfo, Pong, ... complete (completeReply).
  v1::ServerMessage reply;
  /// Subscribers need a snapshot now if paused: the simulation's version
  /// moved (the world or its meta changed).
  bool changed = false;
  /// An accepted Step: the ticks still to run before the reply may be sent.
  std::uint32_t ticksToStep = 0;
  /// SubscribeEvents: the client's event stream starts (true) or stops.
  std::optional<bool> eventSubscription;
  /// SetInterestArea accepted: the client's area (none: the whole room).
  std::optional<InterestAreaRequest> interestArea;
  /// SetBandwidthBudget accepted: the client's budget (none: no budget).
  std::optional<BudgetRequest> budget;
};

/// Who may run a command: the command table's role column.
enum class CommandRole {
  Anyone,  ///< reads, or makes something new
  Owner,   ///< acts on the bodies or joints it names: a player's own only
  Admin,   ///< changes everyone's world
};

/// The bodies and joints a command names (body 0, the world, left out).
struct CommandTargets {
  std::vector<std::uint32_t> bodies;
  std::vector<std::uint32_t> joints;
};

struct CommandContext;

/// A command's row of the command table as the server reads it. A message
/// is resolved to its row once (findCommand); access checks, the handler
/// and the ownership record all read that row.
struct CommandRow {
  v1::ClientMessage::CommandCase wireCase;
  /// The wire name ("spawn_circle", "clear", ...).
  std::string_view name;
  CommandRole role;
  void (*apply)(CommandContext& context);
  CommandTargets (*targets)(const v1::ClientMessage& message);
};

/// The row of the message's command; null for a message without one (or
/// with a command this build does not know, or a second Hello).
const CommandRow* findCommand(const v1::ClientMessage& message);

/// Why a message without a row is refused: "hello was already received",
/// or that it carries no command.
std::string noCommandError(const v1::ClientMessage& message);

/// Applies a command through its row. A Step is validated only: its ticks
/// are run by a StepJob, which adds the tick and state hash they end on.
CommandOutcome applyCommand(Simulation& simulation, const CommandRow& row,
                            const v1::ClientMessage& message, const CommandLimits& limits);

/// findCommand and the above; a message without a row gets the refusal.
CommandOutcome applyCommand(Simulation& simulation, const v1::ClientMessage& message,
                            const CommandLimits& limits);

/// A refusal of `message` before it reached the world, complete.
v1::ServerMessage refusal(const v1::ClientMessage& message, std::string error, std::uint64_t tick);

/// The one place every reply is completed, whatever message answers: the
/// request id, and for a CommandResult the tick it answers at, whether the
/// command's stamp (for_tick) was already past, and a refusal's error in
/// the words its sender typed (user_words.h).
void completeReply(const v1::ClientMessage& message, std::uint64_t tick, v1::ServerMessage& reply);

/// The wire name of a command ("spawn_circle", "clear", ...), "hello", or
/// "(no command)".
std::string_view commandName(const v1::ClientMessage& message);

}  // namespace impulse::server
