#pragma once
/// What the viewer flashes from the server's event stream (SubscribeEvents):
/// a fading mark where two shapes hit, sized and lit by their approach
/// speed; a brief glow on a sensor's body when a shape enters it, and on
/// both bodies of a contact that began. Each flash waits until the drawn
/// (interpolated, so slightly delayed) world reaches its step's simulated
/// time, then fades out over half a second of wall time. At most
/// kMaxFlashes are kept, the oldest dropped first, so a storm of events
/// costs a bounded amount per frame.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "impulse.pb.h"
#include "impulse/math.h"

namespace impulse::viewer {

struct Flash {
  enum class Kind { Hit, ContactBegin, SensorBegin };
  Kind kind = Kind::Hit;
  /// ContactBegin and SensorBegin: the body that glows.
  std::uint32_t body = 0;
  /// Hit: where the shapes met (world) and how fast they closed (m/s).
  Vec2 point = Vec2::Zero();
  double speed = 0;
  /// Simulated time of the step that made it.
  double time = 0;
  /// Wall time it arrived, and when it began to show (< 0 while waiting
  /// for the drawn world to reach `time`).
  double arrived = 0;
  double start = -1;
};

/// A hit's mark: radius (m) and brightness (0-1).
struct HitMark {
  Real radius = 0;
  float brightness = 0;
};
/// Faster hits make larger, brighter marks: from 8 cm and 0.35 at rest to
/// 40 cm and full brightness at 16 m/s and above.
HitMark hitMark(double approachSpeed);

class EventFlashes {
 public:
  static constexpr double kFadeSeconds = 0.5;
  static constexpr std::size_t kMaxFlashes = 256;
  /// A flash the drawn world never reaches (the world was replaced and its
  /// clock started over) is dropped after this long: the playout delay is
  /// at most 5 s (at 0.01x).
  static constexpr double kMaxWaitSeconds = 6;

  /// One Events message, whose step ended at simulated time `time`,
  /// arrived at wall time `now`.
  void add(const v1::Events& events, double time, double now);
  /// Starts the flashes the drawn world has reached (`drawnTime`, simulated
  /// seconds) and drops the faded ones.
  void update(double drawnTime, double now);
  void clear() { flashes_.clear(); }

  /// Waiting and showing flashes, oldest first.
  const std::vector<Flash>& flashes() const { return flashes_; }
  /// 1 as a flash starts, falling linearly to 0 after kFadeSeconds; 0 while
  /// it waits.
  static float intensity(const Flash& flash, double now);

 private:
  void push(Flash flash);

  std::vector<Flash> flashes_;
};

}  // namespace impulse::viewer
