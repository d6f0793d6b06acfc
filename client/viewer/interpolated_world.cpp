#include "interpolated_world.h"

#include <algorithm>

namespace impulse::viewer {

namespace {

InterpolationSettings interpolationSettings(double interval) {
  InterpolationSettings settings;
  settings.snapshotInterval = interval;
  return settings;
}

PlayoutSettings playoutSettings(double interval) {
  PlayoutSettings settings;
  settings.snapshotInterval = interval;
  return settings;
}

}  // namespace

BodyLook lookOf(const client::MirrorBody& body) {
  return {body.shape,         body.extraShapes,   body.material, body.isStatic,
          body.isKinematic,   body.ignoreGravity, body.flags,    body.shapeIds};
}

BodyLook lookOf(const BodyDescription& body) {
  BodyLook look{.shape = body.shape,
                .material = body.material,
                .isStatic = body.properties.isStatic,
                .isKinematic = body.properties.isKinematic,
                .ignoreGravity = body.properties.ignoreGravity};
  for (std::size_t i = 0; i < body.shapes.size(); ++i) {
    if (i == 0) look.flags = body.shapes[i].interaction;
    if (i > 0) look.extraShapes.push_back(body.shapes[i].shape);
  }
  return look;
}

InterpolatedWorld::InterpolatedWorld(double snapshotInterval)
    : buffer_(interpolationSettings(snapshotInterval)),
      clock_(playoutSettings(snapshotInterval)),
      snapshotInterval_(snapshotInterval) {}

void InterpolatedWorld::reset(double snapshotInterval) {
  buffer_ = SnapshotBuffer(interpolationSettings(snapshotInterval));
  clock_ = PlayoutClock(playoutSettings(snapshotInterval));
  timeBase_.reset();
  snapshotInterval_ = snapshotInterval;
  timeScale_ = 1;
  looks_.clear();
  retired_.clear();
  drawn_.clear();
  samples_.clear();
  spawned_.clear();
  mode_ = SampleMode::Empty;
}

void InterpolatedWorld::seed(const client::WorldMirror& mirror, double now) {
  for (const auto& [id, body] : mirror.bodies()) {
    looks_[id] = lookOf(body);
  }
  record(mirror, mirror.simTime(), mirror.timeScale(), true, mirror.paused(), now);
}

void InterpolatedWorld::onSnapshot(const client::WorldMirror& mirror,
                                   const v1::Snapshot& snapshot, double now) {
  const double time = snapshot.sim_time();
  if (snapshot.full()) {
    // Every body is described again, maybe a new one under an old id.
    retired_.push_back({time, std::move(looks_)});
    looks_.clear();
  }
  for (const std::uint32_t id : snapshot.removed()) retire(id, time);
  for (const auto& descriptor : snapshot.added()) {
    if (const auto* body = mirror.find(BodyId{descriptor.id()})) {
      looks_[descriptor.id()] = lookOf(*body);
    }
  }
  relinkDrawnLooks();
  record(mirror, time, mirror.timeScale(), snapshot.full(), snapshot.paused(), now);
}

void InterpolatedWorld::relinkDrawnLooks() {
  std::erase_if(drawn_, [this](DrawnBody& body) {
    body.look = lookAt(body.state.id, renderTime_);
    return body.look == nullptr;
  });
}

void InterpolatedWorld::retire(std::uint32_t id, double time) {
  const auto it = looks_.find(id);
  if (it == looks_.end()) return;
  if (retired_.empty() || retired_.back().until != time) retired_.push_back({time, {}});
  retired_.back().looks.insert_or_assign(id, std::move(it->second));
  looks_.erase(it);
}

const BodyLook* InterpolatedWorld::lookAt(std::uint32_t id, double time) const {
  for (const RetiredLooks& retired : retired_) {
    if (time >= retired.until) continue;
    if (const auto it = retired.looks.find(id); it != retired.looks.end()) return &it->second;
  }
  const auto it = looks_.find(id);
  return it == looks_.end() ? nullptr : &it->second;
}

void InterpolatedWorld::fitSnapshotInterval(const client::WorldMirror& mirror, double timeScale) {
  if (timeScale == timeScale_ || mirror.tick() == 0) return;
  timeScale_ = timeScale;
  const double stepSeconds = mirror.simTime() / double(mirror.tick());
  clock_.setSnapshotInterval(std::max(snapshotInterval_, stepSeconds / timeScale));
}

void InterpolatedWorld::record(const client::WorldMirror& mirror, double serverTime,
                               double timeScale, bool full, bool paused, double now) {
  fitSnapshotInterval(mirror, timeScale);
  SnapshotFrame frame;
  frame.time = serverTime;
  frame.full = full;
  frame.paused = paused;
  frame.bodies.reserve(mirror.bodies().size());
  for (const auto& [id, body] : mirror.bodies()) {
    const BodyState& s = body.state;
    frame.bodies.push_back(
        {id, s.position, s.angle, s.linearVelocity, s.angularVelocity, s.awake});
  }
  buffer_.push(std::move(frame));
  clock_.onSnapshot(timeBase_.onSnapshot(serverTime, timeScale), now, paused);
}

void InterpolatedWorld::update(double now) {
  renderTime_ = timeBase_.toSim(clock_.renderTime(now));
  buffer_.discardBefore(renderTime_);
  mode_ = buffer_.sample(renderTime_, samples_);

  // A retired look is kept while a buffered frame still shows its body
  // (frames older than its retirement).
  const double oldest = buffer_.oldestTime();
  while (!retired_.empty() && retired_.front().until <= oldest) retired_.pop_front();

  spawned_.clear();
  drawn_.clear();
  drawn_.reserve(samples_.size());
  for (const BodySample& sample : samples_) {
    if (const BodyLook* look = lookAt(sample.id, renderTime_)) drawn_.push_back({sample, look});
  }
}

const DrawnBody* InterpolatedWorld::findDrawn(std::uint32_t id) const {
  const auto it = std::lower_bound(drawn_.begin(), drawn_.end(), id,
                                   [](const DrawnBody& body, std::uint32_t key) { return body.state.id < key; });
  return it != drawn_.end() && it->state.id == id ? &*it : nullptr;
}

void InterpolatedWorld::showSpawns(const client::Predictor& predictor) {
  const auto spawns = predictor.unmatchedSpawns();
  spawnedLooks_.clear();
  spawned_.clear();
  // Every look first: the drawn bodies point into the vector.
  for (const client::PredictedSpawn& spawn : spawns) spawnedLooks_.push_back(lookOf(spawn.description));
  for (std::size_t i = 0; i < spawns.size(); ++i) {
    const BodyState& state = spawns[i].body.state;
    spawned_.push_back({BodySample{0, state.position, state.angle, state.linearVelocity, state.angularVelocity,
                                   state.awake},
                        &spawnedLooks_[i]});
  }
}

const BodySample* InterpolatedWorld::find(std::uint32_t id) const {
  const DrawnBody* body = findDrawn(id);
  return body != nullptr ? &body->state : nullptr;
}

std::size_t InterpolatedWorld::showPredicted(const client::Predictor& predictor) {
  std::size_t shown = 0;
  showSpawns(predictor);
  // An owned body the playout has not reached yet (a spawn the server's
  // snapshot just brought) is drawn from the copy already: the spawn never
  // blinks out between the predicted body and the server's.
  for (const std::uint32_t id : predictor.ownedBodies()) {
    const BodyLook* look = lookAt(id, renderTime_);
    if (findDrawn(id) || !look || !predictor.body(id)) continue;
    const auto at = std::lower_bound(drawn_.begin(), drawn_.end(), id,
                                     [](const DrawnBody& body, std::uint32_t key) { return body.state.id < key; });
    drawn_.insert(at, DrawnBody{BodySample{.id = id}, look});
  }
  for (DrawnBody& body : drawn_) {
    if (!predictor.owns(body.state.id)) continue;
    const auto predicted = predictor.body(body.state.id);
    if (!predicted) continue;
    body.state.position = predicted->state.position;
    body.state.angle = predicted->state.angle;
    body.state.velocity = predicted->state.linearVelocity;
    body.state.angularVelocity = predicted->state.angularVelocity;
    body.state.awake = predicted->state.awake;
    ++shown;
  }
  return shown;
}

}  // namespace impulse::viewer
