#include "interpolation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impulse::viewer {

namespace {

// Merge-joins two id-sorted lists: calls both(a, b), onlyA(a) or onlyB(b).
template <class Both, class OnlyA, class OnlyB>
void joinById(const std::vector<BodySample>& a, const std::vector<BodySample>& b, Both both,
              OnlyA onlyA, OnlyB onlyB) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].id < b[j].id)) {
      onlyA(a[i++]);
    } else if (i == a.size() || b[j].id < a[i].id) {
      onlyB(b[j++]);
    } else {
      both(a[i++], b[j++]);
    }
  }
}

BodySample extrapolate(const BodySample& body, double dt) {
  BodySample out = body;
  if (!body.awake) return out;
  out.position += body.velocity * Real(dt);
  out.angle += body.angularVelocity * Real(dt);
  return out;
}

}  // namespace

Real interpolateAngle(Real a, Real b, Real t, Real expectedTurn) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  const double turn =
      expectedTurn + std::remainder(double(b) - double(a) - double(expectedTurn), kTwoPi);
  return Real(double(a) + turn * double(t));
}

bool isTeleport(const BodySample& a, const BodySample& b, double dt, Real slack) {
  // Contacts change velocities within an interval, so the faster of the two
  // bounds how far the body can have travelled.
  const Real fastest = std::max(a.velocity.norm(), b.velocity.norm());
  return (b.position - a.position).norm() > fastest * Real(dt) + slack;
}

SnapshotBuffer::SnapshotBuffer(InterpolationSettings settings) : settings_(settings) {}

void SnapshotBuffer::push(SnapshotFrame frame) {
  if (!frames_.empty()) {
    if (frame.time < frames_.back().time) {
      frames_.clear();
    } else if (frame.time == frames_.back().time) {
      // The same tick again (e.g. a full snapshot after a preset load while
      // paused): the later message is the truth.
      frame.full = frame.full || frames_.back().full;
      frames_.back() = std::move(frame);
      return;
    }
  }
  frames_.push_back(std::move(frame));
  while (frames_.size() > settings_.maxFrames) frames_.pop_front();
}

void SnapshotBuffer::reset() { frames_.clear(); }

void SnapshotBuffer::discardBefore(double time) {
  // Keep the last frame at or before `time`: it is the left end of the
  // interval that `time` falls in.
  while (frames_.size() >= 2 && frames_[1].time <= time) frames_.pop_front();
}

double SnapshotBuffer::oldestTime() const { return frames_.empty() ? 0 : frames_.front().time; }
double SnapshotBuffer::newestTime() const { return frames_.empty() ? 0 : frames_.back().time; }

SampleMode SnapshotBuffer::sample(double time, std::vector<BodySample>& out) const {
  out.clear();
  if (frames_.empty()) return SampleMode::Empty;
  if (time <= frames_.front().time) {
    out = frames_.front().bodies;
    return SampleMode::BeforeOldest;
  }
  const SnapshotFrame& last = frames_.back();
  if (time >= last.time) {
    const double past = time - last.time;
    const double dt = last.paused ? 0.0 : std::min(past, settings_.snapshotInterval);
    out.reserve(last.bodies.size());
    for (const BodySample& body : last.bodies) out.push_back(extrapolate(body, dt));
    return past <= settings_.snapshotInterval ? SampleMode::Extrapolated : SampleMode::Held;
  }

  // The first frame after `time`, and the one before it.
  const auto after = std::upper_bound(frames_.begin(), frames_.end(), time,
                                      [](double t, const SnapshotFrame& f) { return t < f.time; });
  const SnapshotFrame& b = *after;
  const SnapshotFrame& a = *(after - 1);
  if (b.full) {
    out = a.bodies;
    return SampleMode::Interpolated;
  }
  const double dt = b.time - a.time;
  const Real t = Real((time - a.time) / dt);
  out.reserve(std::max(a.bodies.size(), b.bodies.size()));
  joinById(
      a.bodies, b.bodies,
      [&](const BodySample& sa, const BodySample& sb) {
        if (isTeleport(sa, sb, dt, settings_.teleportSlack)) {
          out.push_back(sa);
          return;
        }
        BodySample s = sb;
        s.position = sa.position + (sb.position - sa.position) * t;
        const Real expectedTurn = Real(0.5 * (sa.angularVelocity + sb.angularVelocity) * dt);
        s.angle = interpolateAngle(sa.angle, sb.angle, t, expectedTurn);
        s.velocity = sa.velocity + (sb.velocity - sa.velocity) * t;
        s.angularVelocity = sa.angularVelocity + (sb.angularVelocity - sa.angularVelocity) * t;
        s.awake = sa.awake || sb.awake;
        out.push_back(s);
      },
      // Removed in b: it still exists until b's time.
      [&](const BodySample& sa) { out.push_back(sa); },
      // Added in b: it does not exist before b's time.
      [](const BodySample&) {});
  return SampleMode::Interpolated;
}

}  // namespace impulse::viewer
