#include "playout_clock.h"

#include <algorithm>
#include <cmath>

namespace impulse::viewer {

PlayoutClock::PlayoutClock(PlayoutSettings settings) : settings_(settings) {}

void PlayoutClock::reset() {
  samples_.clear();
  paused_ = false;
  clockRunning_ = false;
  clock_ = 0;
  lastNow_ = 0;
  latestServerTime_ = 0;
}

void PlayoutClock::onSnapshot(double serverTime, double arrival, bool paused) {
  latestServerTime_ = serverTime;
  if (paused) {
    // Server time stood still while the local clock ran: these arrivals say
    // nothing about the link. Timing restarts when the server runs again.
    paused_ = true;
    if (samples_.empty()) samples_.push_back({serverTime, arrival - serverTime});
    return;
  }
  if (paused_ || (!samples_.empty() && serverTime < samples_.back().serverTime)) {
    samples_.clear();
    clockRunning_ = false;
    paused_ = false;
  }
  samples_.push_back({serverTime, arrival - serverTime});
  while (samples_.size() > settings_.window) samples_.pop_front();
}

double PlayoutClock::offset() const {
  double best = samples_.empty() ? 0 : samples_.front().offset;
  for (const Sample& s : samples_) best = std::min(best, s.offset);
  return best;
}

double PlayoutClock::lateness() const {
  if (samples_.empty()) return 0;
  const double base = offset();
  double worst = 0;
  for (const Sample& s : samples_) worst = std::max(worst, s.offset - base);
  return worst;
}

double PlayoutClock::delay() const {
  const double interval = settings_.snapshotInterval;
  const double wanted =
      interval + lateness() * settings_.latenessFactor + settings_.marginSeconds;
  return std::clamp(wanted, settings_.minDelayIntervals * interval,
                    settings_.maxDelayIntervals * interval);
}

double PlayoutClock::renderTime(double now) {
  if (samples_.empty()) return 0;
  if (paused_) {
    // Nothing moves on the server: show its latest state as it arrives.
    clockRunning_ = false;
    lastNow_ = now;
    return latestServerTime_;
  }
  const double target = now - offset() - delay();
  const double dt = std::max(0.0, now - lastNow_);
  lastNow_ = now;
  if (!clockRunning_ || std::abs(target - clock_) > settings_.snapSeconds) {
    clock_ = target;
    clockRunning_ = true;
    return clock_;
  }
  const double error = target - (clock_ + dt);
  const double rate =
      1 + std::clamp(error * settings_.slewGain, -settings_.maxSlew, settings_.maxSlew);
  clock_ += dt * rate;
  return clock_;
}

}  // namespace impulse::viewer
