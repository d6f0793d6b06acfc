// Five boxes, each on its own 0.25 rad ramp, released at rest, with friction
// 0.75 / 0.5 / 0.35 / 0.1 / 0 on both box and ramp (so the pair's coefficient
// is that value whatever an engine's mixing rule). A box holds when its
// coefficient reaches tan(0.25) = 0.2553, else it slides
// d = g (sin - mu cos) t^2 / 2. Every engine gets the one coefficient (Impulse
// uses it as both its static and dynamic friction), so all share one closed form.

#include <cstdio>

#include "scene_helpers.h"

namespace bench {

namespace {

constexpr double kAngle = 0.25;
constexpr double kHalfLength = 7;
constexpr double kHalfThickness = 0.25;
constexpr double kGravity = 9.81;
constexpr double kFrictions[] = {0.75, 0.5, 0.35, 0.1, 0.0};
constexpr int kRampCount = int(std::size(kFrictions));

BodyDesc withFriction(BodyDesc body, double friction) {
  body.friction = friction;
  return body;
}

SceneDescription frictionRamps() {
  SceneDescription scene;
  const Vec2d up{std::cos(kAngle), std::sin(kAngle)};
  const Vec2d normal{-std::sin(kAngle), std::cos(kAngle)};
  for (int i = 0; i < kRampCount; ++i) {
    Vec2d centre{0, 10.0 * i};
    BodyDesc ramp = withFriction(
        makeBody(ShapeDesc::box(kHalfLength, kHalfThickness), centre, impulse::Material::Wood, true),
        kFrictions[i]);
    ramp.angle = kAngle;
    addBody(scene, ramp);
    double along = kHalfLength - 1.5, off = kHalfThickness + 0.5;
    BodyDesc box = withFriction(
        makeBody(ShapeDesc::box(0.5, 0.5),
                 {centre.x + along * up.x + off * normal.x, centre.y + along * up.y + off * normal.y},
                 impulse::Material::Wood),
        kFrictions[i]);
    box.angle = kAngle;
    addBody(scene, box);
  }
  return scene;
}

class RampWatch final : public Measure {
 public:
  explicit RampWatch(const SceneDescription& scene) : scene_(scene) {}
  void observe(const EngineAdapter&, int step) override { time_ = (step + 1) * kDt; }
  std::vector<Metric> results(const EngineAdapter& engine) override {
    const Vec2d up{std::cos(kAngle), std::sin(kAngle)};
    double worst = 0;
    int matches = 0;
    std::vector<Metric> slides;
    for (int i = 0; i < kRampCount; ++i) {
      const double mu = kFrictions[i];
      bool holds = mu >= std::tan(kAngle);
      double expected = holds ? 0 : 0.5 * kGravity * (std::sin(kAngle) - mu * std::cos(kAngle)) * time_ * time_;
      const Vec2d& start = scene_.bodies[std::size_t(2 * i + 1)].position;
      Vec2d now = engine.pose(2 * i + 1).position;
      double slid = -((now.x - start.x) * up.x + (now.y - start.y) * up.y);
      worst = std::max(worst, std::abs(slid - expected));
      if ((slid < 0.05) == holds) ++matches;
      char label[32];
      std::snprintf(label, sizeof label, "slid@%.3g m", mu);
      slides.push_back({label, slid});
    }
    std::vector<Metric> metrics = {{"slide err m", worst}, {"right stick/slide", double(matches)}};
    metrics.insert(metrics.end(), slides.begin(), slides.end());
    return metrics;
  }

 private:
  const SceneDescription& scene_;
  double time_ = 0;
};

}  // namespace

void addFrictionRampScene(SceneList& scenes, bool quick) {
  addListedScene<RampWatch>(scenes, quick, "friction-ramp", frictionRamps, {0, 120, 3, 120}, {0, 5, 1, 5});
}

}  // namespace bench
