#pragma once
/// Chooses the server time the viewer renders: the server's current time as
/// estimated from snapshot arrivals, minus a playout delay that covers the
/// measured jitter (at least three snapshot intervals). The rendered time
/// advances with the local clock and is steered gently (a few percent faster
/// or slower) towards its target, so the view neither jumps nor freezes when
/// snapshots arrive late or in bursts; it jumps only when far off (a preset
/// loaded while paused, a new connection).
///
/// Pure logic: local times are plain seconds passed in by the caller.

#include <cstddef>
#include <deque>

namespace impulse::viewer {

struct PlayoutSettings {
  double snapshotInterval = 1.0 / 30.0;
  /// Smallest delay, in snapshot intervals: one interval to hold the next
  /// snapshot, one for a snapshot the server skipped or TCP delayed, one for
  /// the scheduling noise of the server's tick loop and of our frame loop.
  double minDelayIntervals = 3;
  /// Largest delay, in snapshot intervals (a stalled link is not waited for
  /// beyond this: the buffer extrapolates, then holds).
  double maxDelayIntervals = 12;
  /// Delay = interval + lateness * this + margin, where lateness is the
  /// latest arrival in the window relative to the earliest.
  double latenessFactor = 1.25;
  double marginSeconds = 0.004;
  /// Arrivals the jitter is measured over (about two seconds at 30 Hz).
  std::size_t window = 60;
  /// Fastest steering: the rendered clock runs at 1 +/- this.
  double maxSlew = 0.08;
  /// Steering gain: fraction of the error removed per second.
  double slewGain = 1.0;
  /// Errors larger than this (seconds) are not steered but jumped.
  double snapSeconds = 0.5;
};

class PlayoutClock {
 public:
  explicit PlayoutClock(PlayoutSettings settings = {});

  /// A snapshot of server time `serverTime` arrived at local time `arrival`.
  /// Snapshots of a paused server carry no timing and are only noted.
  void onSnapshot(double serverTime, double arrival, bool paused = false);
  /// Server time to render at local time `now` (call once per frame, with
  /// non-decreasing `now`). Nothing sensible before the first snapshot: 0.
  double renderTime(double now);
  /// Forgets everything (a new connection).
  void reset();

  bool started() const { return !samples_.empty(); }
  bool paused() const { return paused_; }
  /// The current target delay, seconds.
  double delay() const;
  /// Latest arrival in the window relative to the earliest, seconds.
  double lateness() const;
  /// Local minus server time, from the least delayed arrival in the window.
  double offset() const;
  void setSnapshotInterval(double seconds) { settings_.snapshotInterval = seconds; }
  const PlayoutSettings& settings() const { return settings_; }

 private:
  struct Sample {
    double serverTime;
    double offset;  // arrival - serverTime
  };

  PlayoutSettings settings_;
  std::deque<Sample> samples_;
  bool paused_ = false;
  bool clockRunning_ = false;
  double clock_ = 0;    // rendered server time
  double lastNow_ = 0;  // local time of the last renderTime()
  double latestServerTime_ = 0;
};

}  // namespace impulse::viewer
