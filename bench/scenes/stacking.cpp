// Stacks: pyramids, an offset tower, mass-ratio cases and overlap
// recovery. Sleep is off so every step pays for the whole stack.

#include "scene_helpers.h"

namespace bench {

namespace {

using impulse::Material;

// How far the top box of a pyramid of unit boxes sinks (the issue's "top box
// sinks"), how far it moves at all, and the deepest overlap.
class PyramidScene final : public Scene {
 public:
  PyramidScene(int rows, bool quick) : rows_(rows), quick_(quick) {}
  std::string name() const override { return "pyramid-" + std::to_string(rows_); }
  SceneDescription describe() const override {
    SceneDescription scene;
    addGround(scene, rows_ + 10.0);
    addPyramid(scene, rows_, 1.0, Material::Solid);
    return scene;
  }
  RunLength length() const override {
    if (quick_) return {0, 5, 1, 5};
    if (rows_ > 60) return {0, 300, 2, 60};
    return rows_ > 20 ? RunLength{0, 600, 2, 60} : RunLength{0, 600, 3, 30};
  }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  class Watch final : public Measure {
   public:
    explicit Watch(const SceneDescription& scene)
        : top_(static_cast<int>(scene.bodies.size()) - 1), start_(scene.bodies.back().position),
          penetration_(scene) {}
    void observe(const EngineAdapter& engine, int) override { penetration_.observe(engine); }
    std::vector<Metric> results(const EngineAdapter& engine) override {
      Vec2d now = engine.pose(top_).position;
      return {{"top sink m", start_.y - now.y}, {"top drift m", distance(now, start_)},
              {"max pen m", penetration_.peak()}};
    }

   private:
    int top_;
    Vec2d start_;
    PeakPenetration penetration_;
  };
  int rows_;
  bool quick_;
};

// 15 unit boxes, alternately 1 cm left and right: how far they drift in 10 s.
class TowerScene final : public Scene {
 public:
  explicit TowerScene(bool quick) : quick_(quick) {}
  std::string name() const override { return "tower-15"; }
  SceneDescription describe() const override {
    SceneDescription scene;
    addGround(scene, 20);
    for (int i = 0; i < kCount; ++i) {
      double shift = i % 2 == 0 ? 0.01 : -0.01;
      addBody(scene, makeBody(ShapeDesc::box(0.5, 0.5), {shift, 0.5 + i}, Material::Solid));
    }
    return scene;
  }
  RunLength length() const override { return quick_ ? RunLength{0, 5, 1, 5} : RunLength{0, 600, 3, 600}; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  static constexpr int kCount = 15;
  class Watch final : public Measure {
   public:
    explicit Watch(const SceneDescription& scene) : scene_(scene) {}
    void observe(const EngineAdapter&, int) override {}
    std::vector<Metric> results(const EngineAdapter& engine) override {
      double drift = 0;
      for (int i = 1; i <= kCount; ++i) {
        drift = std::max(drift, distance(engine.pose(i).position, scene_.bodies[std::size_t(i)].position));
      }
      double topDrop = scene_.bodies.back().position.y - engine.pose(kCount).position.y;
      return {{"max drift m", drift}, {"top drop m", topDrop}};
    }

   private:
    const SceneDescription& scene_;
  };
  bool quick_;
};

// A 10x10 box dropped 0.5 m onto two 0.5 m boxes (400:1 in mass).
class MassRatioScene final : public Scene {
 public:
  explicit MassRatioScene(bool quick) : quick_(quick) {}
  std::string name() const override { return "mass-ratio-400"; }
  SceneDescription describe() const override {
    SceneDescription scene;
    addGround(scene, 20);
    addBody(scene, makeBody(ShapeDesc::box(0.25, 0.25), {-4, 0.25}, Material::Solid));
    addBody(scene, makeBody(ShapeDesc::box(0.25, 0.25), {4, 0.25}, Material::Solid));
    addBody(scene, makeBody(ShapeDesc::box(5, 5), {0, kRestY + 0.5}, Material::Solid));
    return scene;
  }
  RunLength length() const override { return quick_ ? RunLength{0, 5, 1, 1} : RunLength{0, 240, 3, 1}; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  static constexpr double kRestY = 0.5 + 5;  // small boxes' top + half the big box
  class Watch final : public Measure {
   public:
    explicit Watch(const SceneDescription& scene) : penetration_(scene) {}
    void observe(const EngineAdapter& engine, int) override { penetration_.observe(engine); }
    std::vector<Metric> results(const EngineAdapter& engine) override {
      Pose big = engine.pose(3);
      double sink = kRestY - big.position.y;
      bool holds = std::abs(sink) < 0.1 && std::abs(big.angle) < 0.05;
      return {{"max pen m", penetration_.peak()}, {"sink m", sink}, {"holds", holds ? 1.0 : 0.0}};
    }

   private:
    PeakPenetration penetration_;
  };
  bool quick_;
};

// Watches the last body of a scene, a heavy box resting on lighter ones: how
// far it sinks (the "sinks < 2 cm" figure), whether it holds (sinks
// less than 25 cm: one that falls off or crushes its support sinks more), how
// far it moves at all, the deepest overlap.
class HeavyBoxWatch final : public Measure {
 public:
  explicit HeavyBoxWatch(const SceneDescription& scene)
      : heavy_(static_cast<int>(scene.bodies.size()) - 1), start_(scene.bodies.back().position),
        penetration_(scene) {}
  void observe(const EngineAdapter& engine, int) override { penetration_.observe(engine); }
  std::vector<Metric> results(const EngineAdapter& engine) override {
    Vec2d now = engine.pose(heavy_).position;
    double sink = start_.y - now.y;
    return {{"sink m", sink},
            {"holds", sink < 0.25 ? 1.0 : 0.0},
            {"heavy drift m", distance(now, start_)},
            {"max pen m", penetration_.peak()}};
  }

