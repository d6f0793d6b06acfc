// Five boxes, each on its own 0.25 rad ramp, released at rest. A box holds
// when its static coefficient reaches tan(0.25) = 0.2553, else it slides
// d = g (sin - mu_k cos) t^2 / 2. Coefficients are pair means of Materials
// (what Impulse can express); the 0.35 / 0.1 / 0 cannot be made from
// Impulse's five Materials, so the nearest pairs stand in: 0.45, the 0.265
// just above tan 0.25 (static) but 0.205 sliding, and 0.03.
// Impulse slides with the dynamic coefficient, the peers with their one
// coefficient (= Impulse's static one): each engine's error is against its
// own closed form.

#include <cstdio>

#include "scene_helpers.h"

namespace bench {

namespace {

using impulse::Material;

constexpr double kAngle = 0.25;
constexpr double kHalfLength = 7;
constexpr double kHalfThickness = 0.25;
constexpr double kGravity = 9.81;

struct RampPair {
  Material box;
  Material ramp;
};

constexpr RampPair kPairs[] = {{Material::Wood, Material::Rubber},
                               {Material::Wood, Material::Wood},
                               {Material::Solid, Material::Wood},
                               {Material::Ice, Material::Wood},
                               {Material::Ice, Material::Ice}};
constexpr int kPairCount = int(std::size(kPairs));

double mean(double a, double b) { return 0.5 * (a + b); }

class FrictionRampScene final : public Scene {
 public:
  explicit FrictionRampScene(bool quick) : quick_(quick) {}
  std::string name() const override { return "friction-ramp"; }
  SceneDescription describe() const override {
    SceneDescription scene;
    scene.name = name();
    const Vec2d up{std::cos(kAngle), std::sin(kAngle)};
    const Vec2d normal{-std::sin(kAngle), std::cos(kAngle)};
    for (int i = 0; i < kPairCount; ++i) {
      Vec2d centre{0, 10.0 * i};
      BodyDesc ramp = makeBody(ShapeDesc::box(kHalfLength, kHalfThickness), centre, kPairs[i].ramp, true);
      ramp.angle = kAngle;
      addBody(scene, ramp);
      double along = kHalfLength - 1.5, off = kHalfThickness + 0.5;
      BodyDesc box = makeBody(ShapeDesc::box(0.5, 0.5),
                              {centre.x + along * up.x + off * normal.x, centre.y + along * up.y + off * normal.y},
                              kPairs[i].box);
      box.angle = kAngle;
      addBody(scene, box);
    }
    return scene;
  }
  RunLength length() const override { return quick_ ? RunLength{0, 5, 1, 5} : RunLength{0, 120, 3, 120}; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine engine) const override {
    return std::make_unique<Watch>(scene, engine);
  }

 private:
  class Watch final : public Measure {
   public:
    Watch(const SceneDescription& scene, Engine engine) : scene_(scene), engine_(engine) {}
    void observe(const EngineAdapter&, int step) override { time_ = (step + 1) * kDt; }
    std::vector<Metric> results(const EngineAdapter& engine) override {
      const Vec2d up{std::cos(kAngle), std::sin(kAngle)};
      double worst = 0;
      int matches = 0;
      std::vector<Metric> slides;
      for (int i = 0; i < kPairCount; ++i) {
        const impulse::MaterialProperties& box = impulse::materialProperties(kPairs[i].box);
        const impulse::MaterialProperties& ramp = impulse::materialProperties(kPairs[i].ramp);
        double staticMu = mean(box.staticFriction, ramp.staticFriction);
        double slidingMu = engine_ == Engine::Impulse ? mean(box.dynamicFriction, ramp.dynamicFriction) : staticMu;
        bool holds = staticMu >= std::tan(kAngle);
        double expected =
            holds ? 0 : 0.5 * kGravity * (std::sin(kAngle) - slidingMu * std::cos(kAngle)) * time_ * time_;
        const Vec2d& start = scene_.bodies[std::size_t(2 * i + 1)].position;
        Vec2d now = engine.pose(2 * i + 1).position;
        double slid = -((now.x - start.x) * up.x + (now.y - start.y) * up.y);
        worst = std::max(worst, std::abs(slid - expected));
        if ((slid < 0.05) == holds) ++matches;
        char label[32];
        std::snprintf(label, sizeof label, "slid@%.3g m", staticMu);
        slides.push_back({label, slid});
      }
      std::vector<Metric> metrics = {{"slide err m", worst}, {"right stick/slide", double(matches)}};
      metrics.insert(metrics.end(), slides.begin(), slides.end());
      return metrics;
    }

   private:
    const SceneDescription& scene_;
    Engine engine_;
    double time_ = 0;
  };
  bool quick_;
};

}  // namespace

void addFrictionRampScene(SceneList& scenes, bool quick) {
  scenes.push_back(std::make_unique<FrictionRampScene>(quick));
}

}  // namespace bench
