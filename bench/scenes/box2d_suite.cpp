// Box2D v3's benchmark suite (erincatto/box2d benchmark/main.c and
// shared/benchmarks.c, commit 617d32ab), scene for scene at its release
// sizes (its debug sizes under --quick), with v3's default shape values:
// density 1, friction 0.6, restitution 0. v3 runs each at 4 sub-steps;
// sleep is on except where its scene turns it off.
//
// Where the description departs from v3's code, for every engine alike:
// a static body of many boxes (a floor, a wall) is one static body per box;
// pins between two static bodies (joint_grid's top row) are left out, as
// they hold nothing; spinner's unbounded motor torque is 1e10 N*m (Impulse's
// ceiling); rain only adds ragdolls (its run ends before v3 starts
// replacing them, at step 320).
//
// Each scene's sanity figures, read from poses alone: bodies that got out of
// what holds them (through a floor, out of a drum) at any observation, the
// pyramids' worst top drop, the ragdolls' (or the grid's) worst pin gap.

#include <limits>
#include <numbers>

#include "joint_error.h"
#include "scene_helpers.h"

namespace bench {

namespace {

constexpr double kPi = std::numbers::pi;

/// A body of b2DefaultShapeDef's density, friction and restitution.
BodyDesc v3Body(ShapeDesc shape, Vec2d position, bool isStatic = false) {
  BodyDesc body = makeBody(std::move(shape), position, impulse::Material::Solid, isStatic);
  body.density = 1;
  body.friction = 0.6;
  body.restitution = 0;
  return body;
}

int addStatic(SceneDescription& scene, ShapeDesc shape, Vec2d position = {}) {
  return addBody(scene, v3Body(std::move(shape), position, true));
}

/// How a scene is judged: the bodies out of place, the top boxes whose drop
/// is watched, and whether its pins' gaps are.
struct Sanity {
  /// True for a body found where it cannot be unless it went through
  /// something (`start` is its described origin).
  std::function<bool(const Vec2d& start, const Pose& now)> escaped = [](const Vec2d&, const Pose&) { return false; };
  std::vector<int> tops;
  bool pinGaps = false;
};

struct SuiteLayout {
  SceneDescription scene;
  Sanity sanity;
};

class SuiteMeasure final : public Measure {
 public:
  SuiteMeasure(const SceneDescription& scene, Sanity sanity)
      : scene_(scene), sanity_(std::move(sanity)), joints_(scene), out_(scene.bodies.size(), false) {}

  void observe(const EngineAdapter& engine, int) override {
    for (int i : dynamicBodies(scene_)) {
      const std::size_t index = std::size_t(i);
      if (sanity_.escaped(scene_.bodies[index].position, engine.pose(i))) out_[index] = true;
    }
    if (sanity_.pinGaps) worstGap_ = std::max(worstGap_, joints_.worstPinGap(engine));
  }

  std::vector<Metric> results(const EngineAdapter& engine) override {
    std::vector<Metric> metrics{{"escaped", double(std::count(out_.begin(), out_.end(), true))}};
    if (!sanity_.tops.empty()) metrics.push_back({"top drop m", worstTopDrop(engine)});
    if (sanity_.pinGaps) metrics.push_back({"pin gap m", worstGap_});
    return metrics;
  }

 private:
  /// Signed: a top that rose reports a negative drop.
  double worstTopDrop(const EngineAdapter& engine) const {
    double worst = -std::numeric_limits<double>::infinity();
    for (int top : sanity_.tops) {
      worst = std::max(worst, scene_.bodies[std::size_t(top)].position.y - engine.pose(top).position.y);
    }
    return worst;
  }

  const SceneDescription& scene_;
  Sanity sanity_;
  JointProbe joints_;
  std::vector<bool> out_;
  double worstGap_ = 0;
};

class SuiteScene final : public Scene {
 public:
  SuiteScene(std::string name, std::function<SuiteLayout()> layout, RunLength length)
      : name_(std::move(name)), layout_(std::move(layout)), length_(length) {}
  std::string name() const override { return name_; }
  SceneDescription describe() const override { return layout_().scene; }
  RunLength length() const override { return length_; }
  std::unique_ptr<Measure> measure(const SceneDescription& scene, Engine) const override {
    return std::make_unique<SuiteMeasure>(scene, layout_().sanity);
  }

