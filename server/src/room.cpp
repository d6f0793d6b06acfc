#include "impulse/server/room.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "impulse/server/log.h"
#include "impulse/wire/convert.h"
#include "impulse/wire/framing.h"

namespace impulse::server {

namespace {

constexpr auto kStatsLogInterval = std::chrono::seconds(30);

Clock::duration periodOf(double hz) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / hz));
}

SimulationSettings simulationSettings(const ServerOptions& options) {
  return {.tickHz = options.tickHz,
          .subSteps = options.subSteps,
          .maxBodies = options.maxBodies,
          .preset = options.preset,
          .paused = options.paused};
}

// A CommandResult refusing a command before it reached the world.
v1::ServerMessage refusal(const v1::ClientMessage& message, std::string error, std::uint64_t tick) {
  v1::ServerMessage reply;
  auto* result = reply.mutable_command_result();
  result->set_request_id(message.request_id());
  result->set_ok(false);
  result->set_error(std::move(error));
  result->set_tick(tick);
  return reply;
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

Room::Room(asio::io_context& io, const ServerOptions& options, RoomHost& host)
    : options_(options),
      host_(host),
      timer_(io),
      simulation_(simulationSettings(options)),
      snapshots_(simulation_),
      schedule_(periodOf(options.tickHz), Clock::now()),
      tickTimes_(std::size_t(std::ceil(options.tickHz))) {}

void Room::start() {
  const auto now = Clock::now();
  schedule_ = TickSchedule(periodOf(options_.tickHz), now);
  lastStatsLog_ = now;
  lastSnapshotSlot_ = snapshotSlot();
  scheduleTick();
}

void Room::stop() {
  stopped_ = true;
  timer_.cancel();
  commands_ = FairQueue();
  steps_.clear();
}

// ------------------------------------------------------------------ members

void Room::join(const std::shared_ptr<Session>& session, bool wantSnapshots) {
  members_[session->id()] = session;
  v1::ServerMessage message;
  auto* welcome = message.mutable_welcome();
  welcome->set_protocol_version(wire::kProtocolVersion);
  welcome->set_client_id(session->id());
  welcome->set_tick_hz(options_.tickHz);
  welcome->set_snapshot_hz(options_.snapshotHz);
  welcome->set_tick(simulation_.tick());
  welcome->set_paused(simulation_.paused());
  const auto& bounds = simulation_.world().settings().bounds;
  wire::toWire(bounds.lower, welcome->mutable_world_min());
  wire::toWire(bounds.upper, welcome->mutable_world_max());
  welcome->set_max_frame_bytes(std::uint32_t(options_.maxFrameBytes));
  welcome->set_max_bodies(std::uint32_t(options_.maxBodies));
  welcome->set_max_step_ticks(limits_.maxStepTicks);
  welcome->set_admin(session->admin());
  welcome->set_max_commands_per_second(std::uint32_t(options_.maxCommandsPerSecond));
  welcome->set_idle_timeout(options_.idleTimeoutSeconds);
  session->send(message);
  if (wantSnapshots) session->subscribe(*this);
}

void Room::leave(Session& session) {
  if (members_.erase(session.id()) == 0) return;
  snapshotsSkippedByLeavers_ += session.snapshotsSkipped();
  commands_.dropClient(session.id());
  std::erase_if(steps_, [&](const StepJob& job) { return job.client() == session.id(); });
}

std::shared_ptr<Session> Room::member(std::uint32_t client) const {
  const auto it = members_.find(client);
  return it == members_.end() ? nullptr : it->second;
}

void Room::enqueue(Session& session, v1::ClientMessage&& message, std::size_t bytes) {
  if (!session.withinRate()) {
    // Answered at once and never queued, so a flood costs the tick nothing.
    ++commandsRateLimited_;
    reply(session,
          refusal(message,
                  std::string(commandName(message)) + ": rate limit exceeded (at most " +
                      std::to_string(options_.maxCommandsPerSecond) +
                      " commands per second per client); not applied",
                  simulation_.tick()),
          bytes);
    return;
  }
  commands_.push(session.id(), std::move(message), bytes);
}

std::pair<SharedFrame, std::uint64_t> Room::fullSnapshot(bool quantized) {
  return {quantized ? snapshots_.quantizedFull() : snapshots_.full(), snapshotSequence_};
}

// --------------------------------------------------------------------- ticks

void Room::scheduleTick() {
  timer_.expires_at(schedule_.nextDeadline());
  timer_.async_wait([this](const asio::error_code& ec) {
    if (!ec && !stopped_) onTimer();
  });
}

void Room::onTimer() {
  const auto due = schedule_.due(Clock::now());
  for (int i = 0; i < due.run && !stopped_; ++i) runTick();
  if (due.skipped > 0) {
    logLine("overrun: skipped " + std::to_string(due.skipped) + " tick(s) after running " +
            std::to_string(due.run) + " late");
  }
  if (!stopped_) scheduleTick();
}

void Room::runTick() {
  // Commands until half the period, then a Step in progress until three
  // quarters (at least one of its ticks): whatever is left waits for the
  // next tick, so sockets and timers keep being serviced in between.
  const auto start = Clock::now();
  const auto period = schedule_.period();
  applyCommands(start + period / 2);
  advanceStep(start + period * 3 / 4);
  if (!simulation_.paused()) {
    simulation_.step();
    if (snapshotSlot() != lastSnapshotSlot_) broadcastSnapshot();
  }
  tickTimes_.record(millisecondsSince(start));
  logStats(Clock::now());
}

void Room::advanceStep(Clock::time_point deadline) {
  if (steps_.empty() || !steps_.front().advance(simulation_, deadline)) return;
  StepJob job = std::move(steps_.front());
  steps_.pop_front();
  commands_.release(job.client());
  if (const auto session = member(job.client())) {
    reply(*session, job.finish(simulation_), job.bytes());
  }
  broadcastSnapshot();
}

void Room::applyCommands(Clock::time_point deadline) {
  // Round-robin over the clients' queues (each client's own commands in
  // arrival order), until the deadline. Only the commands there at the
  // start are served: a client sending while the tick runs waits for the next.
  const std::size_t available = commands_.size();
  for (std::size_t applied = 0; applied < available && Clock::now() < deadline; ++applied) {
    auto queued = commands_.pop();
    if (!queued) break;
    // Leavers' queues are dropped, so the client is always a member.
    if (const auto session = member(queued->client)) applyQueued(*queued, *session);
  }
}

void Room::applyQueued(QueuedCommand& queued, Session& session) {
  const auto& message = queued.message;
  if (!session.admin()) {
    if (std::string error = ownership_.playerRefusal(message, session.id()); !error.empty()) {
      return reply(session, refusal(message, std::move(error), simulation_.tick()), queued.bytes);
    }
  }
  auto outcome = applyCommand(simulation_, message, limits_);
  ownership_.recordOutcome(message, outcome.reply, session.id(), simulation_.world());
  if (outcome.ticksToStep > 0) {
    // The client's later commands wait for its Step, keeping their order.
    commands_.hold(session.id());
    steps_.emplace_back(session.id(), std::move(outcome.reply), outcome.ticksToStep, queued.bytes);
    return;
  }
  if (outcome.reply.has_pong()) answerPing(message.ping(), outcome.reply);
  reply(session, std::move(outcome.reply), queued.bytes);
  if (outcome.changed && simulation_.paused()) broadcastSnapshot();
}

void Room::reply(Session& session, v1::ServerMessage message, std::size_t bytes) {
  session.send(message);
  session.commandsApplied(bytes);
}

void Room::answerPing(const v1::Ping& ping, v1::ServerMessage& pong) {
  *pong.mutable_pong()->mutable_stats() = stats(ping.want_state_hash());
}

std::int64_t Room::snapshotSlot() const {
  return std::int64_t(
      std::floor(double(simulation_.tick()) * options_.snapshotHz / options_.tickHz));
}

void Room::broadcastSnapshot() {
  // Snapshots stay on the tick grid (every second tick at 60/30 Hz) even
  // after paused steps broadcast on other ticks.
  lastSnapshotSlot_ = snapshotSlot();
  ++snapshotSequence_;
  // Copies: a session that a send closes leaves members_ at once.
  std::vector<std::shared_ptr<Session>> subscribers;
  for (const auto& [id, session] : members_) {
    if (session->subscribed()) subscribers.push_back(session);
  }
  WorldChanges& changes = simulation_.takeChanges();
  if (subscribers.empty()) {
    snapshots_.skipQuantized();
    return;
  }
  const auto delta = snapshots_.delta(changes);
  lastSnapshotBytes_ = delta->size();
  // Quantized subscribers share one delta too; without any, its baseline lapses.
  const bool anyQuantized = std::any_of(subscribers.begin(), subscribers.end(),
                                        [](const auto& session) { return session->quantized(); });
  const auto quantizedDelta = anyQuantized ? snapshots_.quantizedDelta(changes) : nullptr;
  if (!anyQuantized) snapshots_.skipQuantized();
  for (const auto& session : subscribers) {
    session->offerSnapshot(snapshotSequence_, session->quantized() ? quantizedDelta : delta);
  }
}

v1::ServerStats Room::stats(bool withStateHash) {
  v1::ServerStats stats;
  stats.set_uptime_us(std::uint64_t(
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - schedule_.start())
          .count()));
  stats.set_clock_ticks(std::uint64_t(schedule_.slots()));
  stats.set_ticks_skipped(std::uint64_t(schedule_.skipped()));
  stats.set_last_tick_ms(tickTimes_.last());
  stats.set_mean_tick_ms(tickTimes_.mean());
  stats.set_max_tick_ms(tickTimes_.max());
  stats.set_last_step_ms(simulation_.stepTimes().last());
  stats.set_mean_step_ms(simulation_.stepTimes().mean());
  stats.set_bodies(std::uint32_t(simulation_.world().bodyCount()));
  stats.set_awake_bodies(std::uint32_t(simulation_.world().awakeBodyCount()));
  stats.set_clients(std::uint32_t(host_.connectionCount()));
  stats.set_last_snapshot_bytes(lastSnapshotBytes_);
  std::uint64_t skipped = snapshotsSkippedByLeavers_;
  for (const auto& [id, session] : members_) skipped += session->snapshotsSkipped();
  stats.set_snapshots_skipped(skipped);
  if (withStateHash) stats.set_state_hash(simulation_.stateHash());
  stats.set_bodies_left_world(simulation_.bodiesLeftWorld());
  stats.set_guard_repairs(simulation_.world().guardReport().repairedBodies);
  stats.set_commands_rate_limited(commandsRateLimited_);
  stats.set_commands_queued(commands_.size());
  return stats;
}

void Room::logStats(Clock::time_point now) {
  if (now - lastStatsLog_ < kStatsLogInterval) return;
  lastStatsLog_ = now;
  const auto s = stats(false);
  logLine("tick " + std::to_string(simulation_.tick()) + ": tick " +
          std::to_string(s.mean_tick_ms()) + " ms mean, " + std::to_string(s.max_tick_ms()) +
          " ms max; " + std::to_string(s.bodies()) + " bodies (" +
          std::to_string(s.awake_bodies()) + " awake); " + std::to_string(s.clients()) +
          " clients; " + std::to_string(s.ticks_skipped()) + " ticks skipped");
}

}  // namespace impulse::server
