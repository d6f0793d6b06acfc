#include "impulse/server/server.h"

#include <malloc.h>

#include <cmath>
#include <vector>

#include "impulse/server/log.h"
#include "impulse/wire/convert.h"

namespace impulse::server {

namespace {

constexpr auto kHousekeepingInterval = std::chrono::milliseconds(100);
constexpr auto kStatsLogInterval = std::chrono::seconds(30);
constexpr auto kAcceptRetryDelay = std::chrono::milliseconds(100);
// malloc_trim walks the heap: at most this often, and only after closes.
constexpr auto kTrimInterval = std::chrono::seconds(2);

Clock::duration periodOf(double hz) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / hz));
}

SimulationSettings simulationSettings(const ServerOptions& options) {
  SimulationSettings settings;
  settings.tickHz = options.tickHz;
  settings.subSteps = options.subSteps;
  settings.maxBodies = options.maxBodies;
  settings.preset = options.preset;
  settings.paused = options.paused;
  return settings;
}

SessionLimits sessionLimits(const ServerOptions& options) {
  SessionLimits limits;
  limits.maxFrameBytes = options.maxFrameBytes;
  limits.maxPendingCommandBytes = std::max<std::size_t>(options.maxFrameBytes, 256 * 1024);
  limits.stallTimeout = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(options.stallTimeoutSeconds));
  limits.idleTimeout = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(options.idleTimeoutSeconds));
  limits.commandsPerSecond = options.maxCommandsPerSecond;
  return limits;
}

