// Joints: pins, rods and springs in every engine. Error figures come from
// poses alone (joint_error.h): a pin's gap is the distance between where its
// two anchors, carried by their bodies, are now.
//
//   heavy-chain-300  20 wooden links on pins under a world pin, a weight of
//                    300 links' mass under the last, swinging
//   chain-bridge     14 planks on pins between two world pins, with slack,
//                    two metal balls dropped on it
//   pendulum-90      a ball on a rigid rod released at 90 degrees
//   spring-mass      a 1 kg ball on an undamped 1 Hz spring, no gravity
//   ragdoll-pile     80 ten-piece ragdolls (trees of pins) into a box

#include <numbers>

#include "joint_error.h"
#include "scene_helpers.h"

namespace bench {

namespace {

using impulse::Material;

constexpr double kGravity = 9.81;
constexpr double kPi = std::numbers::pi;

/// The scene set spinning as one rigid body at `spin` rad/s about `pivot`,
/// so every joint's velocity constraint already holds at the start.
void spinAbout(SceneDescription& scene, Vec2d pivot, double spin) {
  for (BodyDesc& body : scene.bodies) {
    if (body.isStatic) continue;
    body.velocity = {-spin * (body.position.y - pivot.y), spin * (body.position.x - pivot.x)};
    body.angularVelocity = spin;
  }
}

/// A signal sampled every step: rising crossings and extremes.
class Samples {
 public:
  void add(double time, double value) {
    time_.push_back(time);
    value_.push_back(value);
  }
  /// Mean time between the first and last rising crossing of `level`
  /// (linearly interpolated); 0 with fewer than two crossings.
  double meanPeriod(double level) const {
    std::vector<double> crossings;
    for (std::size_t i = 1; i < value_.size(); ++i) {
      if (value_[i - 1] < level && value_[i] >= level) {
        double f = (level - value_[i - 1]) / (value_[i] - value_[i - 1]);
        crossings.push_back(time_[i - 1] + f * (time_[i] - time_[i - 1]));
      }
    }
    if (crossings.size() < 2) return 0;
    return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  }
  /// Largest |value - level| from time `from` on.
  double amplitudeSince(double from, double level) const {
    double most = 0;
    for (std::size_t i = 0; i < value_.size(); ++i) {
      if (time_[i] >= from) most = std::max(most, std::abs(value_[i] - level));
    }
    return most;
  }
  double lastTime() const { return time_.empty() ? 0 : time_.back(); }

 private:
  std::vector<double> time_;
  std::vector<double> value_;
};

/// |measured / expected - 1|; 1 when nothing was measured (--quick runs are
/// too short for a period).
double relativeError(double measured, double expected) {
  return measured > 0 ? std::abs(measured / expected - 1) : 1;
}

/// For scenes judged by their pins: the worst gap over the run, the gap at
/// the end, and how fast the fastest body still moves.
class PinGapWatch final : public Measure {
 public:
  explicit PinGapWatch(const SceneDescription& scene)
      : probe_(scene), moving_(dynamicBodies(scene)) {}
  void observe(const EngineAdapter& engine, int) override {
    gap_ = std::max(gap_, probe_.worstPinGap(engine));
  }
  std::vector<Metric> results(const EngineAdapter& engine) override {
    return {{"pin gap m", gap_},
            {"end gap m", probe_.worstPinGap(engine)},
            {"end speed m/s", fastest(engine, moving_)}};
  }

 private:
  JointProbe probe_;
  std::vector<int> moving_;
  double gap_ = 0;
};

// ---- heavy-chain-300 -------------------------------------------------------

constexpr int kChainLinks = 20;
constexpr double kLinkLength = 0.5;
constexpr double kChainLength = kChainLinks * kLinkLength;
constexpr Vec2d kChainTop{0, 12};
constexpr double kWeightRadius = 0.5;

// Joint i pins link i under link i - 1 (joint 0: the first link to the
// world); the last joint pins the weight, whose pin is on its rim.
SceneDescription heavyChain() {
  SceneDescription scene;
  BodyDesc link = makeBody(ShapeDesc::box(0.05, 0.5 * kLinkLength), {}, Material::Wood);
  int above = kWorldBody;
  for (int i = 0; i < kChainLinks; ++i) {
    link.position = {kChainTop.x, kChainTop.y - (i + 0.5) * kLinkLength};
    int index = addBody(scene, link);
    addJoint(scene, makePin(index, above, {kChainTop.x, kChainTop.y - i * kLinkLength}));
    above = index;
  }
  const Vec2d end{kChainTop.x, kChainTop.y - kChainLength};
  BodyDesc weight =
      makeBody(ShapeDesc::circle(kWeightRadius), {end.x, end.y - kWeightRadius}, Material::Metal);
  weight.density = 300 * mass(link) / weight.shape.area();
  addJoint(scene, makePin(addBody(scene, weight), above, end));
  // About 5 m/s at the weight: a swing of about 30 degrees.
  spinAbout(scene, kChainTop, 0.5);
  return scene;
}

class HeavyChainWatch final : public Measure {
 public:
  explicit HeavyChainWatch(const SceneDescription& scene)
      : probe_(scene), weightPin_(int(scene.joints.size()) - 1) {}
  void observe(const EngineAdapter& engine, int) override {
    Vec2d pin = probe_.anchor(engine, weightPin_, 0);
    stretch_ = std::max(stretch_, distance(pin, kChainTop) / kChainLength - 1);
    gap_ = std::max(gap_, probe_.worstPinGap(engine));
  }
  std::vector<Metric> results(const EngineAdapter&) override {
    return {{"stretch", stretch_}, {"pin gap m", gap_}};
  }

