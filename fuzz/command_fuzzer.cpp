// libFuzzer target: the command validator. The input is a stream of up to 16
// delimited ClientMessages (the wire format), applied in order to a paused
// sandbox as the server applies them, players' refusals included. Checked
// after every command: exactly one reply that names the request; a refusal
// says why and leaves the world bit-identical; every body stays finite and
// within the speed limits.
#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_check.h"
#include "quiet_protobuf.h"
#include "world_invariants.h"
#include "impulse.pb.h"
#include "impulse/server/access.h"
#include "impulse/server/commands.h"
#include "impulse/server/simulation.h"
#include "impulse/server/step_job.h"
#include "impulse/wire/framing.h"

namespace {

using impulse::server::Simulation;

constexpr int kMaxCommands = 16;
constexpr std::uint32_t kPlayer = 7;

// Fast enough for millions of runs: short steps, a small world.
Simulation makeSimulation() {
  impulse::server::SimulationSettings settings;
  settings.paused = true;
  settings.maxBodies = 64;
  return Simulation(settings);
}

std::uint64_t replyRequestId(const impulse::v1::ServerMessage& reply) {
  if (reply.has_command_result()) return reply.command_result().request_id();
  if (reply.has_body_info()) return reply.body_info().request_id();
  if (reply.has_joint_info()) return reply.joint_info().request_id();
  if (reply.has_room_list()) return reply.room_list().request_id();
  if (reply.has_scene_data()) return reply.scene_data().request_id();
  if (reply.has_query_result()) return reply.query_result().request_id();
  FUZZ_CHECK(reply.has_pong());
  return reply.pong().request_id();
}

// A Step's ticks, all at once (the server spreads them over its ticks).
impulse::v1::ServerMessage runStep(Simulation& simulation,
                                   impulse::server::CommandOutcome&& outcome) {
  impulse::server::StepJob job(0, std::move(outcome.reply), outcome.ticksToStep, 0);
  while (!job.advance(simulation, impulse::server::Clock::time_point::max())) {
  }
  return job.finish(simulation);
}

void applyOne(Simulation& simulation, impulse::server::Ownership& ownership,
              const impulse::v1::ClientMessage& message, bool asPlayer) {
  const impulse::server::CommandLimits limits{.maxStepTicks = 4};
  const impulse::server::CommandRow* row = impulse::server::findCommand(message);
  if (asPlayer && row != nullptr && !ownership.playerRefusal(*row, message, kPlayer).empty()) return;
  const std::uint64_t hashBefore = simulation.world().stateHash();
  const int bodiesBefore = simulation.world().bodyCount();
  const impulse::Vec2 gravityBefore = simulation.world().gravity();

  auto outcome = row != nullptr ? impulse::server::applyCommand(simulation, *row, message, limits)
                                : impulse::server::applyCommand(simulation, message, limits);
  if (outcome.ticksToStep > 0) outcome.reply = runStep(simulation, std::move(outcome));
  FUZZ_CHECK(replyRequestId(outcome.reply) == message.request_id());
  if (outcome.reply.has_command_result() && !outcome.reply.command_result().ok()) {
    FUZZ_CHECK(!outcome.reply.command_result().error().empty());
    FUZZ_CHECK(simulation.world().stateHash() == hashBefore);
    FUZZ_CHECK(simulation.world().bodyCount() == bodiesBefore);
    FUZZ_CHECK(simulation.world().gravity() == gravityBefore);
  }
  if (row != nullptr) ownership.recordOutcome(*row, message, outcome.reply, kPlayer, simulation);
  checkWorldSane(simulation.world());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // The first byte decides whether the commands come from a player.
  const bool asPlayer = (data[0] & 1) != 0;
  std::span<const char> stream(reinterpret_cast<const char*>(data + 1), size - 1);

  Simulation simulation = makeSimulation();
  impulse::server::Ownership ownership;
  impulse::wire::FrameReader reader(4096);
  for (int applied = 0; applied < kMaxCommands && !stream.empty();) {
    const auto result = reader.feed(stream);
    stream = stream.subspan(result.consumed);
    if (result.status != impulse::wire::FrameReader::Status::Frame) break;
    impulse::v1::ClientMessage message;
    if (!impulse::wire::parseFrame(reader.frame(), message) || message.has_hello()) continue;
    applyOne(simulation, ownership, message, asPlayer);
    ++applied;
  }
  return 0;
}
