// Small fast discs (0.1 m across) shot at a 0.2 m wall at 50, 200 and
// 400 m/s, five at each speed, no gravity: how many end up beyond the wall.

#include <cstdio>

#include "scene_helpers.h"

namespace bench {

namespace {

using impulse::Material;

constexpr double kWallX = 10;
constexpr double kWallThickness = 0.2;
constexpr double kSpeeds[] = {50, 200, 400};
constexpr int kPerSpeed = 5;

SceneDescription bullets() {
  SceneDescription scene;
  scene.gravity = {0, 0};
  addBody(scene, makeStaticBox({kWallX, -1}, {kWallX + kWallThickness, 16}));
  int shot = 0;
  for (double speed : kSpeeds) {
    for (int i = 0; i < kPerSpeed; ++i, ++shot) {
      BodyDesc disc = makeBody(ShapeDesc::circle(0.05), {0, 0.5 + shot}, Material::Solid);
      disc.velocity = {speed, 0};
      addBody(scene, disc);
    }
  }
  return scene;
}

class BulletWatch final : public Measure {
 public:
  explicit BulletWatch(const SceneDescription& scene) : through_(scene.bodies.size(), false) {}
  void observe(const EngineAdapter& engine, int) override {
    for (std::size_t i = 1; i < through_.size(); ++i) {
      if (engine.pose(int(i)).position.x > kWallX + kWallThickness) through_[i] = true;
    }
  }
  std::vector<Metric> results(const EngineAdapter&) override {
    std::vector<Metric> metrics = {{"tunnelled", 0}};
    for (std::size_t s = 0; s < std::size(kSpeeds); ++s) {
      int count = 0;
      for (int i = 0; i < kPerSpeed; ++i) count += through_[1 + s * kPerSpeed + std::size_t(i)] ? 1 : 0;
      metrics[0].value += count;
      char label[24];
      std::snprintf(label, sizeof label, "@%d m/s", int(kSpeeds[s]));
      metrics.push_back({label, double(count)});
    }
    return metrics;
  }

 private:
  std::vector<bool> through_;
};

}  // namespace

void addBulletScene(SceneList& scenes, bool quick) {
  addListedScene<BulletWatch>(scenes, quick, "bullets", bullets, {0, 60, 3, 1}, {0, 5, 1, 1});
}

}  // namespace bench