// A CommandResult refusing a command before it reached the world.
v1::ServerMessage refusal(const v1::ClientMessage& message, std::string error,
                          std::uint64_t tick) {
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

Server::Server(asio::io_context& io, const ServerOptions& options)
    : io_(io),
      options_(options),
      acceptor_(io),
      timer_(io),
      simulation_(simulationSettings(options)),
      sessionLimits_(sessionLimits(options)),
      schedule_(periodOf(options.tickHz), Clock::now()),
      tickTimes_(std::size_t(std::ceil(options.tickHz))),
      tokens_{options.token, options.adminToken} {
  const asio::ip::tcp::endpoint endpoint(asio::ip::make_address(options.bind), options.port);
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(asio::ip::tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
}

void Server::start() {
  const auto now = Clock::now();
  schedule_ = TickSchedule(periodOf(options_.tickHz), now);
  lastHousekeeping_ = now;
  lastStatsLog_ = now;
  lastTrim_ = now;
  lastSnapshotSlot_ = snapshotSlot();
  logLine("serving preset " + std::to_string(options_.preset) + " at " +
          std::to_string(options_.tickHz) + " Hz" + (options_.paused ? ", paused" : ""));
  accept();
  scheduleTick();
}

void Server::stop() {
  if (stopped_) return;
  stopped_ = true;
  logLine("shutting down");
  asio::error_code ignored;
  acceptor_.close(ignored);
  timer_.cancel();
  commands_ = FairQueue();
  std::vector<std::shared_ptr<Session>> sessions;
  for (const auto& [id, session] : sessions_) sessions.push_back(session);
  for (const auto& session : sessions) session->close("server shutting down");
}

// ------------------------------------------------------------------ clients

void Server::accept() {
  acceptor_.async_accept([this](const asio::error_code& ec, asio::ip::tcp::socket socket) {
    if (stopped_) return;
    if (ec) {
      // Out of descriptors and the like: retry soon instead of spinning.
      logLine("accept failed: " + ec.message());
      auto retry = std::make_shared<asio::steady_timer>(io_, kAcceptRetryDelay);
      retry->async_wait([this, retry](const asio::error_code&) {
        if (!stopped_) accept();
      });
      return;
    }
    const std::uint32_t id = nextClientId_++;
    auto session = std::make_shared<Session>(std::move(socket), *this, id, sessionLimits_);
    const std::string refusal = admissionRefusal(*session);
    sessions_[id] = session;
    if (!refusal.empty()) {
      session->reject(refusal);
    } else {
      session->start();
    }
    accept();
  });
}

std::string Server::admissionRefusal(const Session& newcomer) {
  const auto now = Clock::now();
  std::size_t active = 0;
  std::size_t fromAddress = 0;
  Session* idlest = nullptr;
  Session* idlestFromAddress = nullptr;
  auto idler = [](Session* a, Session& b) {
    return a == nullptr || b.lastActive() < a->lastActive() ? &b : a;
  };
  for (const auto& [id, other] : sessions_) {
    if (!other->acceptingTraffic()) continue;
    ++active;
    const bool sameAddress = other->address() == newcomer.address();
    fromAddress += sameAddress ? 1 : 0;
    if (!other->evictable(now)) continue;
    idlest = idler(idlest, *other);
    if (sameAddress) idlestFromAddress = idler(idlestFromAddress, *other);
  }
  // A full server (or address) makes room by closing its idlest silent
  // connection, so clients that say nothing cannot keep anyone out.
  Session* victim = nullptr;
  if (fromAddress >= std::size_t(options_.maxClientsPerAddress)) {
    if (idlestFromAddress == nullptr) {
      return "too many connections from " + newcomer.address() + " (at most " +
             std::to_string(options_.maxClientsPerAddress) + " per address)";
    }
    victim = idlestFromAddress;
  } else if (active >= std::size_t(options_.maxClients)) {
    if (idlest == nullptr) {
      return "server is full (" + std::to_string(options_.maxClients) + " clients)";
    }
    victim = idlest;
  }
  if (victim != nullptr) victim->evict(now);
  return {};
}

void Server::onHello(const std::shared_ptr<Session>& session, const v1::Hello& hello) {
  const Admission admission = admit(tokens_, hello.token());
  if (!admission.error.empty()) return session->reject(admission.error);
  session->setAdmin(admission.admin);
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
  welcome->set_admin(admission.admin);
  welcome->set_max_commands_per_second(std::uint32_t(options_.maxCommandsPerSecond));
  welcome->set_idle_timeout(options_.idleTimeoutSeconds);
  session->send(message);
  if (hello.want_snapshots()) session->subscribe();
}

void Server::onCommand(const std::shared_ptr<Session>& session, v1::ClientMessage&& message,
                       std::size_t bytes) {
  if (!session->withinRate()) {
    // Answered at once and never queued, so a flood costs the tick nothing.
    ++commandsRateLimited_;
    session->send(refusal(message,
                          std::string(commandName(message)) + ": rate limit exceeded (at most " +
                              std::to_string(options_.maxCommandsPerSecond) +
                              " commands per second per client); not applied",
                          simulation_.tick()));
    session->commandsApplied(bytes);
    return;
  }
  commands_.push(session->id(), std::move(message), bytes);
}

void Server::onClosed(Session& session) {
  snapshotsSkipped_ += session.snapshotsSkipped();
  commands_.dropClient(session.id());
  ++closedSinceTrim_;
  sessions_.erase(session.id());
}

std::pair<SharedFrame, std::uint64_t> Server::currentFullSnapshot() {
  return {simulation_.snapshots().full(simulation_.meta()), snapshotSequence_};
}

// --------------------------------------------------------------------- ticks

void Server::scheduleTick() {
  timer_.expires_at(schedule_.nextDeadline());
  timer_.async_wait([this](const asio::error_code& ec) {
    if (!ec && !stopped_) onTimer();
  });
}

void Server::onTimer() {
  const auto due = schedule_.due(Clock::now());
  for (int i = 0; i < due.run && !stopped_; ++i) runTick();
  if (due.skipped > 0) {
    logLine("overrun: skipped " + std::to_string(due.skipped) + " tick(s) after running " +
            std::to_string(due.run) + " late");
  }
  if (!stopped_) scheduleTick();
}

void Server::runTick() {
  const auto start = Clock::now();
  applyCommands();
  if (!simulation_.paused()) {
    simulation_.step();
    if (snapshotDue()) broadcastSnapshot();
  }
  ++ticksRun_;
  tickTimes_.record(millisecondsSince(start));
  housekeeping(Clock::now());
}

void Server::applyCommands() {
  // Round-robin over the clients' queues (each client's own commands in
  // arrival order), within a time budget: commands left over (behind a long
  // Step or a burst of preset loads) wait for the next tick, so sockets keep
  // being serviced in between.
  const auto start = Clock::now();
  const auto budget = schedule_.period() / 2;
  std::size_t applied = 0;
  const std::size_t available = commands_.size();
  while (applied < available && Clock::now() - start < budget) {
    auto queued = commands_.pop();
    ++applied;
    // Closed clients' queues are dropped, so the session is always there.
    const auto session = sessions_.find(queued->client);
    if (session != sessions_.end()) applyQueued(*queued, *session->second);
  }
}

void Server::applyQueued(QueuedCommand& queued, Session& session) {
  if (!session.admin()) {
    if (std::string error = ownership_.playerRefusal(queued.message, session.id());
        !error.empty()) {
      session.send(refusal(queued.message, std::move(error), simulation_.tick()));
      return session.commandsApplied(queued.bytes);
    }
  }
  const bool ping = queued.message.has_ping();
  const bool withHash = ping && queued.message.ping().want_state_hash();
  const auto outcome = applyCommand(simulation_, queued.message, limits_,
                                    ping ? stats(withHash) : v1::ServerStats());
  ownership_.recordOutcome(queued.message, outcome.reply, session.id(), simulation_.world());
  session.send(outcome.reply);
  session.commandsApplied(queued.bytes);
  if (outcome.stepped || (outcome.changed && simulation_.paused())) broadcastSnapshot();
}

std::int64_t Server::snapshotSlot() const {
  return std::int64_t(
      std::floor(double(simulation_.tick()) * options_.snapshotHz / options_.tickHz));
}

bool Server::snapshotDue() const { return snapshotSlot() != lastSnapshotSlot_; }

void Server::broadcastSnapshot() {
  // Snapshots stay on the tick grid (every second tick at 60/30 Hz) even
  // after paused steps broadcast on other ticks.
  lastSnapshotSlot_ = snapshotSlot();
  std::vector<std::shared_ptr<Session>> subscribers;
  for (const auto& [id, session] : sessions_) {
    if (session->subscribed()) subscribers.push_back(session);
  }
  ++snapshotSequence_;
  if (subscribers.empty()) {
    simulation_.snapshots().discardPending();
    return;
  }
  const auto delta = simulation_.snapshots().takeDelta(simulation_.meta());
  lastSnapshotBytes_ = delta->size();
  for (const auto& session : subscribers) session->offerSnapshot(snapshotSequence_, delta);
}

v1::ServerStats Server::stats(bool withStateHash) {
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
  stats.set_clients(std::uint32_t(sessions_.size()));
  stats.set_last_snapshot_bytes(lastSnapshotBytes_);
  std::uint64_t skipped = snapshotsSkipped_;
  for (const auto& [id, session] : sessions_) skipped += session->snapshotsSkipped();
  stats.set_snapshots_skipped(skipped);
  if (withStateHash) stats.set_state_hash(simulation_.stateHash());
  stats.set_bodies_left_world(simulation_.bodiesLeftWorld());
  stats.set_guard_repairs(simulation_.world().guardReport().repairedBodies);
  stats.set_commands_rate_limited(commandsRateLimited_);
  stats.set_commands_queued(commands_.size());
  return stats;
}

void Server::releaseMemory(Clock::time_point now) {
  if (closedSinceTrim_ == 0 || now - lastTrim_ < kTrimInterval) return;
  closedSinceTrim_ = 0;
  lastTrim_ = now;
  malloc_trim(0);
}

void Server::housekeeping(Clock::time_point now) {
  releaseMemory(now);
  if (now - lastHousekeeping_ >= kHousekeepingInterval) {
    lastHousekeeping_ = now;
    std::vector<std::shared_ptr<Session>> sessions;
    for (const auto& [id, session] : sessions_) sessions.push_back(session);
    for (const auto& session : sessions) session->checkTimeouts(now);
  }
  if (now - lastStatsLog_ >= kStatsLogInterval) {
    lastStatsLog_ = now;
    const auto s = stats(false);
    logLine("tick " + std::to_string(simulation_.tick()) + ": tick " +
            std::to_string(s.mean_tick_ms()) + " ms mean, " + std::to_string(s.max_tick_ms()) +
            " ms max; " + std::to_string(s.bodies()) + " bodies (" +
            std::to_string(s.awake_bodies()) + " awake); " + std::to_string(s.clients()) +
            " clients; " + std::to_string(s.ticks_skipped()) + " ticks skipped");
  }
}

}  // namespace impulse::server
