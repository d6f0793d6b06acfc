#include "impulse/client/predictor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "impulse/client/client.h"
#include "impulse/client/commands.h"
#include "impulse/client/number_format.h"
#include "local_world.h"

namespace impulse::client {

namespace {

/// Offsets smaller than this (m, rad) are dropped: nothing left to see.
constexpr Real kNegligibleOffset = Real(1e-4);

/// A point of the welcome, relative to the room's origin (in double first).
Vec2 relativeToOrigin(const v1::Vec2& point, const v1::Welcome& welcome) {
  return Vec2(Real(point.x() - welcome.world_origin().x()), Real(point.y() - welcome.world_origin().y()));
}

WorldSettings settingsOf(const v1::Welcome& welcome, const PredictionOptions& options) {
  WorldSettings settings;
  settings.subSteps = options.subSteps;
  // The copy computes around the room's origin, as the room does.
  settings.bounds = AABB{relativeToOrigin(welcome.world_min(), welcome), relativeToOrigin(welcome.world_max(), welcome)};
  if (welcome.max_bodies() > 0) settings.maxBodies = int(welcome.max_bodies());
  return settings;
}

std::string outside(std::string_view field, double value, std::string_view range) {
  return "PredictionOptions::" + std::string(field) + " " + formatNumber(value) + " is outside " + std::string(range);
}

/// Why a snapshot that withheld states cannot be predicted from.
std::string withheldStates(std::uint64_t tick, std::uint32_t states) {
  return "Predictor: the snapshot of tick " + std::to_string(tick) + " withheld " + std::to_string(states) +
         " body states (states_withheld: a bandwidth budget too small for the area); the copy needs every "
         "change of its area in every snapshot: raise the budget, narrow the area or stop predicting";
}

/// The client, once it takes snapshots and the options are in range;
/// std::invalid_argument naming what is not.
Client& validated(Client& client, const PredictionOptions& options) {
  if (client.mirror().snapshotsApplied() == 0) {
    throw std::invalid_argument("Predictor: the client takes no snapshots (ConnectOptions::wantSnapshots)");
  }
  if (client.lastSnapshot() && client.lastSnapshot()->states_withheld() > 0) {
    throw std::invalid_argument(withheldStates(client.lastSnapshot()->tick(), client.lastSnapshot()->states_withheld()));
  }
  const std::uint32_t bound = client.welcome().max_input_delay_ticks();
  if (options.leadTicks == 0 || options.leadTicks > bound) {
    throw std::invalid_argument(outside("leadTicks", options.leadTicks,
                                        "1.." + std::to_string(bound) + " (Welcome.max_input_delay_ticks)"));
  }
  if (!(options.blendPerTick > 0 && options.blendPerTick <= 1)) {
    throw std::invalid_argument(outside("blendPerTick", options.blendPerTick, "(0, 1]"));
  }
  if (!(options.snapDistance > 0 && std::isfinite(options.snapDistance))) {
    throw std::invalid_argument(outside("snapDistance", options.snapDistance, "(0, inf) m"));
  }
  if (options.subSteps < 1 || options.subSteps > 64) {
    throw std::invalid_argument(outside("subSteps", options.subSteps, "1..64"));
  }
  return client;
}

/// The tag an UpdateJoint or RemoveJoint names its joint by (0: its id).
std::uint32_t jointTagOf(const v1::ClientMessage& message) {
  if (message.has_update_joint()) return message.update_joint().joint_tag();
  if (message.has_remove_joint()) return message.remove_joint().joint_tag();
  return 0;
}

/// The angle in (-pi, pi]: a turn through the shorter way.
Real wrapAngle(Real angle) {
  return std::remainder(angle, Real(2 * std::numbers::pi));
}

}  // namespace

Predictor::Predictor(Client& client, const PredictionOptions& options)
    : client_(validated(client, options)),
      options_(options),
      dt_(Real(1.0 / client.welcome().tick_hz())),
      local_(std::make_unique<LocalWorld>(settingsOf(client.welcome(), options))) {
  const WorldMirror& mirror = client_.mirror();
  snapshotsSeen_ = mirror.snapshotsApplied();
  withheldSeen_ = client_.withheldSnapshots().snapshots;
  snapshotTick_ = mirror.tick();
  tick_ = snapshotTick_ + options_.leadTicks;
  local_->rebuild(mirror);
  replayFrom(snapshotTick_);
}

Predictor::~Predictor() = default;

std::uint64_t Predictor::send(v1::ClientMessage message) {
  // A paused room never reaches a stamped tick: the command goes unstamped,
  // applied at once, and shows with the snapshot it changes.
  if (client_.mirror().paused()) return client_.send(std::move(message));
  message.set_for_tick(tick_);
  const std::uint64_t id = client_.send(message);
  if (message.has_create_joint() && message.create_joint().tag() != 0) rememberTag(message.create_joint(), id);
  if (const auto named = bodyNamedBy(message)) touched_[*named] = tick_;
  pending_.push_back({id, tick_, std::move(message)});
  if (LocalWorld::predictsKind(pending_.back().message)) applyToCopy(pending_.back());
  return id;
}

void Predictor::rememberTag(const v1::CreateJoint& joint, std::uint64_t requestId) {
  tags_[joint.tag()] = {requestId, joint.body_a()};
  if (tags_.size() <= kKeptTags) return;
  const auto oldest = std::ranges::min_element(tags_, {}, [](const auto& entry) { return entry.second.requestId; });
  tags_.erase(oldest);
}

std::optional<std::uint32_t> Predictor::taggedJoint(std::uint32_t tag) const {
  const auto it = tags_.find(tag);
  const auto created = it == tags_.end() ? std::nullopt : client_.created(it->second.requestId);
  if (!created || created->joint == 0) return std::nullopt;
  return created->joint;
}

void Predictor::applyToCopy(const Command& command) {
  const v1::ClientMessage& message = command.message;
  const std::uint32_t tag = jointTagOf(message);
  // Once the server's joint is in the copy (rebuilt from a snapshot that
  // holds it), the tag names it by its id; before, the copy's own joint.
  const auto server = tag != 0 ? taggedJoint(tag) : std::nullopt;
  if (!server || !local_->localJoint(*server)) {
    local_->apply(message, dt_, command.requestId);
    return;
  }
  local_->apply(byJointId(message, *server), dt_, command.requestId);
}

bool Predictor::predicts(const v1::ClientMessage& message) { return LocalWorld::predictsKind(message); }

std::optional<std::uint32_t> Predictor::bodyNamedBy(const v1::ClientMessage& message) const {
  if (const auto body = LocalWorld::namedBody(message)) return body;
  // A joint moved or removed: its body (a mouse joint's, the one dragged).
  if (const auto tagged = tags_.find(jointTagOf(message)); tagged != tags_.end()) return tagged->second.bodyA;
  const std::uint32_t joint = message.has_update_joint()   ? message.update_joint().joint_id()
                              : message.has_remove_joint() ? message.remove_joint().joint_id()
                                                           : 0;
  const auto& joints = client_.mirror().joints();
  const auto found = joints.find(joint);
  if (found == joints.end()) return std::nullopt;
  return found->second.bodyA.value;
}

void Predictor::advance() {
  if (client_.mirror().snapshotsApplied() != snapshotsSeen_ && client_.lastSnapshot()) {
    snapshotsSeen_ = client_.mirror().snapshotsApplied();
    // A withheld state, in the newest snapshot or one before it, leaves the
    // mirror's older one: replaying from it would undo what the copy
    // stepped since.
    const Client::WithheldSnapshots& withheld = client_.withheldSnapshots();
    if (withheld.snapshots != withheldSeen_) throw PredictionError(withheldStates(withheld.lastTick, withheld.lastStates));
    takeSnapshot(*client_.lastSnapshot());
  }
  // The room does not step while paused; and a copy twice its lead ahead of
  // the snapshots runs faster than the room: it waits for them.
  if (client_.mirror().paused() || tick_ >= snapshotTick_ + 2 * std::uint64_t(options_.leadTicks)) return;
  stepOnce();
  fadeOffsets();
}

void Predictor::fadeOffsets() {
  const Real keep = Real(1 - options_.blendPerTick);
  for (auto it = offsets_.begin(); it != offsets_.end();) {
    Offset& offset = it->second;
    offset.position *= keep;
    offset.angle *= keep;
    const bool negligible = offset.position.norm() < kNegligibleOffset && std::abs(offset.angle) < kNegligibleOffset;
    it = negligible ? offsets_.erase(it) : std::next(it);
  }
}

void Predictor::takeSnapshot(const v1::Snapshot& snapshot) {
  const std::uint64_t tick = snapshot.tick();
  snapshotTick_ = tick;
  ++snapshotsTaken_;
  // Spawns the snapshot acknowledges leave pending_: their bodies first.
  auto before = answeredSpawns();
  acknowledge(snapshot);
  before.merge(ownedStates());
  // A copy fallen behind its lead (a slow caller, a late first snapshot)
  // jumps ahead; stamps never go back, so one ahead keeps its tick.
  constexpr std::uint64_t kLagAllowed = 2;
  const std::uint64_t wanted = tick + options_.leadTicks;
  if (tick_ + kLagAllowed < wanted || tick_ < tick) tick_ = wanted;
  rewindTo(tick);
  replayFrom(tick);
  blendCorrections(before);
}

void Predictor::acknowledge(const v1::Snapshot& snapshot) {
  const std::uint32_t self = client_.welcome().client_id();
  std::uint64_t applied = 0;
  for (const auto& stamp : snapshot.applied_stamps()) {
    if (stamp.client_id() == self) applied = stamp.request_id();
  }
  // A stamp the server refused on arrival is never listed: once past the
  // server's bound it can no longer be applied.
  const std::uint64_t bound = client_.welcome().max_input_delay_ticks();
  for (const Command& command : pending_) {
    if (command.requestId <= applied) rememberTarget(command.message);
  }
  std::erase_if(pending_, [&](const Command& command) {
    return command.requestId <= applied || command.forTick + bound < snapshot.tick();
  });
}

void Predictor::rememberTarget(const v1::ClientMessage& message) {
  if (!message.has_update_joint() || !message.update_joint().has_target()) return;
  const std::uint32_t tag = message.update_joint().joint_tag();
  const auto joint = tag != 0 ? taggedJoint(tag) : std::optional(message.update_joint().joint_id());
  if (joint) targets_[*joint] = byJointId(message, *joint);
}

void Predictor::restoreTargets() {
  std::erase_if(targets_, [&](const auto& entry) { return !local_->localJoint(entry.first); });
  for (const auto& [joint, update] : targets_) local_->apply(update, dt_);
}

void Predictor::rewindTo(std::uint64_t tick) {
  const WorldMirror& mirror = client_.mirror();
  while (!history_.empty() && history_.front().first < tick) history_.pop_front();
  bool own = !history_.empty() && history_.front().first == tick && local_->describes(mirror) &&
             local_->world().importState(history_.front().second).ok();
  // Bodies or joints predicted before the snapshot's tick and not in it
  // yet (late commands) would be made twice by the replay.
  own = own && local_->predictedBodies() == 0 && local_->predictedJoints() == 0;
  if (own) {
    local_->takeStates(mirror);
  } else {
    local_->rebuild(mirror);
    restoreTargets();
    ++rebuilds_;
  }
  history_.clear();
}

void Predictor::replayFrom(std::uint64_t from) {
  for (std::uint64_t tick = from;; ++tick) {
    history_.emplace_back(tick, local_->world().exportState());
    for (const Command& command : pending_) {
      // Commands stamped before the first tick replayed were late: the
      // server applies them now, so the copy does too.
      if (command.forTick == tick || (tick == from && command.forTick < from)) applyToCopy(command);
    }
    if (tick == tick_) return;
    local_->world().step(dt_);
  }
}

void Predictor::stepOnce() {
  local_->world().step(dt_);
  ++tick_;
  history_.emplace_back(tick_, local_->world().exportState());
  // A copy holds at most twice its lead ahead of the last snapshot (advance).
  while (history_.size() > 2 * std::size_t(options_.leadTicks) + 2) history_.pop_front();
}

std::map<std::uint32_t, BodyState> Predictor::ownedStates() const {
  std::map<std::uint32_t, BodyState> states;
  for (const auto& entry : touched_) {
    if (!owns(entry.first)) continue;
    const auto local = local_->localBody(entry.first);
    if (const auto state = local ? local_->world().bodyState(*local) : std::nullopt) states[entry.first] = *state;
  }
  return states;
}

std::map<std::uint32_t, BodyState> Predictor::answeredSpawns() {
  std::map<std::uint32_t, BodyState> states;
  for (const Command& command : pending_) {
    const auto created = client_.created(command.requestId);
    const auto local = local_->localSpawn(command.requestId);
    const auto state = local ? local_->world().bodyState(*local) : std::nullopt;
    if (!created || created->body == 0 || !state) continue;
    states[created->body] = *state;
    touched_[created->body] = command.forTick;
  }
  return states;
}

void Predictor::blendCorrections(const std::map<std::uint32_t, BodyState>& before) {
  lastCorrection_ = 0;
  for (const auto& [id, old] : before) {
    const auto local = local_->localBody(id);
    const auto now = local ? local_->world().bodyState(*local) : std::nullopt;
    if (!now) continue;
    const Vec2 jump = old.position - now->position;
    lastCorrection_ = std::max(lastCorrection_, double(jump.norm()));
    Offset& offset = offsets_[id];
    offset.position += jump;
    offset.angle = wrapAngle(offset.angle + wrapAngle(old.angle - now->angle));
    if (offset.position.norm() > options_.snapDistance) offset = {};
  }
  largestCorrection_ = std::max(largestCorrection_, lastCorrection_);
}

std::optional<PredictedBody> Predictor::body(std::uint32_t serverBody) const {
  const auto local = local_->localBody(serverBody);
  const auto state = local ? local_->world().bodyState(*local) : std::nullopt;
  if (!state) return std::nullopt;
  PredictedBody shown{*state, Vec2::Zero()};
  shown.state.id = BodyId{serverBody};
  if (const auto offset = offsets_.find(serverBody); offset != offsets_.end()) {
    shown.state.position += offset->second.position;
    shown.state.angle += offset->second.angle;
    shown.correction = offset->second.position;
  }
  return shown;
}

std::optional<PredictedBody> Predictor::spawned(std::uint64_t requestId) const {
  const auto local = local_->localSpawn(requestId);
  const auto state = local ? local_->world().bodyState(*local) : std::nullopt;
  if (!state) return std::nullopt;
  PredictedBody shown{*state, Vec2::Zero()};
  shown.state.id = BodyId{};
  return shown;
}

std::vector<PredictedSpawn> Predictor::unmatchedSpawns() const {
  std::vector<PredictedSpawn> spawns;
  for (const Command& command : pending_) {
    const auto local = local_->localSpawn(command.requestId);
    auto description = local ? local_->world().bodyDescription(*local) : std::nullopt;
    const auto shown = spawned(command.requestId);
    if (description && shown) spawns.push_back({command.requestId, *shown, std::move(*description)});
  }
  return spawns;
}

bool Predictor::owns(std::uint32_t serverBody) const {
  const auto it = touched_.find(serverBody);
  return it != touched_.end() && tick_ <= it->second + options_.holdTicks;
}

std::vector<std::uint32_t> Predictor::ownedBodies() const {
  std::vector<std::uint32_t> owned;
  for (const auto& entry : touched_) {
    if (owns(entry.first)) owned.push_back(entry.first);
  }
  return owned;
}

double Predictor::shownCorrection() const {
  double largest = 0;
  for (const auto& [id, offset] : offsets_) {
    if (owns(id)) largest = std::max(largest, double(offset.position.norm()));
  }
  return largest;
}

}  // namespace impulse::client
