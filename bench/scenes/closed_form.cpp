// Single bodies with an analytic answer: free fall, a box sliding down an
// incline, a ball rolling down one, and a ball bouncing. Each engine's error
// is against the closed form for its own coefficients (Impulse: dynamic
// friction and rolling resistance; peers: one friction, no rolling resistance).

#include <functional>

#include "scene_helpers.h"

namespace bench {

namespace {

using impulse::Material;

constexpr double kGravity = 9.81;

const impulse::MaterialProperties& props(Material m) { return impulse::materialProperties(m); }

// A ramp (static box) of angle `angle` whose top surface passes through the
// origin, and a body resting on it `along` metres up the slope.
void addRampWith(SceneDescription& scene, double angle, Material material, BodyDesc body, double along,
                 double halfHeight) {
  const Vec2d up{std::cos(angle), std::sin(angle)}, normal{-std::sin(angle), std::cos(angle)};
  BodyDesc ramp = makeBody(ShapeDesc::box(15, 0.5), {-0.5 * normal.x, -0.5 * normal.y}, material, true);
  ramp.angle = angle;
  addBody(scene, ramp);
  body.position = {along * up.x + halfHeight * normal.x, along * up.y + halfHeight * normal.y};
  body.angle = angle;
  addBody(scene, body);
}

double slid(const SceneDescription& scene, const EngineAdapter& engine, double angle) {
  const Vec2d& start = scene.bodies[1].position;
  Vec2d now = engine.pose(1).position;
  return -((now.x - start.x) * std::cos(angle) + (now.y - start.y) * std::sin(angle));
}

/// Callbacks make up a scene: the closed-form cases differ only in these.
struct ClosedFormCase {
  std::string name;
  int steps = 60;
  std::function<SceneDescription()> build;
  /// Error figures from the final state, the scene, the engine, time t and
  /// what the watcher recorded.
  std::function<std::vector<Metric>(const SceneDescription&, const EngineAdapter&, Engine, double t, double watched)>
      finish;
  /// Optional per-step watcher (the bounce tracks its apex).
  std::function<void(const EngineAdapter&, double& state)> watch;
};

class ClosedFormScene final : public Scene {
 public:
  ClosedFormScene(ClosedFormCase c, bool quick) : case_(std::move(c)), quick_(quick) {}
  std::string name() const override { return case_.name; }
  SceneDescription describe() const override {
    SceneDescription scene = case_.build();
    return scene;
  }
  RunLength length() const override {
    return quick_ ? RunLength{0, 5, 1, 1} : RunLength{0, case_.steps, 3, 1};
  }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine engine) const override {
    return std::make_unique<Watch>(case_, scene, engine);
  }

 private:
  class Watch final : public Measure {
   public:
    Watch(const ClosedFormCase& c, const SceneDescription& scene, Engine engine)
        : case_(c), scene_(scene), engine_(engine) {}
    void observe(const EngineAdapter& engine, int step) override {
      time_ = (step + 1) * kDt;
      if (case_.watch) case_.watch(engine, state_);
    }
    std::vector<Metric> results(const EngineAdapter& engine) override {
      return case_.finish(scene_, engine, engine_, time_, state_);
    }

   private:
    const ClosedFormCase& case_;
    const SceneDescription& scene_;
    Engine engine_;
    double time_ = 0;
    double state_ = 0;
  };
  ClosedFormCase case_;
  bool quick_;
};

ClosedFormCase freeFall() {
  return {"free-fall", 60,
          [] {
            SceneDescription scene;
            addBody(scene, makeBody(ShapeDesc::circle(0.5), {0, 100}, Material::Solid));
            return scene;
          },
          [](const SceneDescription&, const EngineAdapter& engine, Engine, double t, double) {
            Pose pose = engine.pose(0);
            return std::vector<Metric>{{"height err m", std::abs(pose.position.y - (100 - 0.5 * kGravity * t * t))},
                                       {"speed err m/s", std::abs(pose.velocity.y + kGravity * t)}};
          },
          {}};
}

// WOOD on WOOD at 0.6 rad: static 0.5 < tan 0.6 = 0.68, so it slides.
ClosedFormCase inclineSlide() {
  constexpr double angle = 0.6;
  return {"incline-slide", 120,
          [] {
            SceneDescription scene;
            addRampWith(scene, angle, Material::Wood, makeBody(ShapeDesc::box(0.5, 0.5), {}, Material::Wood), 10,
                        0.5);
            return scene;
          },
          [](const SceneDescription& scene, const EngineAdapter& engine, Engine e, double t, double) {
            double mu = isImpulse(e) ? props(Material::Wood).dynamicFriction : props(Material::Wood).staticFriction;
            double expected = 0.5 * kGravity * (std::sin(angle) - mu * std::cos(angle)) * t * t;
            double d = slid(scene, engine, angle);
            return std::vector<Metric>{{"slide err m", std::abs(d - expected)}, {"slid m", d}};
          },
          {}};
}

// A RUBBER disc rolling without slipping down a 0.2 rad RUBBER ramp:
// a = g (sin - c_rr cos) / (1 + I / m r^2) with I = m r^2 / 2.
ClosedFormCase rollingBall() {
  constexpr double angle = 0.2;
  return {"rolling-ball", 120,
          [] {
            SceneDescription scene;
            addRampWith(scene, angle, Material::Rubber, makeBody(ShapeDesc::circle(0.5), {}, Material::Rubber), 10,
                        0.5);
            return scene;
          },
          [](const SceneDescription& scene, const EngineAdapter& engine, Engine e, double t, double) {
            double rolling = isImpulse(e) ? props(Material::Rubber).rollingResistance : 0;
            double a = kGravity * (std::sin(angle) - rolling * std::cos(angle)) / 1.5;
            double d = slid(scene, engine, angle);
            // Rolling without slipping: the spin matches the speed.
            Pose pose = engine.pose(1);
            double slip = std::abs(speed(pose) - std::abs(pose.angularVelocity) * 0.5);
            return std::vector<Metric>{{"roll err m", std::abs(d - 0.5 * a * t * t)}, {"slip m/s", slip}};
          },
          {}};
}

// A SOLID ball dropped from 5 m onto SOLID ground rebounds to e^2 * 5 m.
ClosedFormCase bounce() {
  constexpr double drop = 5;
  return {"bounce", 150,
          [] {
            SceneDescription scene;
            addGround(scene, 10);
            addBody(scene, makeBody(ShapeDesc::circle(0.5), {0, 0.5 + drop}, Material::Solid));
            return scene;
          },
          [](const SceneDescription&, const EngineAdapter&, Engine, double, double apex) {
            double e = props(Material::Solid).restitution;
            return std::vector<Metric>{{"rebound err m", std::abs(apex - e * e * drop)}, {"rebound m", apex}};
          },
          // state: the highest centre height after the first rebound (0 until then).
          [](const EngineAdapter& engine, double& apex) {
            Pose pose = engine.pose(1);
            if (pose.velocity.y > 0 || apex > 0) apex = std::max(apex, pose.position.y - 0.5);
          }};
}

}  // namespace

void addClosedFormScenes(SceneList& scenes, bool quick) {
  for (ClosedFormCase c : {freeFall(), inclineSlide(), rollingBall(), bounce()}) {
    scenes.push_back(std::make_unique<ClosedFormScene>(std::move(c), quick));
  }
}

}  // namespace bench