 private:
  std::string name_;
  std::function<SuiteLayout()> layout_;
  RunLength length_;
};

/// Escaped when below `floorY` or beside the walls at +-`halfWidth`.
std::function<bool(const Vec2d&, const Pose&)> outsideBox(double floorY, double halfWidth) {
  return [=](const Vec2d&, const Pose& now) {
    return now.position.y < floorY || std::abs(now.position.x) > halfWidth;
  };
}

/// Escaped when farther than `radius` from `centre`.
std::function<bool(const Vec2d&, const Pose&)> outsideCircle(Vec2d centre, double radius) {
  return [=](const Vec2d&, const Pose& now) { return distance(now.position, centre) > radius; };
}

/// A motor turning `body` about `pin` at `speed` (rad/s, anticlockwise)
/// against the world. v3 makes the world A and the body B; a description's
/// world is always B, and a motor drives B relative to A, so the speed's
/// sign turns.
JointDesc worldMotor(int body, Vec2d pin, double speed, double maxTorque) {
  JointDesc motor = makePin(body, kWorldBody, pin);
  motor.enableMotor = true;
  motor.motorSpeed = -speed;
  motor.maxMotorTorque = maxTorque;
  return motor;
}

// ---- joint_grid -------------------------------------------------------------

SuiteLayout jointGrid(bool quick) {
  const int n = quick ? 20 : 100;
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  auto isAnchor = [&](int k, int i) { return k >= n / 2 - 3 && k <= n / 2 + 3 && i == 0; };
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < n; ++i) {
      ShapeDesc circle = ShapeDesc::circle(0.4);
      // The grid's circles never touch each other (only the world's shapes).
      circle.filter.category = 2;
      circle.filter.mask = ~2u;
      const int body = addBody(scene, v3Body(circle, {double(k), double(-i)}, isAnchor(k, i)));
      if (i > 0 && !(isAnchor(k, i) && isAnchor(k, i - 1))) {
        addJoint(scene, makePin(body - 1, body, {double(k), -i + 0.5}));
      }
      if (k > 0 && !(isAnchor(k, i) && isAnchor(k - 1, i))) {
        addJoint(scene, makePin(body - n, body, {k - 0.5, double(-i)}));
      }
    }
  }
  layout.sanity.pinGaps = true;
  return layout;
}

// ---- large_pyramid and many_pyramids ----------------------------------------

/// A pyramid of squares of half-size `extent`, its base of `baseCount`
/// starting at x = left + extent, on y = baseY; returns its top box.
int addV3Pyramid(SceneDescription& scene, int baseCount, double extent, double left, double baseY) {
  int top = 0;
  for (int i = 0; i < baseCount; ++i) {
    const double y = (2 * i + 1) * extent + baseY;
    for (int j = i; j < baseCount; ++j) {
      const double x = (i + 1) * extent + 2 * (j - i) * extent + left;
      top = addBody(scene, v3Body(ShapeDesc::box(extent, extent), {x, y}));
    }
  }
  return top;
}

SuiteLayout largePyramid(bool quick) {
  const int baseCount = quick ? 20 : 100;
  SuiteLayout layout;
  addStatic(layout.scene, ShapeDesc::box(100, 1), {0, -1});
  layout.sanity.tops = {addV3Pyramid(layout.scene, baseCount, 0.5, -0.5 * baseCount, 0)};
  layout.sanity.escaped = outsideBox(0, 100);
  return layout;
}

