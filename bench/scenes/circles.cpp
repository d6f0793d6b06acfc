// Many circles: 625 confined without gravity, 900 squeezed by walls and
// weight, rain poured into a box, and the rain at five sizes for the
// ms/step-versus-n slope. Circles and containers
// are METAL (restitution 0.1) so that piles settle in every engine; Impulse's
// METAL rolling resistance (0.01) has no counterpart in the peers.

#include "scene_helpers.h"

namespace bench {

namespace {

using impulse::Material;


double kineticEnergy(const SceneDescription& scene, const EngineAdapter& engine, const std::vector<int>& bodies) {
  double energy = 0;
  for (int i : bodies) {
    const BodyDesc& body = scene.bodies[std::size_t(i)];
    double m = mass(body);
    double inertia = 0.5 * m * body.shape.radius * body.shape.radius;
    Pose pose = engine.pose(i);
    energy += 0.5 * m * (pose.velocity.x * pose.velocity.x + pose.velocity.y * pose.velocity.y) +
              0.5 * inertia * pose.angularVelocity * pose.angularVelocity;
  }
  return energy;
}

double potentialEnergy(const SceneDescription& scene, int body, const Vec2d& position) {
  return -mass(scene.bodies[std::size_t(body)]) * (scene.gravity.x * position.x + scene.gravity.y * position.y);
}

// Kinetic plus potential energy in the scene's gravity.
double mechanicalEnergy(const SceneDescription& scene, const EngineAdapter& engine, const std::vector<int>& bodies) {
  double potential = 0;
  for (int i : bodies) potential += potentialEnergy(scene, i, engine.pose(i).position);
  return kineticEnergy(scene, engine, bodies) + potential;
}

// The described start's energy, every body at rest.
double restingEnergy(const SceneDescription& scene, const std::vector<int>& bodies) {
  double potential = 0;
  for (int i : bodies) potential += potentialEnergy(scene, i, scene.bodies[std::size_t(i)].position);
  return potential;
}

// Box2D v3's "confined" sample (samples/sample_stacking.cpp): a 25x25 grid of
// 1 m circles at 0.72 m pitch (0.28 m overlap), first at (-8.75, 1.5), in a
// closed box whose inside is x in [-10, 10], y in [0.5, 20] (v3 walls it with
// capsules; boxes here), which cannot hold them without overlap.
class ConfinedScene final : public Scene {
 public:
  explicit ConfinedScene(bool quick) : quick_(quick) {}
  std::string name() const override { return "confined"; }
  SceneDescription describe() const override {
    SceneDescription scene;
    scene.gravity = {0, 0};
    addBody(scene, makeStaticBox({-11, -0.5}, {11, 0.5}, Material::Metal));
    addBody(scene, makeStaticBox({-11, 20}, {11, 21}, Material::Metal));
    addBody(scene, makeStaticBox({-11, 0.5}, {-10, 20}, Material::Metal));
    addBody(scene, makeStaticBox({10, 0.5}, {11, 20}, Material::Metal));
    const int grid = 25;
    for (int row = 0; row < grid; ++row) {
      for (int column = 0; column < grid; ++column) {
        addBody(scene, makeBody(ShapeDesc::circle(0.5), {-8.75 + column * 0.72, 1.5 + row * 0.72}, Material::Metal));
      }
    }
    return scene;
  }
  RunLength length() const override { return quick_ ? RunLength{0, 5, 1, 5} : RunLength{0, 300, 3, 5}; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  class Watch final : public Measure {
   public:
    explicit Watch(const SceneDescription& scene)
        : scene_(scene), bodies_(dynamicBodies(scene)), penetration_(scene) {}
    void observe(const EngineAdapter& engine, int) override {
      last_ = penetration_.observe(engine);
      maxEnergy_ = std::max(maxEnergy_, kineticEnergy(scene_, engine, bodies_));
      maxSpeed_ = std::max(maxSpeed_, fastest(engine, bodies_));
    }
    // Max speed first: the figure, with "no energy gain" (the balls
    // start at rest, so any kinetic energy is gained).
    std::vector<Metric> results(const EngineAdapter&) override {
      return {{"max speed m/s", maxSpeed_}, {"max KE J", maxEnergy_}, {"end pen m", last_}};
    }

   private:
    const SceneDescription& scene_;
    std::vector<int> bodies_;
    PeakPenetration penetration_;
    double last_ = 0;
    double maxEnergy_ = 0;
    double maxSpeed_ = 0;
  };
  bool quick_;
};

// A squeezed crowd: a 30x30 square lattice of touching r=0.5 circles, sleep
// off, in an open box exactly 30 m wide, for 10 s. The side walls hold every
// row at its full width and each bottom circle carries 29 above it, so the
// crowd is squeezed by walls and weight; the right answer is that nothing
// moves. Figures: the fastest any circle goes, the largest gain of kinetic
// plus potential energy over the start, the deepest overlap.
class SqueezeScene final : public Scene {
 public:
  explicit SqueezeScene(bool quick) : quick_(quick) {}
  std::string name() const override { return "squeeze-900"; }
  SceneDescription describe() const override {
    SceneDescription scene;
    const double half = 0.5 * kSide;
    addBody(scene, makeStaticBox({-half - 1, -1}, {half + 1, 0}, Material::Metal));
    addBody(scene, makeStaticBox({-half - 1, 0}, {-half, kSide + 2}, Material::Metal));
    addBody(scene, makeStaticBox({half, 0}, {half + 1, kSide + 2}, Material::Metal));
    for (int row = 0; row < kSide; ++row) {
      for (int column = 0; column < kSide; ++column) {
        addBody(scene, makeBody(ShapeDesc::circle(0.5), {-half + 0.5 + column, 0.5 + row}, Material::Metal));
      }
    }
    return scene;
  }
  RunLength length() const override { return quick_ ? RunLength{0, 5, 1, 5} : RunLength{0, 600, 3, 5}; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  static constexpr int kSide = 30;
  class Watch final : public Measure {
   public:
    explicit Watch(const SceneDescription& scene)
        : scene_(scene), bodies_(dynamicBodies(scene)), start_(restingEnergy(scene, bodies_)), penetration_(scene) {}
    void observe(const EngineAdapter& engine, int) override {
      penetration_.observe(engine);
      maxGain_ = std::max(maxGain_, mechanicalEnergy(scene_, engine, bodies_) - start_);
      maxSpeed_ = std::max(maxSpeed_, fastest(engine, bodies_));
    }
    std::vector<Metric> results(const EngineAdapter&) override {
      return {{"max speed m/s", maxSpeed_}, {"energy gain J", maxGain_}, {"max pen m", penetration_.peak()}};
    }

   private:
    const SceneDescription& scene_;
    std::vector<int> bodies_;
    double start_;
    PeakPenetration penetration_;
    double maxGain_ = 0;
    double maxSpeed_ = 0;
  };
  bool quick_;
};

// impulse::buildRain's layout: an open box about square in what it must hold,
// circles in a staggered grid above it.
SceneDescription rainScene(int count) {
  const double radius = 0.25;
  SceneDescription scene;
  scene.allowSleep = true;
  const double width = std::max(10.0, std::sqrt(double(count)) * radius * 3);
  addBody(scene, makeStaticBox({-width / 2 - 1, -1}, {width / 2 + 1, 0}, Material::Metal));
  addBody(scene, makeStaticBox({-width / 2 - 1, 0}, {-width / 2, width}, Material::Metal));
  addBody(scene, makeStaticBox({width / 2, 0}, {width / 2 + 1, width}, Material::Metal));
  const double pitch = 2.2 * radius;
  const int perRow = std::max(1, static_cast<int>((width - 2 * radius) / pitch));
  for (int i = 0; i < count; ++i) {
    int row = i / perRow, column = i % perRow;
    double stagger = (row % 2) * 0.5 * pitch;
    addBody(scene, makeBody(ShapeDesc::circle(radius),
                            {-width / 2 + radius + stagger + pitch * column, 2 + pitch * row}, Material::Metal));
  }
  return scene;
}

class RainScene final : public Scene {
 public:
  RainScene(std::string name, int count, RunLength length) : name_(std::move(name)), count_(count), length_(length) {}
  std::string name() const override { return name_; }
  SceneDescription describe() const override { return rainScene(count_); }
  RunLength length() const override { return length_; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<Watch>(scene);
  }

