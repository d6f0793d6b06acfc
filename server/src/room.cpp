#include "impulse/server/room.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "impulse/server/log.h"
#include "impulse/wire/framing.h"
#include "impulse/wire/wire_positions.h"

namespace impulse::server {

namespace {

constexpr auto kStatsLogInterval = std::chrono::seconds(30);

Clock::duration periodOf(double hz) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / hz));
}

SimulationSettings simulationSettings(const ServerOptions& options, const RoomBounds& bounds,
                                      std::shared_ptr<ServerBodies> serverBodies, const TaskSettings& tasks) {
  return {.tickHz = options.tickHz,
          .subSteps = options.subSteps,
          .maxBodies = options.maxBodies,
          .preset = options.preset,
          .paused = options.paused,
          .fieldLimits = {.maxFields = options.maxFields, .maxCost = options.maxFieldCost},
          .serverBodies = std::move(serverBodies),
          .bounds = bounds.relativeToOrigin(),
          .origin = bounds.origin(),
          .tasks = tasks};
}

void putPoint(const Vec2d& point, v1::Vec2* out) {
  out->set_x(point.x());
  out->set_y(point.y());
}

// Welcome's and RoomInfo's bounds and origin, from (0, 0).
void putBounds(const RoomBounds& bounds, v1::Vec2* min, v1::Vec2* max, v1::Vec2* origin) {
  putPoint(bounds.lower, min);
  putPoint(bounds.upper, max);
  putPoint(bounds.origin(), origin);
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

Room::Room(std::string name, asio::io_context& io, asio::thread_pool& steppers, const TaskSettings& engineWorkers,
           const ServerOptions& options, RoomHost& host, const RoomBounds& bounds)
    : name_(std::move(name)),
      bounds_(bounds),
      io_(io),
      strand_(asio::make_strand(steppers.get_executor())),
      options_(options),
      host_(host),
      timer_(strand_),
      simulation_(simulationSettings(options, bounds, host.serverBodies(), engineWorkers)),
      snapshots_(simulation_),
      schedule_(periodOf(options.tickHz), Clock::now()),
      tickTimes_(std::size_t(std::ceil(options.tickHz))) {
  publishedTickEnd_ = Clock::now().time_since_epoch().count();
  publish();
}

template <class Work>
void Room::onStrand(Work work) {
  asio::post(strand_, [self = shared_from_this(), work = std::move(work)]() mutable {
    work();
    self->publish();
    if (self->outbox_.empty()) return;
    auto batch = std::make_shared<Batch>(std::move(self->outbox_));
    self->outbox_.clear();
    asio::post(self->io_, [self, batch] { self->deliver(*batch); });
  });
}

void Room::start() {
  onStrand([this] {
    const auto now = Clock::now();
    schedule_ = TickSchedule(periodOf(options_.tickHz), now);
    lastStatsLog_ = now;
    lastSnapshotSlot_ = snapshotSlot();
    scheduleTick(schedule_.nextDeadline());
  });
}

void Room::stop() {
  onStrand([this] {
    stopped_ = true;
    timer_.cancel();
    commands_ = FairQueue();
    stamped_.clear();
    steps_.clear();
  });
}

// ------------------------------------------------------------------ members

void Room::join(const std::shared_ptr<Session>& session, bool wantSnapshots) {
  members_[session->id()] = session;
  onStrand([this, client = session->id(), admin = session->admin(), quantized = session->quantized(),
            wantSnapshots] { welcome(client, admin, quantized, wantSnapshots); });
}

void Room::welcome(std::uint32_t client, bool admin, bool quantized, bool wantSnapshots) {
  clients_[client] = admin;
  if (quantized) quantizedClients_.insert(client);
  v1::ServerMessage message;
  auto* welcome = message.mutable_welcome();
  welcome->set_protocol_version(wire::kProtocolVersion);
  welcome->set_client_id(client);
  welcome->set_tick_hz(options_.tickHz);
  welcome->set_snapshot_hz(options_.snapshotHz);
  welcome->set_tick(simulation_.tick());
  welcome->set_paused(simulation_.paused());
  putBounds(bounds_, welcome->mutable_world_min(), welcome->mutable_world_max(), welcome->mutable_world_origin());
  welcome->set_max_frame_bytes(std::uint32_t(options_.maxFrameBytes));
  welcome->set_max_bodies(std::uint32_t(options_.maxBodies));
  welcome->set_max_step_ticks(limits_.maxStepTicks);
  welcome->set_admin(admin);
  welcome->set_max_commands_per_second(std::uint32_t(options_.maxCommandsPerSecond));
  welcome->set_idle_timeout(options_.idleTimeoutSeconds);
  welcome->set_time_scale(simulation_.timeScale());
  welcome->set_max_input_delay_ticks(std::uint32_t(options_.maxInputDelayTicks));
  outbox_.emplace_back(Reply{client, std::move(message), 0,
                             wantSnapshots ? ReplyKind::WelcomeAndSubscribe : ReplyKind::Welcome});
}

void Room::leave(Session& session) {
  const auto it = members_.find(session.id());
  if (it == members_.end()) return;
  members_.erase(it);
  subscriberIds_.erase(session.id());
  countSubscribers();
  snapshotsSkippedByLeavers_ += session.snapshotsSkipped();
  rateWaitsByLeavers_ += session.rateWaits();
  onStrand([this, client = session.id()] {
    clients_.erase(client);
    quantizedClients_.erase(client);
    streams_.erase(client);
    subscribeEvents(client, false);
    commands_.dropClient(client);
    stamped_.dropClient(client);
    jointTags_.dropClient(client);
    snapshots_.forgetClient(client);
    std::erase_if(steps_, [&](const StepJob& job) { return job.client() == client; });
  });
}

std::shared_ptr<Session> Room::member(std::uint32_t client) const {
  const auto it = members_.find(client);
  return it == members_.end() ? nullptr : it->second;
}

void Room::countSubscribers() {
  subscribers_ = subscriberIds_.size();
  quantizedSubscribers_ = std::size_t(std::ranges::count_if(subscriberIds_, [&](std::uint32_t id) {
    const auto session = member(id);
    return session && session->quantized();
  }));
}

void Room::enqueue(Session& session, v1::ClientMessage&& message, std::size_t bytes) {
  // The session keeps to its rate by reading no faster (Session::rateAllowsACommand).
  onStrand([this, client = session.id(), message = std::move(message), bytes]() mutable {
    // A leaver's commands are dropped: its leave was posted after them.
    if (clients_.contains(client)) commands_.push(client, std::move(message), bytes);
  });
}

v1::RoomInfo Room::info() const {
  v1::RoomInfo info;
  info.set_name(name_);
  info.set_clients(std::uint32_t(members_.size()));
  info.set_bodies(publishedBodies_.load());
  info.set_tick(publishedTick_.load());
  putBounds(bounds_, info.mutable_world_min(), info.mutable_world_max(), info.mutable_world_origin());
  return info;
}

Clock::duration Room::sinceLastTick(Clock::time_point now) const {
  return now - Clock::time_point(Clock::duration(publishedTickEnd_.load()));
}

void Room::requestFullSnapshot(std::uint32_t client, bool quantized) {
  onStrand([this, client, quantized] {
    // Between ticks the strand owns the world: built here, the frame costs
    // the I/O thread nothing, and it is cached for others asking this tick.
    const auto stream = streams_.find(client);
    if (stream != streams_.end() && !stream->second.wantsShared()) {
      snapshots_.refreshPlaces();
      outbox_.emplace_back(FullSnapshot{client, snapshots_.personalFull(stream->second), snapshotSequence_});
      return;
    }
    SharedFrame frame = quantized ? snapshots_.quantizedFull() : snapshots_.full();
    outbox_.emplace_back(FullSnapshot{client, std::move(frame), snapshotSequence_});
  });
}

// ------------------------------------------------------- I/O-thread delivery

void Room::deliver(Batch& batch) {
  for (auto& item : batch) {
    if (auto* reply = std::get_if<Reply>(&item)) {
      deliverReply(*reply);
    } else if (auto* broadcast = std::get_if<Broadcast>(&item)) {
      deliverBroadcast(*broadcast);
    } else if (auto* events = std::get_if<EventsBroadcast>(&item)) {
      deliverEvents(*events);
    } else {
      deliverFullSnapshot(std::get<FullSnapshot>(item));
    }
  }
}

void Room::deliverReply(Reply& reply) {
  const auto session = member(reply.client);
  if (!session) return;
  auto& message = reply.message;
  if (message.has_pong()) {
    // What only the I/O thread knows: connections and the members' skips.
    auto* stats = message.mutable_pong()->mutable_stats();
    stats->set_clients(std::uint32_t(host_.connectionCount()));
    std::uint64_t skipped = snapshotsSkippedByLeavers_;
    std::uint64_t rateWaits = rateWaitsByLeavers_;
    for (const auto& [id, other] : members_) {
      skipped += other->snapshotsSkipped();
      rateWaits += other->rateWaits();
    }
    stats->set_snapshots_skipped(skipped);
    stats->set_commands_rate_limited(rateWaits);
  }
  if (message.has_room_list()) host_.listRooms(*message.mutable_room_list());
  if (message.has_command_result() && !message.command_result().ok()) {
    session->logRefusal(message.command_result().error());
  }
  session->send(message);
  if (reply.kind == ReplyKind::Command) session->commandsApplied(reply.bytes);
  if (reply.kind == ReplyKind::WelcomeAndSubscribe) {
    session->subscribe(*this);
    if (session->subscribed()) subscriberIds_.insert(session->id());
    countSubscribers();
  }
}

void Room::deliverBroadcast(const Broadcast& broadcast) {
  // Copies: a session that a send closes leaves members_ at once. The list
  // keeps its capacity from one broadcast to the next.
  broadcastTargets_.clear();
  for (const auto& [id, session] : members_) {
    if (session->subscribed()) broadcastTargets_.push_back(session);
  }
  for (const auto& session : broadcastTargets_) {
    const auto personal =
        std::ranges::lower_bound(broadcast.personal, session->id(), {}, &PersonalFrame::client);
    if (personal != broadcast.personal.end() && personal->client == session->id()) {
      session->offerSnapshot(broadcast.sequence, personal->frame);
      continue;
    }
    // A subscriber counted after the tick found no delta of its encoding:
    // its null frame becomes a full snapshot (or key frame) when written.
    session->offerSnapshot(broadcast.sequence,
                           session->quantized() ? broadcast.quantizedDelta : broadcast.delta);
  }
  broadcastTargets_.clear();  // lets closed sessions go
}

void Room::deliverFullSnapshot(FullSnapshot& snapshot) {
  // A member that left meanwhile no longer wants it.
  if (const auto session = member(snapshot.client)) {
    session->takeFullSnapshot(std::move(snapshot.frame), snapshot.sequence);
  }
}

void Room::deliverEvents(const EventsBroadcast& events) {
  for (const std::uint32_t client : events.clients) {
    if (const auto session = member(client)) session->offerEvents(events.frame);
  }
}

// --------------------------------------------------------------------- ticks

void Room::scheduleTick(Clock::time_point at) {
  timer_.expires_at(at);
  timer_.async_wait([self = shared_from_this()](const asio::error_code& ec) {
    if (ec || self->stopped_) return;
    self->onStrand([self] { self->onTimer(); });
  });
}

void Room::onTimer() {
  if (stopped_) return;
  const auto start = Clock::now();
  const auto period = schedule_.period();
  auto due = schedule_.due(start);
  // A room whose ticks overrun its period (over the last second: a moment
  // of CPU contention is caught up as before) runs one tick, not a
  // catch-up, and then rests as long as it worked: it takes at most half a
  // stepping thread and runs in slow motion (ticks_skipped), and the other
  // rooms' ticks, Pongs and Welcomes get their turn on the pool.
  if (overrunning_ && due.run > 1) {
    schedule_.skip(due.run - 1);
    due.skipped += due.run - 1;
    due.run = 1;
  }
  for (int i = 0; i < due.run; ++i) runTick();
  const auto worked = Clock::now() - start;
  if (due.skipped > 0) {
    logLine("room " + name_ + ": overrun: skipped " + std::to_string(due.skipped) +
            " tick(s) after running " + std::to_string(due.run) + " late");
  }
  overrunning_ = tickTimes_.mean() > std::chrono::duration<double, std::milli>(period).count();
  publishedOverrunning_ = overrunning_;
  publishedTickEnd_ = Clock::now().time_since_epoch().count();
  const auto next = schedule_.nextDeadline();
  scheduleTick(overrunning_ ? std::max(next, Clock::now() + worked) : next);
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
    ++runningTicks_;
    const int stepped = runScaledSteps(start + period * 3 / 4);
    // Below 1x most ticks run no step: they have nothing new to send.
    if (stepped > 0 && snapshotSlot() != lastSnapshotSlot_) broadcastSnapshot();
  }
  broadcastEvents();
  tickTimes_.record(millisecondsSince(start));
  logStats(Clock::now());
}

