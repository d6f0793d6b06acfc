#pragma once
// Small pieces the scene files share.

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "penetration.h"
#include "scene.h"

namespace bench {

inline double distance(const Vec2d& a, const Vec2d& b) { return std::hypot(a.x - b.x, a.y - b.y); }
inline double speed(const Pose& pose) { return std::hypot(pose.velocity.x, pose.velocity.y); }
inline double mass(const BodyDesc& body) { return body.density * body.shape.area(); }

/// The largest speed among `bodies`.
inline double fastest(const EngineAdapter& engine, const std::vector<int>& bodies) {
  double most = 0;
  for (int i : bodies) most = std::max(most, speed(engine.pose(i)));
  return most;
}

/// A static ground slab whose top is at y = 0.
inline int addGround(SceneDescription& scene, double halfWidth,
                     impulse::Material material = impulse::Material::Solid) {
  return addBody(scene, makeStaticBox({-halfWidth, -1}, {halfWidth, 0}, material));
}

/// A unit-box pyramid of `rows` rows standing on y = 0 at `pitch` spacing;
/// returns the index of its first box (bottom row first, top box last).
inline int addPyramid(SceneDescription& scene, int rows, double pitch, impulse::Material material) {
  int first = static_cast<int>(scene.bodies.size());
  for (int row = 0; row < rows; ++row) {
    int count = rows - row;
    for (int i = 0; i < count; ++i) {
      double x = (i - 0.5 * (count - 1)) * pitch;
      addBody(scene, makeBody(ShapeDesc::box(0.5, 0.5), {x, 0.5 + row * pitch}, material));
    }
  }
  return first;
}

/// Every dynamic body's index.
inline std::vector<int> dynamicBodies(const SceneDescription& scene) {
  std::vector<int> indices;
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
    if (!scene.bodies[std::size_t(i)].isStatic) indices.push_back(i);
  }
  return indices;
}

/// Deepest overlap seen over all observations.
class PeakPenetration {
 public:
  explicit PeakPenetration(const SceneDescription& scene) : probe_(scene) {}
  double observe(const EngineAdapter& engine) {
    double now = probe_.maxPenetration(engine);
    peak_ = std::max(peak_, now);
    return now;
  }
  double peak() const { return peak_; }

 private:
  PenetrationProbe probe_;
  double peak_ = 0;
};

/// Overlaps that must push out gently: the fastest any body went and when
/// the last overlap deeper than twice the 5 mm slop was gone (99 s: never).
class OverlapWatch final : public Measure {
 public:
  explicit OverlapWatch(const SceneDescription& scene) : bodies_(dynamicBodies(scene)), penetration_(scene) {}
  void observe(const EngineAdapter& engine, int step) override {
    // Separated: no overlap beyond twice the 5 mm slop all engines use.
    if (penetration_.observe(engine) > 0.01) separatedAt_ = -1;
    else if (separatedAt_ < 0) separatedAt_ = (step + 1) * kDt;
    maxSpeed_ = std::max(maxSpeed_, fastest(engine, bodies_));
  }
  // Max speed first: the figure (push-out must not throw boxes).
  std::vector<Metric> results(const EngineAdapter&) override {
    return {{"max speed m/s", maxSpeed_}, {"separate s", separatedAt_ < 0 ? 99.0 : separatedAt_}};
  }

 private:
  std::vector<int> bodies_;
  PeakPenetration penetration_;
  double separatedAt_ = -1;
  double maxSpeed_ = 0;
};

/// A scene as data: its name, a function that lays it out, its run length,
/// and the Measure type that watches it (built from the description alone).
template <class Watch>
class ListedScene final : public Scene {
 public:
  ListedScene(std::string name, std::function<SceneDescription()> layout, RunLength length)
      : name_(std::move(name)), layout_(std::move(layout)), length_(length) {}
  std::string name() const override { return name_; }
  SceneDescription describe() const override { return layout_(); }
  RunLength length() const override { return length_; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  std::string name_;
  std::function<SceneDescription()> layout_;
  RunLength length_;
};

/// Appends a ListedScene run for `full`, or for `quickLength` in --quick runs.
template <class Watch>
void addListedScene(SceneList& scenes, bool quick, std::string name, std::function<SceneDescription()> layout,
                    RunLength full, RunLength quickLength) {
  scenes.push_back(
      std::make_unique<ListedScene<Watch>>(std::move(name), std::move(layout), quick ? quickLength : full));
}

}  // namespace bench
