#pragma once
/// A Step command in progress. A Step of hundreds of ticks on a large world
/// takes seconds; run in one piece it would hold the server's only thread,
/// so no socket, timer or other client would be served meanwhile. A StepJob
/// runs it in pieces bounded by a deadline, one piece per server tick.

#include <cstddef>
#include <cstdint>

#include "impulse.pb.h"
#include "impulse/server/simulation.h"
#include "impulse/server/tick_schedule.h"

namespace impulse::server {

class StepJob {
 public:
  /// `reply` is the Step's accepted CommandResult, completed when done.
  StepJob(std::uint32_t client, v1::ServerMessage reply, std::uint32_t ticks, std::size_t bytes);

  /// Runs ticks until done or past `deadline`, at least one. True when done.
  bool advance(Simulation& simulation, Clock::time_point deadline);
  /// The reply, with the tick and state hash after the last tick.
  v1::ServerMessage finish(Simulation& simulation);

  std::uint32_t client() const { return client_; }
  /// The Step's frame size, given back to the client's read budget when done.
  std::size_t bytes() const { return bytes_; }

 private:
  std::uint32_t client_;
  v1::ServerMessage reply_;
  std::uint32_t remaining_;
  std::size_t bytes_;
};

}  // namespace impulse::server
