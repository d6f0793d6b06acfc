// What sleeping bodies cost: 5000 boxes resting asleep on 50 shelves plus 50
// awake circles falling into a box, against the 50 circles alone. The boxes
// get 1.5 s of untimed warm-up to fall asleep; the timed 2 s then cover the
// circles' landing. Error figure: resting boxes still awake at the end.

#include "scene_helpers.h"

namespace bench {

namespace {

using impulse::Material;

constexpr int kShelves = 50;
constexpr int kPerShelf = 100;
constexpr int kAwake = 50;

// The awake circles in their box, and with `withResting` the shelves of boxes.
SceneDescription shelves(bool withResting) {
  SceneDescription scene;
  scene.allowSleep = true;
  // The awake circles' box, away from the shelves.
  addBody(scene, makeStaticBox({69, -1}, {81, 0}));
  addBody(scene, makeStaticBox({69, 0}, {70, 5}));
  addBody(scene, makeStaticBox({80, 0}, {81, 5}));
  for (int i = 0; i < kAwake; ++i) {
    addBody(scene, makeBody(ShapeDesc::circle(0.25), {71 + (i % 10) * 0.8, 25 + (i / 10) * 0.8}, Material::Solid));
  }
  if (!withResting) return scene;
  for (int shelf = 0; shelf < kShelves; ++shelf) {
    double top = 3.0 * shelf;
    addBody(scene, makeStaticBox({-60, top - 1}, {60, top}));
    for (int i = 0; i < kPerShelf; ++i) {
      addBody(scene, makeBody(ShapeDesc::box(0.5, 0.5), {-55 + 1.1 * i, top + 0.5}, Material::Solid));
    }
  }
  return scene;
}

class RestingAwakeWatch final : public Measure {
 public:
  explicit RestingAwakeWatch(const SceneDescription& scene) : scene_(scene) {}
  void observe(const EngineAdapter&, int) override {}
  std::vector<Metric> results(const EngineAdapter& engine) override {
    int awake = 0;
    for (int i = 3 + kAwake; i < static_cast<int>(scene_.bodies.size()); ++i) {
      if (!scene_.bodies[std::size_t(i)].isStatic && engine.pose(i).awake) ++awake;
    }
    return {{"resting awake", double(awake)}};
  }

 private:
  const SceneDescription& scene_;
};

}  // namespace

void addSleepingScenes(SceneList& scenes, bool quick) {
  for (bool withResting : {true, false}) {
    addListedScene<RestingAwakeWatch>(scenes, quick, withResting ? "sleeping-5050" : "sleeping-awake-50",
                                      [withResting] { return shelves(withResting); }, {90, 120, 3, 120},
                                      {5, 5, 1, 5});
  }
}

}  // namespace bench
