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
SceneDescription confined() {
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

class ConfinedWatch final : public Measure {
 public:
  explicit ConfinedWatch(const SceneDescription& scene)
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

// A squeezed crowd: a 30x30 square lattice of touching r=0.5 circles, sleep
// off, in an open box exactly 30 m wide. The side walls hold every row at its
// full width and each bottom circle carries 29 above it, so the crowd is
// squeezed by walls and weight; the right answer is that nothing moves.
SceneDescription squeeze() {
  constexpr int side = 30;
  constexpr double half = 0.5 * side;
  SceneDescription scene;
  addBody(scene, makeStaticBox({-half - 1, -1}, {half + 1, 0}, Material::Metal));
  addBody(scene, makeStaticBox({-half - 1, 0}, {-half, side + 2}, Material::Metal));
  addBody(scene, makeStaticBox({half, 0}, {half + 1, side + 2}, Material::Metal));
  for (int row = 0; row < side; ++row) {
    for (int column = 0; column < side; ++column) {
      addBody(scene, makeBody(ShapeDesc::circle(0.5), {-half + 0.5 + column, 0.5 + row}, Material::Metal));
    }
  }
  return scene;
}

// The fastest any body goes, the largest gain of kinetic plus potential
// energy over the resting start, the deepest overlap.
class SqueezeWatch final : public Measure {
 public:
  explicit SqueezeWatch(const SceneDescription& scene)
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

// Settled: every ball slower than 0.1 m/s from then on.
class RainWatch final : public Measure {
 public:
  explicit RainWatch(const SceneDescription& scene) : bodies_(dynamicBodies(scene)), penetration_(scene) {}
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

}  // namespace

void addCircleScenes(SceneList& scenes, bool quick) {
  // Watched every step: each headline is an extreme (the fastest body, the
  // deepest overlap) that sampling misses. Every 5th step read Impulse's
  // confined crowd at 0.76 m/s, every step 1.22; every 60th step read
  // scaling-8000's deepest overlap at 0.196 m and v3's at 0.089, every step
  // 0.207 and 0.162.
  addListedScene<ConfinedWatch>(scenes, quick, "confined", confined, {0, 300, 3, 1}, {0, 5, 1, 1});
  addListedScene<SqueezeWatch>(scenes, quick, "squeeze-900", squeeze, {0, 600, 3, 1}, {0, 5, 1, 1});
  addListedScene<RainWatch>(scenes, quick, "rain-2000", [] { return rainScene(2000); }, {0, 600, 3, 1},
                            {0, 5, 1, 1});
  for (int count : {500, 1000, 2000, 4000, 8000}) {
    addListedScene<RainWatch>(scenes, quick, "scaling-" + std::to_string(count), [count] { return rainScene(count); },
                              {0, 180, 2, 1}, {0, 3, 1, 1});
  }
}

}  // namespace bench