 private:
  // Settled: every ball slower than 0.1 m/s from then on.
  class Watch final : public Measure {
   public:
    explicit Watch(const SceneDescription& scene) : bodies_(dynamicBodies(scene)), penetration_(scene) {}
    void observe(const EngineAdapter& engine, int step) override {
      penetration_.observe(engine);
      if (fastest(engine, bodies_) >= 0.1) settledAt_ = -1;
      else if (settledAt_ < 0) settledAt_ = (step + 1) * kDt;
    }
    std::vector<Metric> results(const EngineAdapter&) override {
      return {{"max pen m", penetration_.peak()}, {"settle s", settledAt_ < 0 ? 99.0 : settledAt_}};
    }

   private:
    std::vector<int> bodies_;
    PeakPenetration penetration_;
    double settledAt_ = -1;
  };
  std::string name_;
  int count_;
  RunLength length_;
};

}  // namespace

void addCircleScenes(SceneList& scenes, bool quick) {
  scenes.push_back(std::make_unique<ConfinedScene>(quick));
  scenes.push_back(std::make_unique<SqueezeScene>(quick));
  scenes.push_back(std::make_unique<RainScene>("rain-2000", 2000, quick ? RunLength{0, 5, 1, 5}
                                                                        : RunLength{0, 600, 3, 10}));
  for (int count : {500, 1000, 2000, 4000, 8000}) {
    scenes.push_back(std::make_unique<RainScene>("scaling-" + std::to_string(count), count,
                                                 quick ? RunLength{0, 3, 1, 3} : RunLength{0, 180, 2, 60}));
  }
}

}  // namespace bench
