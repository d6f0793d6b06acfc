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
  departed_.clear();
  drawn_.clear();
  samples_.clear();
  mode_ = SampleMode::Empty;
}

void InterpolatedWorld::seed(const client::WorldMirror& mirror, double now) {
  for (const auto& [id, body] : mirror.bodies()) {
    looks_[id] = {body.shape, body.extraShapes, body.material, body.isStatic, body.isKinematic, body.ignoreGravity};
  }
  record(mirror, mirror.simTime(), mirror.timeScale(), true, mirror.paused(), now);
}

void InterpolatedWorld::onSnapshot(const client::WorldMirror& mirror,
                                   const v1::Snapshot& snapshot, double now) {
  const double time = snapshot.sim_time();
  if (snapshot.full()) {
    for (const auto& [id, look] : looks_) {
      if (mirror.bodies().count(id) == 0) departed_.emplace_back(id, time);
    }
  }
  for (const std::uint32_t id : snapshot.removed()) departed_.emplace_back(id, time);
  for (const auto& descriptor : snapshot.added()) {
    if (const auto* body = mirror.find(BodyId{descriptor.id()})) {
      looks_[descriptor.id()] = {body->shape, body->material, body->isStatic,
                                 body->ignoreGravity};
    }
  }
  record(mirror, time, mirror.timeScale(), snapshot.full(), snapshot.paused(), now);
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

  // A departed body's look is kept while a buffered frame still shows it
  // (frames older than its departure).
  const double oldest = buffer_.oldestTime();
  std::erase_if(departed_, [&](const std::pair<std::uint32_t, double>& gone) {
    if (gone.second > oldest) return false;
    looks_.erase(gone.first);
    return true;
  });

  drawn_.clear();
  drawn_.reserve(samples_.size());
  for (const BodySample& sample : samples_) {
    const auto it = looks_.find(sample.id);
    if (it != looks_.end()) drawn_.push_back({sample, &it->second});
  }
}

const BodySample* InterpolatedWorld::find(std::uint32_t id) const {
  const auto it = std::lower_bound(drawn_.begin(), drawn_.end(), id,
                                   [](const DrawnBody& body, std::uint32_t key) { return body.state.id < key; });
  return it != drawn_.end() && it->state.id == id ? &it->state : nullptr;
}

}  // namespace impulse::viewer
