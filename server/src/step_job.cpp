#include "impulse/server/step_job.h"

namespace impulse::server {

StepJob::StepJob(std::uint32_t client, v1::ServerMessage reply, std::uint32_t ticks,
                 std::size_t bytes)
    : client_(client), reply_(std::move(reply)), remaining_(ticks), bytes_(bytes) {}

bool StepJob::advance(Simulation& simulation, Clock::time_point deadline) {
  do {
    simulation.step();
    --remaining_;
  } while (remaining_ > 0 && Clock::now() < deadline);
  return remaining_ == 0;
}

v1::ServerMessage StepJob::finish(Simulation& simulation) {
  auto* result = reply_.mutable_command_result();
  result->set_tick(simulation.tick());
  result->set_state_hash(simulation.stateHash());
  return std::move(reply_);
}

}  // namespace impulse::server