SuiteLayout manyPyramids(bool quick) {
  const int baseCount = 10, rows = quick ? 5 : 20, columns = quick ? 5 : 20;
  const double extent = 0.5;
  const double shelfPitch = 2 * extent * (baseCount + 1);
  const double groundWidth = 2 * extent * columns * (baseCount + 1);
  SuiteLayout layout;
  for (int i = 0; i < rows; ++i) {
    addStatic(layout.scene, ShapeDesc::segment({-0.5 * groundWidth, 0}, {0.5 * groundWidth, 0}), {0, i * shelfPitch});
  }
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const double centreX = -0.5 * groundWidth + j * (2 * extent * baseCount + 2 * extent) + 2 * extent;
      layout.sanity.tops.push_back(addV3Pyramid(layout.scene, baseCount, extent, centreX - 0.5, i * shelfPitch));
    }
  }
  // Each box stays above the shelf it started on.
  layout.sanity.escaped = [shelfPitch](const Vec2d& start, const Pose& now) {
    return now.position.y < std::floor(start.y / shelfPitch) * shelfPitch;
  };
  return layout;
}

// ---- rain -------------------------------------------------------------------

/// One bone of Box2D's human (shared/human.c) at scale 1: a capsule along y
/// about the body's origin at height `y`, pinned to its parent at `pivotY`.
struct Bone {
  double y;
  double capsuleBottom, capsuleTop, radius;
  int parent;  ///< index into the bone table; -1 for the hip
  double pivotY, lowerTurns, upperTurns;  ///< limits in half-turns (x pi)
  double frictionScale;
  double linearDamping;
  bool hasFoot;
};

// hip, torso, head, upper and lower left leg, upper and lower right leg,
// upper and lower left arm, upper and lower right arm.
constexpr Bone kBones[] = {
    {0.95, -0.02, 0.02, 0.095, -1, 0, 0, 0, 1, 0, false},
    {1.2, -0.135, 0.135, 0.09, 0, 1.0, -0.25, 0, 0.5, 0, false},
    {1.475, -0.038, 0.039, 0.075, 1, 1.4, -0.3, 0.1, 0.25, 0.1, false},
    {0.775, -0.125, 0.125, 0.06, 0, 0.9, -0.05, 0.4, 1, 0, false},
    {0.475, -0.155, 0.125, 0.045, 3, 0.625, -0.5, -0.02, 0.5, 0, true},
    {0.775, -0.125, 0.125, 0.06, 0, 0.9, -0.05, 0.4, 1, 0, false},
    {0.475, -0.155, 0.125, 0.045, 5, 0.625, -0.5, -0.02, 0.5, 0, true},
    {1.225, -0.125, 0.125, 0.035, 1, 1.35, -0.1, 0.8, 0.5, 0, false},
    {0.975, -0.125, 0.125, 0.03, 7, 1.1, -0.2, 0.3, 0.1, 0.1, false},
    {1.225, -0.125, 0.125, 0.035, 1, 1.35, -0.1, 0.8, 0.5, 0, false},
    {0.975, -0.125, 0.125, 0.03, 9, 1.1, -0.2, 0.3, 0.1, 0.1, false},
};

/// A lower leg's foot: a rounded quadrilateral that touches only the world.
ShapeDesc foot() {
  ShapeDesc shape = ShapeDesc::polygon({{-0.03, -0.185}, {0.11, -0.185}, {0.11, -0.16}, {-0.03, -0.14}}, 0.015);
  shape.filter.category = 2;
  shape.filter.mask = 1;
  shape.friction = 0.05;
  return shape;
}

/// CreateHuman at scale 1 with rain's joint friction 0.05 N*m, spring 5 Hz
/// and damping ratio 0.5; its bones never touch each other (group -group).
void addHuman(SceneDescription& scene, Vec2d at, int group, int spawnStep) {
  const int first = static_cast<int>(scene.bodies.size());
  for (const Bone& bone : kBones) {
    ShapeDesc capsule = ShapeDesc::capsule({0, bone.capsuleBottom}, {0, bone.capsuleTop}, bone.radius);
    capsule.filter = {2, 3, -group};
    BodyDesc body = v3Body(capsule, {at.x, at.y + bone.y});
    body.friction = 0.2;
    body.linearDamping = bone.linearDamping;
    body.spawnStep = spawnStep;
    if (bone.hasFoot) {
      body.extraShapes.push_back(foot());
      body.extraShapes.back().filter.group = -group;
    }
    addBody(scene, body);
  }
  for (int b = 1; b < static_cast<int>(std::size(kBones)); ++b) {
    const Bone& bone = kBones[b];
    JointDesc pin = makePin(first + bone.parent, first + b, {at.x, at.y + bone.pivotY});
    pin.enableLimit = true;
    pin.lowerAngle = bone.lowerTurns * kPi;
    pin.upperAngle = bone.upperTurns * kPi;
    pin.enableMotor = true;
    pin.maxMotorTorque = 0.05 * bone.frictionScale;
    pin.springHertz = 5;
    pin.springDampingRatio = 0.5;
    addJoint(scene, pin);
  }
}

