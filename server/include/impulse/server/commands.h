#pragma once
/// Applying one client command to a simulation, through the command table
/// (impulse/wire/command_table.h). Every command is validated completely
/// before anything changes, and produces exactly one reply.

#include <cstdint>
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
  /// CommandResult, BodyInfo or Pong (request_id set).
  v1::ServerMessage reply;
  /// Subscribers need a snapshot now if paused (the world or its meta changed).
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

/// Applies a command (not Hello). A Step is validated only: its ticks are
/// run by a StepJob, which completes the reply.
CommandOutcome applyCommand(Simulation& simulation, const v1::ClientMessage& message,
                            const CommandLimits& limits);

/// The wire name of a command ("spawn_circle", "clear", ...).
std::string_view commandName(const v1::ClientMessage& message);

/// Who may run a command: the command table's role column.
enum class CommandRole {
  Anyone,  ///< reads, or makes something new
  Owner,   ///< acts on the bodies or joints it names: a player's own only
  Admin,   ///< changes everyone's world
};
CommandRole commandRole(const v1::ClientMessage& message);

/// The bodies and joints a command names (body 0, the world, left out).
struct CommandTargets {
  std::vector<std::uint32_t> bodies;
  std::vector<std::uint32_t> joints;
};
CommandTargets commandTargets(const v1::ClientMessage& message);

}  // namespace impulse::server
