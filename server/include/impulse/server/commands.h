#pragma once
/// Applying one client command to the simulation. Every command is validated
/// completely before anything changes, and produces exactly one reply.

#include "impulse.pb.h"
#include "impulse/server/simulation.h"

namespace impulse::server {

struct CommandLimits {
  /// Step.ticks range: ten seconds of simulated time at 60 Hz, so one Step
  /// holds the server's thread for at most a second or two.
  std::uint32_t maxStepTicks = 600;
};

struct CommandOutcome {
  /// CommandResult, BodyInfo or Pong (request_id set).
  v1::ServerMessage reply;
  /// Subscribers need a snapshot now if paused (the world or its meta changed).
  bool changed = false;
  /// A Step ran: a snapshot follows the reply.
  bool stepped = false;
};

/// Applies a command (not Hello). `stats` is copied into a Pong.
CommandOutcome applyCommand(Simulation& simulation, const v1::ClientMessage& message,
                            const CommandLimits& limits, const v1::ServerStats& stats);

}  // namespace impulse::server
