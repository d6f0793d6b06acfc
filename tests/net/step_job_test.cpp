// A Step runs in pieces bounded by a deadline, at least one tick each, and
// its reply carries the tick and state hash after the last tick.
#include "impulse/server/step_job.h"

#include <gtest/gtest.h>

namespace impulse::server {
namespace {

SimulationSettings pausedSandbox() {
  SimulationSettings settings;
  settings.paused = true;
  return settings;
}

v1::ServerMessage acceptedStep() {
  v1::ServerMessage reply;
  reply.mutable_command_result()->set_ok(true);
  return reply;
}

TEST(StepJob, PastItsDeadlineAPieceIsStillOneTick) {
  Simulation sim(pausedSandbox());
  StepJob job(1, acceptedStep(), 10, 0);
  const auto past = Clock::now() - std::chrono::seconds(1);
  EXPECT_FALSE(job.advance(sim, past));
  EXPECT_EQ(sim.tick(), 1u);
  EXPECT_FALSE(job.advance(sim, past));
  EXPECT_EQ(sim.tick(), 2u);
}

TEST(StepJob, RunsExactlyItsTicksThenRepliesWithTickAndHash) {
  Simulation sim(pausedSandbox());
  StepJob job(1, acceptedStep(), 10, 0);
  EXPECT_FALSE(job.advance(sim, Clock::now() - std::chrono::seconds(1)));
  EXPECT_TRUE(job.advance(sim, Clock::time_point::max()));
  EXPECT_EQ(sim.tick(), 10u);
  const auto reply = job.finish(sim);
  EXPECT_TRUE(reply.command_result().ok());
  EXPECT_EQ(reply.command_result().tick(), 10u);
  EXPECT_EQ(reply.command_result().state_hash(), sim.stateHash());
}

}  // namespace
}  // namespace impulse::server