int Room::runScaledSteps(Clock::time_point deadline) {
  // Like a StepJob: the first step always runs; the others while the tick's
  // budget lasts. Steps that do not fit are dropped, never owed, so a world
  // too large for its time scale runs slower instead of falling behind.
  const int due = simulation_.stepsDueThisTick();
  int stepped = 0;
  while (stepped < due && (stepped == 0 || Clock::now() < deadline)) {
    // Commands stamped for the tick this step starts from meet here.
    applyDueCommands();
    simulation_.step();
    ++stepped;
  }
  scaledStepsDropped_ += std::uint64_t(due - stepped);
  return stepped;
}

void Room::advanceStep(Clock::time_point deadline) {
  if (steps_.empty() || !steps_.front().advance(simulation_, deadline)) return;
  StepJob job = std::move(steps_.front());
  steps_.pop_front();
  commands_.release(job.client());
  if (clients_.contains(job.client())) reply(job.client(), job.finish(simulation_), job.bytes());
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
    if (const auto client = clients_.find(queued->client); client != clients_.end()) {
      applyOrSchedule(*queued, client->second);
    }
  }
  // Stamped for this tick: applied before its step, whether the room runs
  // (runScaledSteps finds none left) or is paused.
  applyDueCommands();
}

void Room::applyOrSchedule(QueuedCommand& queued, bool admin) {
  const StampCheck stamp = checkStamp(queued.message, simulation_.tick(), std::uint64_t(options_.maxInputDelayTicks));
  if (!stamp.refusal.empty()) {
    return reply(queued.client, refusal(queued.message, stamp.refusal, simulation_.tick()), queued.bytes);
  }
  if (stamp.timing == StampTiming::Waits || stamp.timing == StampTiming::Now) {
    return stamped_.schedule(std::move(queued));
  }
  applyQueued(queued, admin);
}