SuiteLayout rain(bool quick) {
  const int rows = quick ? 3 : 5, columns = quick ? 10 : 40, groupSize = quick ? 2 : 5;
  const int gridCount = quick ? 200 : 500, spawnEvery = quick ? 32 : 8;
  const double gridSize = 0.5, shelfPitch = 45;
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  scene.allowSleep = true;
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j <= gridCount; ++j) {
      addStatic(scene, ShapeDesc::box(0.5 * gridSize, 0.5 * gridSize), {(j - 0.5 * gridCount) * gridSize, i * shelfPitch});
    }
  }
  const double span = gridCount * gridSize, groupDistance = span / columns;
  // StepRain adds a column of groups, one per row, every spawnEvery steps.
  for (int column = 0; column < columns; ++column) {
    for (int row = 0; row < rows; ++row) {
      Vec2d at{-0.5 * span + groupDistance * (column + 0.5), 40 + shelfPitch * row};
      for (int i = 0; i < groupSize; ++i, at.x += 0.5) addHuman(scene, at, i + 1, column * spawnEvery);
    }
  }
  // A bone below the middle of its shelf's boxes, and not beyond the
  // shelf's ends (where ragdolls may fall off), went through it.
  const double shelfEnd = 0.5 * (span + gridSize);
  layout.sanity.escaped = [shelfPitch, shelfEnd](const Vec2d& start, const Pose& now) {
    return now.position.y < std::floor(start.y / shelfPitch) * shelfPitch && std::abs(now.position.x) < shelfEnd;
  };
  layout.sanity.pinGaps = true;
  return layout;
}

// ---- smash ------------------------------------------------------------------

SuiteLayout smash(bool quick) {
  const int columns = quick ? 20 : 120, rows = quick ? 10 : 80;
  const double d = 0.4;
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  scene.gravity = {0, 0};
  scene.allowSleep = true;
  BodyDesc ram = v3Body(ShapeDesc::box(4, 4), {-20, 0});
  ram.density = 8;
  ram.velocity = {40, 0};
  addBody(scene, ram);
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      BodyDesc box = v3Body(ShapeDesc::box(0.5 * d, 0.5 * d), {i * d + 30, (j - rows / 2.0) * d});
      box.startsAsleep = true;
      addBody(scene, box);
    }
  }
  return layout;
}

// ---- spinner ----------------------------------------------------------------

SuiteLayout spinner(bool quick) {
  const int pointCount = 360;
  const Vec2d drumCentre{0, 32};
  const double drumRadius = 40;
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  scene.allowSleep = true;
  // Clockwise: solid outside the loop, the bodies held inside.
  std::vector<Vec2d> points;
  for (int i = 0; i < pointCount; ++i) {
    const double angle = -2 * kPi * i / pointCount;
    points.push_back({drumRadius * std::cos(angle), drumRadius * std::sin(angle) + drumCentre.y});
  }
  BodyDesc drum = v3Body(ShapeDesc::chain(points, true), {}, true);
  drum.friction = 0.1;
  addBody(scene, drum);

  BodyDesc rotor = v3Body(ShapeDesc::polygon(ShapeDesc::box(0.4, 20).vertices, 0.2), {0, 12});
  rotor.friction = 0;
  addJoint(scene, worldMotor(addBody(scene, rotor), {0, 12}, 5, 1e10));

  const ShapeDesc shapes[] = {ShapeDesc::capsule({-0.25, 0}, {0.25, 0}, 0.25), ShapeDesc::circle(0.35),
                              ShapeDesc::box(0.35, 0.35)};
  const int bodyCount = quick ? 499 : 2 * 3038;
  double x = -23, y = 2;
  for (int i = 0; i < bodyCount; ++i) {
    BodyDesc body = v3Body(shapes[i % 3], {x, y});
    body.friction = 0.1;
    body.restitution = 0.1;
    body.density = 0.25;
    addBody(scene, body);
    x += 0.5;
    if (x >= 23) {
      x = -23;
      y += 0.5;
    }
  }
  layout.sanity.escaped = outsideCircle(drumCentre, drumRadius);
  return layout;
}

