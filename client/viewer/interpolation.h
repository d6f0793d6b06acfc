#pragma once
/// The snapshot buffer the viewer renders from: body states at server times,
/// sampled at any time in between (linear positions, angles along the short
/// arc), extrapolated for at most one snapshot interval past the newest, then
/// held. Teleports and full snapshots are discontinuities: they snap.
///
/// Pure logic: times are plain seconds passed in by the caller.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "impulse/math.h"

namespace impulse::viewer {

/// One body's state in one snapshot.
struct BodySample {
  std::uint32_t id = 0;
  Vec2 position = Vec2::Zero();
  Real angle = 0;
  Vec2 velocity = Vec2::Zero();
  Real angularVelocity = 0;
  bool awake = false;
};

/// Every body of the world at one server time.
struct SnapshotFrame {
  double time = 0;  ///< server simulation time, seconds
  /// A full snapshot (connect, preset load, skipped deltas): nothing is
  /// interpolated into it; its states replace the previous ones at its time.
  bool full = false;
  /// The server's clock was stopped: nothing is extrapolated past this frame.
  bool paused = false;
  std::vector<BodySample> bodies;  ///< ascending id
};

struct InterpolationSettings {
  /// Server time between snapshots, seconds (1 / snapshot_hz).
  double snapshotInterval = 1.0 / 30.0;
  /// A body that moves further than its velocities explain by more than this
  /// (metres) between two frames was teleported: it snaps.
  Real teleportSlack = Real(0.5);
  /// Frames kept at most (a bound, not a target: discardBefore trims).
  std::size_t maxFrames = 120;
};

/// How a sample was obtained (for the HUD and tests).
enum class SampleMode {
  Empty,         ///< no frame yet
  BeforeOldest,  ///< time precedes every frame: the oldest is shown
  Interpolated,  ///< between two frames
  Extrapolated,  ///< past the newest, within one interval
  Held,          ///< past the newest by more than one interval: held
};

class SnapshotBuffer {
 public:
  explicit SnapshotBuffer(InterpolationSettings settings = {});

  /// Adds the newest frame. A frame at the newest frame's time replaces it; a
  /// frame older than the newest (a restarted server) resets the buffer first.
  void push(SnapshotFrame frame);
  /// Forgets every frame (a new connection).
  void reset();
  /// Drops frames that sampling at `time` or later no longer needs.
  void discardBefore(double time);

  /// The world at server time `time`, into `out` (ascending id).
  SampleMode sample(double time, std::vector<BodySample>& out) const;

  bool empty() const { return frames_.empty(); }
  std::size_t size() const { return frames_.size(); }
  double oldestTime() const;
  double newestTime() const;
  const SnapshotFrame* newest() const { return frames_.empty() ? nullptr : &frames_.back(); }
  const InterpolationSettings& settings() const { return settings_; }
  void setSnapshotInterval(double seconds) { settings_.snapshotInterval = seconds; }

 private:
  InterpolationSettings settings_;
  std::deque<SnapshotFrame> frames_;
};

/// The turn from angle a to angle b, for t in [0, 1]: the shortest arc, or
/// with `expectedTurn` (from the angular velocities) the arc closest to it, so
/// a body spinning faster than half a turn per snapshot keeps its direction.
Real interpolateAngle(Real a, Real b, Real t, Real expectedTurn = 0);

/// Whether a body's move from `a` to `b` over `dt` seconds is a teleport.
bool isTeleport(const BodySample& a, const BodySample& b, double dt, Real slack);

}  // namespace impulse::viewer