 private:
  JointProbe probe_;
  int weightPin_;
  double stretch_ = 0;
  double gap_ = 0;
};

// ---- chain-bridge ----------------------------------------------------------

constexpr int kPlanks = 14;
constexpr double kPlankLength = 1;
constexpr double kBridgeHalfSpan = 6;
constexpr double kBridgeHeight = 8;

// The planks start as a V between the two world pins, seven sloping down to
// the middle and seven up, so every pin holds at the start and the bridge
// swings into its sag.
SceneDescription chainBridge() {
  SceneDescription scene;
  addGround(scene, 20);
  const double halfLength = 0.5 * kPlanks * kPlankLength;
  const double slope = std::acos(kBridgeHalfSpan / halfLength);
  Vec2d pin{-kBridgeHalfSpan, kBridgeHeight};
  int previous = kWorldBody;
  for (int i = 0; i < kPlanks; ++i) {
    const double angle = i < kPlanks / 2 ? -slope : slope;
    const Vec2d next{pin.x + kPlankLength * std::cos(angle),
                     pin.y + kPlankLength * std::sin(angle)};
    BodyDesc plank = makeBody(ShapeDesc::box(0.5 * kPlankLength, 0.05),
                              {0.5 * (pin.x + next.x), 0.5 * (pin.y + next.y)}, Material::Wood);
    plank.angle = angle;
    int index = addBody(scene, plank);
    addJoint(scene, makePin(index, previous, pin));
    previous = index;
    pin = next;
  }
  addJoint(scene, makePin(previous, kWorldBody, pin));
  for (double x : {-2.0, 2.5})
    addBody(scene, makeBody(ShapeDesc::circle(0.3), {x, kBridgeHeight}, Material::Metal));
  return scene;
}

// ---- pendulum-90 -----------------------------------------------------------

constexpr Vec2d kPivot{0, 5};
constexpr double kRodLength = 1;

SceneDescription pendulum() {
  SceneDescription scene;
  const Vec2d start{kPivot.x + kRodLength, kPivot.y};
  addJoint(scene, makeRod(addBody(scene, makeBody(ShapeDesc::circle(0.1), start, Material::Metal)),
                          kWorldBody, start, kPivot));
  return scene;
}

// A point mass released at rest at angle a swings with the period
// 4 sqrt(L / g) K(sin(a / 2)), K the complete elliptic integral of the first
// kind (the ball is on the rod at its centre, so its spin plays no part).
double pendulumPeriod(double releaseAngle) {
  return 4 * std::sqrt(kRodLength / kGravity) * std::comp_ellint_1(std::sin(0.5 * releaseAngle));
}

class PendulumWatch final : public Measure {
 public:
  explicit PendulumWatch(const SceneDescription& scene) : probe_(scene) {}
  void observe(const EngineAdapter& engine, int step) override {
    Pose ball = engine.pose(0);
    x_.add((step + 1) * kDt, ball.position.x - kPivot.x);
    height_.add((step + 1) * kDt, ball.position.y - kPivot.y);
    rod_ = std::max(rod_, probe_.worstRodError(engine));
  }
  // Height loss: how far below the release height the ball turned in the
  // last period (energy the integrator lost or, when negative, gained).
  std::vector<Metric> results(const EngineAdapter&) override {
    const double period = pendulumPeriod(kPi / 2);
    return {{"period err", relativeError(x_.meanPeriod(0), period)},
            {"height loss m",
             kRodLength - height_.amplitudeSince(height_.lastTime() - period, -kRodLength)},
            {"rod err m", rod_}};
  }

 private:
  JointProbe probe_;
  Samples x_;
  Samples height_;
  double rod_ = 0;
};

// ---- spring-mass -----------------------------------------------------------

constexpr double kSpringMass = 1;
constexpr double kSpringPeriod = 1;
constexpr double kRestLength = 2;
constexpr double kAmplitude = 0.5;

SceneDescription springMass() {
  SceneDescription scene;
  scene.gravity = {0, 0};
  BodyDesc ball = makeBody(ShapeDesc::circle(0.1), {kRestLength + kAmplitude, 0}, Material::Metal);
  ball.density = kSpringMass / ball.shape.area();
  const double stiffness = kSpringMass * std::pow(2 * kPi / kSpringPeriod, 2);
  addJoint(scene, makeSpring(addBody(scene, ball), kWorldBody, ball.position, {0, 0}, kRestLength,
                             stiffness, 0));
  return scene;
}

class SpringWatch final : public Measure {
 public:
  explicit SpringWatch(const SceneDescription&) {}
  void observe(const EngineAdapter& engine, int step) override {
    x_.add((step + 1) * kDt, engine.pose(0).position.x);
  }
  // The amplitude in the last period against the release amplitude.
  std::vector<Metric> results(const EngineAdapter&) override {
    const double amplitude = x_.amplitudeSince(x_.lastTime() - kSpringPeriod, kRestLength);
    return {{"period err", relativeError(x_.meanPeriod(kRestLength), kSpringPeriod)},
            {"amp loss", 1 - amplitude / kAmplitude}};
  }