 private:
  int heavy_;
  Vec2d start_;
  PeakPenetration penetration_;
};

// A heavy unit box on top of a base-10 pyramid of RUBBER boxes (density 200)
// at 10:1 (METAL's 2000), and at the 300:1 and 1000:1 given as
// explicit densities.
SceneDescription heavyTop(double ratio) {
  SceneDescription scene;
  addGround(scene, 20, Material::Rubber);
  addPyramid(scene, 10, 1.0, Material::Rubber);
  BodyDesc heavy = makeBody(ShapeDesc::box(0.5, 0.5), {0, 10.5}, Material::Metal);
  heavy.density = ratio * impulse::materialProperties(Material::Rubber).density;
  addBody(scene, heavy);
  return scene;
}

// A 1 m box resting centred on one 0.5 m box on the ground, `ratio` times its
// mass (SOLID boxes, the heavy one's density set for the ratio).
SceneDescription heavyOnOneBox(double ratio) {
  SceneDescription scene;
  addGround(scene, 20);
  BodyDesc small = makeBody(ShapeDesc::box(0.25, 0.25), {0, 0.25}, Material::Solid);
  BodyDesc heavy = makeBody(ShapeDesc::box(0.5, 0.5), {0, 0.5 + 0.5}, Material::Solid);
  heavy.density = ratio * small.density * small.shape.area() / heavy.shape.area();
  addBody(scene, small);
  addBody(scene, heavy);
  return scene;
}

// A heavy box (the last body) resting on lighter ones for 10 s, at a mass
// ratio; `layout` places the bodies, the name is `family` + the ratio.
class HeavyBoxScene final : public Scene {
 public:
  using Layout = SceneDescription (*)(double ratio);
  HeavyBoxScene(std::string family, Layout layout, double ratio, bool quick)
      : family_(std::move(family)), layout_(layout), ratio_(ratio), quick_(quick) {}
  std::string name() const override { return family_ + std::to_string(int(ratio_)); }
  SceneDescription describe() const override { return layout_(ratio_); }
  RunLength length() const override { return quick_ ? RunLength{0, 5, 1, 5} : RunLength{0, 600, 3, 10}; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<HeavyBoxWatch>(scene);
  }

 private:
  std::string family_;
  Layout layout_;
  double ratio_;
  bool quick_;
};

// A base-4 pyramid built at 0.75 m pitch: 25% overlap to push out gently.
class OverlapRecoveryScene final : public Scene {
 public:
  explicit OverlapRecoveryScene(bool quick) : quick_(quick) {}
  std::string name() const override { return "overlap-recovery"; }
  SceneDescription describe() const override {
    SceneDescription scene;
    addGround(scene, 20);
    addPyramid(scene, 4, 0.75, Material::Solid);
    return scene;
  }
  RunLength length() const override { return quick_ ? RunLength{0, 5, 1, 1} : RunLength{0, 300, 3, 1}; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  class Watch final : public Measure {
   public:
    explicit Watch(const SceneDescription& scene) : bodies_(dynamicBodies(scene)), penetration_(scene) {}
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
  bool quick_;
};

}  // namespace

void addStackingScenes(SceneList& scenes, bool quick) {
  for (int rows : {20, 60, 100}) scenes.push_back(std::make_unique<PyramidScene>(rows, quick));
  scenes.push_back(std::make_unique<TowerScene>(quick));
  scenes.push_back(std::make_unique<MassRatioScene>(quick));
  for (double ratio : {10, 300, 1000}) {
    scenes.push_back(std::make_unique<HeavyBoxScene>("heavy-top-", heavyTop, ratio, quick));
  }
  for (double ratio : {180, 1000}) {
    scenes.push_back(std::make_unique<HeavyBoxScene>("heavy-on-box-", heavyOnOneBox, ratio, quick));
  }
  scenes.push_back(std::make_unique<OverlapRecoveryScene>(quick));
}

}  // namespace bench