void Room::applyDueCommands() {
  for (QueuedCommand& due : stamped_.takeDue(simulation_.tick())) {
    // Leavers' commands are dropped, so the client is always a member.
    if (const auto client = clients_.find(due.client); client != clients_.end()) {
      applyQueued(due, client->second);
    }
  }
}

void Room::applyQueued(QueuedCommand& queued, bool admin) {
  auto& message = queued.message;
  const std::uint32_t client = queued.client;
  // Positions from (0, 0) become the world's, in double, before any float.
  wire::shiftPositions(message, -simulation_.world().origin());
  if (message.has_for_tick()) snapshots_.stampProcessed(client, message.request_id());
  const CommandRow* row = findCommand(message);
  if (row == nullptr) {
    return reply(client, refusal(message, noCommandError(message), simulation_.tick()), queued.bytes);
  }
  // A joint named by its tag: its id, now that the CreateJoint before it ran.
  if (std::string error = jointTags_.resolve(message, client, simulation_); !error.empty()) {
    return reply(client, refusal(message, std::move(error), simulation_.tick()), queued.bytes);
  }
  if (!admin) {
    if (std::string error = ownership_.playerRefusal(*row, message, client); !error.empty()) {
      return reply(client, refusal(message, std::move(error), simulation_.tick()), queued.bytes);
    }
  }
  auto outcome = applyCommand(simulation_, *row, message, limits_);
  ownership_.recordOutcome(*row, message, outcome.reply, client, simulation_);
  jointTags_.record(message, outcome.reply, client, simulation_.world());
  if (outcome.eventSubscription) subscribeEvents(client, *outcome.eventSubscription);
  if (outcome.interestArea || outcome.budget) changeStream(client, *row, message, outcome);
  if (outcome.ticksToStep > 0) {
    // The client's later commands wait for its Step, keeping their order.
    commands_.hold(client);
    steps_.emplace_back(client, std::move(outcome.reply), outcome.ticksToStep, queued.bytes);
    return;
  }
  if (outcome.reply.has_pong()) answerPing(message.ping(), outcome.reply);
  reply(client, std::move(outcome.reply), queued.bytes);
  // A paused room broadcasts only when something changes, and a new area
  // changes what its client sees: the bodies it now covers come at once.
  if ((outcome.changed || outcome.interestArea) && simulation_.paused()) broadcastSnapshot();
}