// ---- tumbler and washer -----------------------------------------------------

/// A grid of `count` x `count` squares of half-size `half`, `pitch` apart,
/// its lower left at `corner`.
void addSquareGrid(SceneDescription& scene, int count, double half, double pitch, Vec2d corner) {
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) {
      addBody(scene, v3Body(ShapeDesc::box(half, half), {corner.x + j * pitch, corner.y + i * pitch}));
    }
  }
}

SuiteLayout tumbler(bool quick) {
  const Vec2d centre{0, 10};
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  scene.allowSleep = true;
  BodyDesc frame = v3Body(ShapeDesc::box(0.5, 10, {10, 0}), centre);
  frame.extraShapes = {ShapeDesc::box(0.5, 10, {-10, 0}), ShapeDesc::box(10, 0.5, {0, 10}),
                       ShapeDesc::box(10, 0.5, {0, -10})};
  frame.density = 50;
  addJoint(scene, worldMotor(addBody(scene, frame), centre, 25 * kPi / 180, 1e8));
  const int gridCount = quick ? 20 : 45;
  addSquareGrid(scene, gridCount, 0.125, 0.4, {-0.2 * gridCount, -0.2 * gridCount + centre.y});
  // Inside the frame's walls whatever its turn: within half its inner diagonal.
  layout.sanity.escaped = outsideCircle(centre, 9.5 * std::numbers::sqrt2);
  return layout;
}

/// The washer's drum piece between radii r0 and r1 from direction u1 to u2:
/// corners outward along u1, across, and back along u2 (anticlockwise).
ShapeDesc ringPiece(double r0, double r1, Vec2d u1, Vec2d u2) {
  return ShapeDesc::polygon({{r0 * u1.x, r0 * u1.y}, {r1 * u1.x, r1 * u1.y}, {r1 * u2.x, r1 * u2.y}, {r0 * u2.x, r0 * u2.y}});
}

Vec2d direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

SuiteLayout washer(bool quick) {
  const Vec2d centre{0, 10};
  const double r0 = 14, r1 = 16, r2 = 18, piece = kPi / 18, overlap = 0.1 * piece;
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  scene.allowSleep = true;
  BodyDesc drum = v3Body(ringPiece(r1, r2, direction(-overlap), direction(piece + overlap)), centre);
  drum.isKinematic = true;
  drum.angularVelocity = 25 * kPi / 180;
  drum.velocity = {0.001, -0.002};
  for (int i = 0; i < 36; ++i) {
    const double a1 = i * piece, a2 = i == 35 ? 2 * kPi : (i + 1) * piece;
    // Each ring piece overlaps its neighbours by a tenth of a piece.
    if (i > 0) drum.extraShapes.push_back(ringPiece(r1, r2, direction(a1 - overlap), direction(a2 + overlap)));
    if (i % 9 == 0) drum.extraShapes.push_back(ringPiece(r0, r1, direction(a1), direction(a2)));
  }
  addBody(scene, drum);
  const int gridCount = quick ? 20 : 90;
  const double half = 0.1;
  addSquareGrid(scene, gridCount, half, 2.1 * half, {-1.1 * half * gridCount, -1.1 * half * gridCount + centre.y});
  layout.sanity.escaped = outsideCircle(centre, r1);
  return layout;
}

// ---- compounds and junkyard -------------------------------------------------