 private:
  Samples x_;
};

// ---- ragdoll-pile ----------------------------------------------------------

constexpr int kRagdollColumns = 8;
constexpr int kRagdollRows = 10;
constexpr double kRagdollPitch = 2;
constexpr double kBoxHalfWidth = 0.5 * kRagdollColumns * kRagdollPitch;

/// A part of a ragdoll in its own frame: its shape, centre and the pin that
/// joins it to the part `parent` (an index into the list; -1: none).
struct Part {
  ShapeDesc shape;
  Vec2d centre;
  int parent = -1;
  Vec2d pin;
};

// Torso, head, arms out (upper, lower), legs down (thigh, shin): a tree of
// nine pins, each in the middle of a 2 cm gap between its two parts, so no
// two parts touch at the start.
std::vector<Part> ragdollParts() {
  const ShapeDesc arm = ShapeDesc::box(0.15, 0.04), leg = ShapeDesc::box(0.06, 0.18);
  std::vector<Part> parts{{ShapeDesc::box(0.15, 0.3), {0, 0}, -1, {}},
                          {ShapeDesc::circle(0.12), {0, 0.44}, 0, {0, 0.31}}};
  for (double side : {-1.0, 1.0}) {
    parts.push_back({arm, {0.32 * side, 0.24}, 0, {0.16 * side, 0.24}});
    parts.push_back({arm, {0.64 * side, 0.24}, int(parts.size()) - 1, {0.48 * side, 0.24}});
    parts.push_back({leg, {0.08 * side, -0.5}, 0, {0.08 * side, -0.31}});
    parts.push_back({leg, {0.08 * side, -0.88}, int(parts.size()) - 1, {0.08 * side, -0.69}});
  }
  return parts;
}

// The ragdoll turned by `angle` about the middle of its height (every part
// within 0.95 m of it) and put there at `at`.
void addRagdoll(SceneDescription& scene, const std::vector<Part>& parts, Vec2d at, double angle) {
  const Vec2d middle{0, -0.25};
  const double c = std::cos(angle), s = std::sin(angle);
  auto place = [&](const Vec2d& p) {
    const double x = p.x - middle.x, y = p.y - middle.y;
    return Vec2d{at.x + c * x - s * y, at.y + s * x + c * y};
  };
  const int first = int(scene.bodies.size());
  for (const Part& part : parts) {
    BodyDesc body = makeBody(part.shape, place(part.centre), Material::Wood);
    body.angle = angle;
    int index = addBody(scene, body);
    if (part.parent >= 0) addJoint(scene, makePin(index, first + part.parent, place(part.pin)));
  }
}

SceneDescription ragdollPile() {
  SceneDescription scene;
  addGround(scene, kBoxHalfWidth + 1);
  const double wallTop = kRagdollRows * kRagdollPitch + 2;
  addBody(scene, makeStaticBox({-kBoxHalfWidth - 1, 0}, {-kBoxHalfWidth, wallTop}));
  addBody(scene, makeStaticBox({kBoxHalfWidth, 0}, {kBoxHalfWidth + 1, wallTop}));
  const std::vector<Part> parts = ragdollParts();
  for (int row = 0; row < kRagdollRows; ++row) {
    for (int column = 0; column < kRagdollColumns; ++column) {
      const Vec2d at{-kBoxHalfWidth + (column + 0.5) * kRagdollPitch, 1.5 + row * kRagdollPitch};
      addRagdoll(scene, parts, at, 0.7 * (row * kRagdollColumns + column));
    }
  }
  return scene;
}

}  // namespace

void addJointScenes(SceneList& scenes, bool quick) {
  const RunLength quickLength{0, 5, 1, 1};
  addListedScene<HeavyChainWatch>(scenes, quick, "heavy-chain-300", heavyChain, {0, 600, 3, 1},
                                  quickLength);
  addListedScene<PinGapWatch>(scenes, quick, "chain-bridge", chainBridge, {0, 600, 3, 1},
                              quickLength);
  addListedScene<PendulumWatch>(scenes, quick, "pendulum-90", pendulum, {0, 720, 3, 1},
                                quickLength);
  addListedScene<SpringWatch>(scenes, quick, "spring-mass", springMass, {0, 660, 3, 1},
                              quickLength);
  addListedScene<PinGapWatch>(scenes, quick, "ragdoll-pile", ragdollPile, {0, 300, 3, 1},
                              quickLength);
}

}  // namespace bench