void Room::reply(std::uint32_t client, v1::ServerMessage message, std::size_t bytes) {
  wire::shiftPositions(message, simulation_.world().origin());
  outbox_.emplace_back(Reply{client, std::move(message), bytes});
}

void Room::changeStream(std::uint32_t client, const CommandRow& row, const v1::ClientMessage& message,
                        CommandOutcome& outcome) {
  if (quantizedClients_.contains(client)) {
    outcome.reply = refusal(message,
                            std::string(row.name) +
                                ": areas of interest and budgets need plain snapshots "
                                "(Hello.snapshot_encoding SNAPSHOT_ENCODING_PLAIN)",
                            simulation_.tick());
    return;
  }
  PersonalStream& stream = streams_[client];
  if (outcome.interestArea) stream.setArea(outcome.interestArea->area);
  if (outcome.budget) stream.setBudget(outcome.budget->bytesPerSecond);
}

void Room::answerPing(const v1::Ping& ping, v1::ServerMessage& pong) {
  *pong.mutable_pong()->mutable_stats() = stats(ping.want_state_hash());
}

std::int64_t Room::snapshotSlot() const {
  return std::int64_t(std::floor(double(runningTicks_) * options_.snapshotHz / options_.tickHz));
}

void Room::broadcastSnapshot() {
  // Snapshots stay on the tick grid (every second tick at 60/30 Hz) even
  // after paused steps broadcast on other ticks.
  lastSnapshotSlot_ = snapshotSlot();
  ++snapshotSequence_;
  WorldChanges& changes = simulation_.takeChanges();
  changes.normalise();
  // Quantized subscribers share one delta; without any, its baseline lapses.
  const std::size_t quantized = quantizedSubscribers_.load();
  if (quantized == 0) snapshots_.skipQuantized();
  // A subscriber joining meanwhile starts from a full snapshot, so nothing is
  // lost; and each encoding is built only for its subscribers (one counted
  // after this point gets a null frame, which becomes a full snapshot).
  const std::size_t subscribers = subscribers_.load();
  if (subscribers == 0) {
    // Nobody took this broadcast: a personal stream's client (subscribing
    // just now) starts over from a full snapshot.
    snapshots_.forgetPlaces();
    for (auto& [client, stream] : streams_) stream.startOver();
    return;
  }
  std::vector<PersonalFrame> personal = personalFrames(changes);
  // Personal streams take no shared delta (one that a member without a
  // stream finds missing becomes a full snapshot).
  SharedFrame delta = subscribers > quantized + personal.size() ? snapshots_.delta(changes) : nullptr;
  SharedFrame quantizedDelta = quantized > 0 ? snapshots_.quantizedDelta(changes) : nullptr;
  // The plain delta's size when there is one, else the quantized or the
  // first personal one's (Pong's last_snapshot_bytes).
  lastSnapshotBytes_ = delta            ? delta->size()
                       : quantizedDelta ? quantizedDelta->size()
                                        : personal.front().frame->size();
  outbox_.emplace_back(Broadcast{snapshotSequence_, std::move(delta), std::move(quantizedDelta), std::move(personal)});
}

