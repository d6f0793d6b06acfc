#pragma once
/// The world as the viewer draws it: each snapshot the client applies is
/// recorded into the snapshot buffer, timed by the playout clock, and each
/// frame samples the buffer at the playout time. Shapes and materials are
/// kept for as long as a buffered frame still shows their body.
///
/// Body ids start over when the world is replaced (preset, clear, scene), so
/// one id may name one body in older frames and another in newer ones: each
/// frame is drawn with the looks in force at its time.

#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include "impulse.pb.h"
#include "impulse/client/predictor.h"
#include "impulse/client/world_mirror.h"
#include "interpolation.h"
#include "playout_clock.h"
#include "playout_time_base.h"

namespace impulse::viewer {

/// How a body looks (what its descriptor said).
struct BodyLook {
  Shape shape;
  /// A compound body's further shapes.
  std::vector<Shape> extraShapes{};
  Material material = Material::Solid;
  bool isStatic = false;
  bool isKinematic = false;
  bool ignoreGravity = false;
  /// The first shape's filter, sensor flag and events (a body made over the
  /// wire gives every shape the same).
  ShapeInteraction flags{};
  /// Every shape's id (events and queries name them), in the order shape,
  /// extraShapes.
  std::vector<std::uint32_t> shapeIds{};
};

/// The look of a body as the client's mirror describes it.
BodyLook lookOf(const client::MirrorBody& body);
/// The look of a body as an engine world describes it (a predicted spawn).
BodyLook lookOf(const BodyDescription& body);

/// One body to draw.
struct DrawnBody {
  BodySample state;
  const BodyLook* look = nullptr;
};

class InterpolatedWorld {
 public:
  explicit InterpolatedWorld(double snapshotInterval = 1.0 / 30.0);

  /// `mirror` has just applied `snapshot`, which arrived at local time `now`.
  void onSnapshot(const client::WorldMirror& mirror, const v1::Snapshot& snapshot, double now);
  /// The mirror as it stands (the first snapshot, applied during connection).
  void seed(const client::WorldMirror& mirror, double now);
  /// A new connection: forgets everything.
  void reset(double snapshotInterval);

  /// Samples the world for a frame drawn at local time `now`.
  void update(double now);
  /// After update(): the bodies the predictor owns (the viewer's own drags,
  /// pushes and spawns) are drawn where it predicts them, correction
  /// included; the others stay as sampled. Returns how many it moved. Its
  /// spawns the server has not brought yet are spawnedBodies() until the
  /// next update().
  std::size_t showPredicted(const client::Predictor& predictor);
  /// The viewer's own spawns before the server's snapshot brings them (id
  /// 0: nothing to select or inspect yet).
  const std::vector<DrawnBody>& spawnedBodies() const { return spawned_; }
  /// In ascending id, as the snapshot frames hold them.
  const std::vector<DrawnBody>& bodies() const { return drawn_; }
  /// The drawn state of body `id`, or null when it is not drawn.
  const BodySample* find(std::uint32_t id) const;
  /// The drawn body `id` with its look, or null when it is not drawn.
  const DrawnBody* findDrawn(std::uint32_t id) const;
  SampleMode lastMode() const { return mode_; }
  /// The simulated time drawn.
  double renderTime() const { return renderTime_; }

  const SnapshotBuffer& buffer() const { return buffer_; }
  const PlayoutClock& clock() const { return clock_; }

 private:
  void record(const client::WorldMirror& mirror, double serverTime, double timeScale, bool full,
              bool paused, double now);
  /// Snapshots come at most every `dt / scale` wall seconds below 1x (one
  /// step per 1/scale ticks): the playout delay must cover that gap.
  void fitSnapshotInterval(const client::WorldMirror& mirror, double timeScale);

  SnapshotBuffer buffer_;
  PlayoutClock clock_;
  PlayoutTimeBase timeBase_;
  double snapshotInterval_;
  double timeScale_ = 1;
  using Looks = std::unordered_map<std::uint32_t, BodyLook>;
  /// Looks of bodies gone from the server by server time `until`: a full
  /// snapshot retires every look at once, a removal one.
  struct RetiredLooks {
    double until;
    Looks looks;
  };
  /// The look of body `id` in frames sampled at server time `time`, or null.
  const BodyLook* lookAt(std::uint32_t id, double time) const;
  void retire(std::uint32_t id, double time);
  /// A snapshot between two frames moves or frees looks (a removal moves
  /// one into the retired ones) while the frame's drawn bodies are still
  /// read (picking, the energy plot): they are pointed at the looks anew.
  void relinkDrawnLooks();
  /// The predictor's unmatched spawns into spawned_.
  void showSpawns(const client::Predictor& predictor);

  /// The bodies of the newest snapshot.
  Looks looks_;
  /// Oldest first; dropped once no buffered frame is older.
  std::deque<RetiredLooks> retired_;
  std::vector<BodySample> samples_;
  /// Their looks point into looks_ and retired_, relinked whenever those change.
  std::vector<DrawnBody> drawn_;
  SampleMode mode_ = SampleMode::Empty;
  double renderTime_ = 0;
  /// The predicted spawns drawn, and their looks (which they point at).
  std::vector<BodyLook> spawnedLooks_;
  std::vector<DrawnBody> spawned_;
};

}  // namespace impulse::viewer