/// A floor of `floorCount` boxes on y = 0 centred on x = 0 and two walls of
/// `wallCount` boxes at x = +-halfWidth, grid 1 m, each box a static body.
void addBin(SceneDescription& scene, int floorCount, int wallCount, double halfWidth) {
  for (int i = 0; i < floorCount; ++i) addStatic(scene, ShapeDesc::box(0.55, 0.5), {i - halfWidth, 0});
  for (double side : {-halfWidth, halfWidth}) {
    for (int i = 0; i < wallCount; ++i) addStatic(scene, ShapeDesc::box(0.5, 0.55), {side, i + 1.0});
  }
}

SuiteLayout compounds(bool quick) {
  const int columns = quick ? 10 : 20, rows = quick ? 40 : 150;
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  scene.allowSleep = true;
  addBin(scene, 81, 100, 40);
  addStatic(scene, ShapeDesc::segment({-800, -80}, {800, -80}));
  const ShapeDesc left = ShapeDesc::polygon({{-1, 0}, {0.5, 1}, {0, 2}});
  const ShapeDesc right = ShapeDesc::polygon({{1, 0}, {0, 2}, {-0.5, 1}});
  const double shift = 2, extraY = 0.25, centreX = shift * columns / 2 - 1, centreY = 1.15 / 2, yStart = 5;
  double side = 0.25;
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j, side = -side) {
      BodyDesc body = v3Body(left, {i * shift - centreX + side, j * (shift + extraY) + centreY + yStart});
      body.extraShapes = {right};
      body.friction = 0.5;
      addBody(scene, body);
    }
  }
  layout.sanity.escaped = outsideBox(0, 40);
  return layout;
}

/// Junkyard's pentagon: five points of a Fibonacci spiral on a circle of
/// radius 0.25, in angle order.
ShapeDesc junk() {
  const double radius = 0.25, phi = kPi * (std::sqrt(5.0) - 1);
  std::vector<double> angles;
  for (int i = 0; i < 5; ++i) angles.push_back(std::remainder(phi * i, 2 * kPi));
  std::sort(angles.begin(), angles.end());
  std::vector<Vec2d> points;
  for (double angle : angles) points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  return ShapeDesc::polygon(points);
}

SuiteLayout junkyard(bool quick) {
  const int columns = 200, rows = quick ? 2 : 40;
  const double radius = 0.25, yStart = 15;
  SuiteLayout layout;
  SceneDescription& scene = layout.scene;
  scene.allowSleep = true;
  addBin(scene, 161, 50, 80);
  const ShapeDesc piece = junk();
  double side = -0.1;
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j, side = -side) {
      addBody(scene, v3Body(piece, {1.5 * (2 * i - columns) * radius + side, 4 * j * radius + yStart}));
    }
  }
  BodyDesc pusher = v3Body(ShapeDesc::box(2, 4, {0, 4}), {0, 0});
  pusher.isKinematic = true;
  scene.targets.push_back({addBody(scene, pusher), [](double time) { return Vec2d{60 * std::sin(0.2 * time), 0}; }});
  layout.sanity.escaped = outsideBox(0, 80);
  return layout;
}

}  // namespace

void addBox2DSuiteScenes(SceneList& scenes, bool quick) {
  struct Entry {
    const char* name;
    SuiteLayout (*layout)(bool quick);
    int v3Steps;  ///< benchmark/main.c's step count
  };
  const Entry entries[] = {{"joint_grid", jointGrid, 500},     {"large_pyramid", largePyramid, 500},
                           {"many_pyramids", manyPyramids, 200}, {"rain", rain, 1000},
                           {"smash", smash, 300},               {"spinner", spinner, 500},
                           {"tumbler", tumbler, 750},           {"washer", washer, 500},
                           {"compounds", compounds, 500},       {"junkyard", junkyard, 800}};
  for (const Entry& entry : entries) {
    // Short runs on a shared machine: at most 300 steps (rain's last wave
    // lands at step 312), the first step untimed as in v3's benchmark.
    const int steps = quick ? 5 : std::min(entry.v3Steps, 300);
    scenes.push_back(std::make_unique<SuiteScene>(std::string("v3-") + entry.name,
                                                  [layout = entry.layout, quick] { return layout(quick); },
                                                  RunLength{1, steps - 1, 1, quick ? 1 : 10}));
  }
}

}  // namespace bench