std::vector<Room::PersonalFrame> Room::personalFrames(const WorldChanges& changes) {
  std::vector<PersonalFrame> frames;
  if (streams_.empty()) {
    snapshots_.forgetPlaces();
    return frames;
  }
  snapshots_.updatePlaces(changes);
  for (auto it = streams_.begin(); it != streams_.end();) {
    if (it->second.wantsShared()) {
      frames.push_back({it->first, snapshots_.full()});
      it = streams_.erase(it);
    } else {
      frames.push_back({it->first, snapshots_.personalDelta(it->second, changes)});
      ++it;
    }
  }
  return frames;
}

void Room::broadcastEvents() {
  for (v1::ServerMessage& message : simulation_.takeEvents()) {
    wire::shiftPositions(message, simulation_.world().origin());
    outbox_.emplace_back(EventsBroadcast{wire::encodeSharedFrame(message), eventSubscribers_});
  }
}

void Room::subscribeEvents(std::uint32_t client, bool enabled) {
  const auto place = std::ranges::lower_bound(eventSubscribers_, client);
  const bool listed = place != eventSubscribers_.end() && *place == client;
  if (enabled && !listed) eventSubscribers_.insert(place, client);
  if (!enabled && listed) eventSubscribers_.erase(place);
  simulation_.setEventsWanted(!eventSubscribers_.empty());
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
  stats.set_last_snapshot_bytes(lastSnapshotBytes_);
  if (withStateHash) stats.set_state_hash(simulation_.stateHash());
  stats.set_bodies_left_world(simulation_.bodiesLeftWorld());
  stats.set_guard_repairs(simulation_.world().guardReport().repairedBodies);
  stats.set_commands_queued(commands_.size() + stamped_.size());
  stats.set_scaled_steps_dropped(scaledStepsDropped_);
  return stats;
}

void Room::logStats(Clock::time_point now) {
  if (now - lastStatsLog_ < kStatsLogInterval) return;
  lastStatsLog_ = now;
  const auto s = stats(false);
  logLine("room " + name_ + ": tick " + std::to_string(simulation_.tick()) + ": tick " +
          std::to_string(s.mean_tick_ms()) + " ms mean, " + std::to_string(s.max_tick_ms()) +
          " ms max; " + std::to_string(s.bodies()) + " bodies (" +
          std::to_string(s.awake_bodies()) + " awake); " + std::to_string(clients_.size()) +
          " clients; " + std::to_string(s.ticks_skipped()) + " ticks skipped");
}

void Room::publish() {
  publishedTick_ = simulation_.tick();
  publishedBodies_ = std::uint32_t(simulation_.world().bodyCount());
}

}  // namespace impulse::server
