#pragma once
/// Snapshots carry simulated time, which runs `time_scale` times as fast as
/// wall time (SetTimeScale). The playout clock steers by arrival times, so
/// it needs a time that runs with the wall clock at any scale: this maps
/// each snapshot's simulated time to such a playout time, and back, linear
/// between snapshots. At 1x the two are the same number.
///
/// Pure logic: times are plain seconds.

#include <deque>

namespace impulse::viewer {

class PlayoutTimeBase {
 public:
  /// A snapshot at `simTime` sent while the server ran at `scale` (0, an
  /// older server that sends none, means 1): its playout time.
  double onSnapshot(double simTime, double scale);
  /// The simulated time to show at playout time `playout`.
  double toSim(double playout) const;
  /// Forgets everything (a new connection).
  void reset() { anchors_.clear(); }

 private:
  struct Anchor {
    double playout;
    double sim;
    double scale;
  };
  /// The last snapshots, oldest first: enough to cover the playout delay.
  std::deque<Anchor> anchors_;
};

}  // namespace impulse::viewer
