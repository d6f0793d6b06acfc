// Solver2D's scene collection (erincatto/solver2d samples/collection, commit
// d178a56), scene for scene with its sizes, densities, frictions and
// gravity (10 m/s^2), and Solver2D's defaults elsewhere: density 1,
// friction 0.6, restitution 0. The "far" scenes are their near twins moved
// 40-100 km from the origin, built and measured alike, with the world's
// origin moved out to them (SceneDescription::origin) where an engine can.
//
// Left to other families, as they are the same scene: the pyramid
// (pyramid-20 and -100, stacking.cpp), the friction ramp (friction-ramp, the
// same five coefficients on 0.25 rad slopes, as closed forms) and the
// confined crowd (confined, circles.cpp). Rush (a force towards the centre
// every step) and warm-start energy (a body removed mid-run) need what no
// description holds: they are engine tests only
// (tests/engine/solver2d_scenes_test.cpp).
//
// Beyond Solver2D's collection: the card house's twin built with every card
// touching its supports (s2d-card-house-touching), whose cards only give
// and slide.
//
// Where the description departs from Solver2D, for every engine alike: the
// chains' and the bridge's angular damping (0.1/s) is left out, their
// linear damping kept; the far ragdoll pile stands 80 km out, not
// Solver2D's 6 km, to be as far as the other far scenes.

#include <array>
#include <numbers>

#include "contact_slip.h"
#include "joint_error.h"
#include "scene_helpers.h"

namespace bench {

namespace {

constexpr double kPi = std::numbers::pi;

/// A body of Solver2D's default shape values unless given.
BodyDesc s2Body(ShapeDesc shape, Vec2d position, double friction = 0.6, double density = 1,
                bool isStatic = false) {
  BodyDesc body = makeBody(std::move(shape), position, impulse::Material::Solid, isStatic);
  body.density = density;
  body.friction = friction;
  body.restitution = 0;
  return body;
}

int addStatic(SceneDescription& scene, ShapeDesc shape, Vec2d position = {},
              double friction = 0.6) {
  return addBody(scene, s2Body(std::move(shape), position, friction, 1, true));
}

SceneDescription solver2DWorld() {
  SceneDescription scene;
  scene.gravity = {0, -10};
  return scene;
}

/// The scene moved by `offset`: every body and every joint anchor, with the
/// world's origin put there, as a user building a level that far out would.
SceneDescription shifted(SceneDescription scene, Vec2d offset) {
  scene.origin = offset;
  auto move = [&](Vec2d& p) {
    p.x += offset.x;
    p.y += offset.y;
  };
  for (BodyDesc& body : scene.bodies) move(body.position);
  for (JointDesc& joint : scene.joints) {
    move(joint.anchorA);
    move(joint.anchorB);
  }
  return scene;
}

// ---- watches ---------------------------------------------------------------

/// Where a body must come to rest: its end position minus its start.
struct RestTarget {
  int body;
  Vec2d drop;
};
using RestTargets = std::vector<RestTarget> (*)(const SceneDescription& scene);

/// Bodies that must come to rest where `targetsOf` says: the worst distance
/// from there at the end, and the fastest body then.
template <RestTargets targetsOf>
class RestWatch final : public Measure {
 public:
  explicit RestWatch(const SceneDescription& scene) : scene_(scene), targets_(targetsOf(scene)) {}
  void observe(const EngineAdapter&, int) override {}
  std::vector<Metric> results(const EngineAdapter& engine) override {
    double worst = 0;
    for (const RestTarget& target : targets_) {
      const Vec2d& start = scene_.bodies[std::size_t(target.body)].position;
      worst = std::max(worst, distance(engine.pose(target.body).position,
                                       {start.x + target.drop.x, start.y + target.drop.y}));
    }
    return {{"rest err m", worst}, {"end speed m/s", fastest(engine, dynamicBodies(scene_))}};
  }

 private:
  const SceneDescription& scene_;
  std::vector<RestTarget> targets_;
};

/// Every dynamic body of the scene, to rest `drop(body)` from its start.
template <class Drop>
std::vector<RestTarget> restingAll(const SceneDescription& scene, Drop drop) {
  std::vector<RestTarget> all;
  for (int i : dynamicBodies(scene)) all.push_back({i, drop(i)});
  return all;
}

/// A scene that must not move: the farthest any body got from its start at
/// any step; the farthest any body got, after the first second, from where
/// it was then (the card house is built with gaps between its cards that
/// put its top cards' resting place about 2 cm below their start: only once
/// they have closed is a card's move its own); and the fastest body at the
/// end.
class MoveWatch final : public Measure {
 public:
  explicit MoveWatch(const SceneDescription& scene)
      : scene_(scene), moving_(dynamicBodies(scene)) {}
  void observe(const EngineAdapter& engine, int step) override {
    const bool settled = (step + 1) * kDt >= kSettleTime - 1e-9;
    if (settled && settledAt_.empty()) {
      for (int i : moving_) settledAt_.push_back(engine.pose(i).position);
    }
    for (std::size_t k = 0; k < moving_.size(); ++k) {
      const Vec2d at = engine.pose(moving_[k]).position;
      move_ = std::max(move_, distance(at, scene_.bodies[std::size_t(moving_[k])].position));
      if (settled) settledMove_ = std::max(settledMove_, distance(at, settledAt_[k]));
    }
  }
  std::vector<Metric> results(const EngineAdapter& engine) override {
    return {{"max move m", move_}, {"settled move m", settledMove_}, {"end speed m/s", fastest(engine, moving_)}};
  }

 private:
  static constexpr double kSettleTime = 1;  ///< s
  const SceneDescription& scene_;
  std::vector<int> moving_;
  std::vector<Vec2d> settledAt_;
  double move_ = 0;
  double settledMove_ = 0;
};

/// A house of polygons that must stand, judged as Solver2D words it (no
/// piece slipping more than 1 cm): first the largest slip of one piece
/// along another where they touch (ContactSlipProbe), then MoveWatch's
/// figures, whose farthest move from the start counts a house sinking as a
/// whole.
class ContactSlipWatch final : public Measure {
 public:
  explicit ContactSlipWatch(const SceneDescription& scene) : moves_(scene), contacts_(scene) {}
  void observe(const EngineAdapter& engine, int step) override {
    moves_.observe(engine, step);
    contacts_.observe(engine);
  }
  std::vector<Metric> results(const EngineAdapter& engine) override {
    std::vector<Metric> figures{{"contact slip m", contacts_.largestSlip()}};
    for (Metric& figure : moves_.results(engine)) figures.push_back(std::move(figure));
    return figures;
  }

 private:
  MoveWatch moves_;
  ContactSlipProbe contacts_;
};

/// Joints that must hold: the worst pin gap at any step and at the end, how
/// far the body that dropped most is below its start at the end (a bridge's
/// sag), and the fastest body at the end.
class HoldWatch final : public Measure {
 public:
  explicit HoldWatch(const SceneDescription& scene)
      : scene_(scene), probe_(scene), moving_(dynamicBodies(scene)) {}
  void observe(const EngineAdapter& engine, int) override {
    gap_ = std::max(gap_, probe_.worstPinGap(engine));
  }
  std::vector<Metric> results(const EngineAdapter& engine) override {
    double drop = 0;
    for (int i : moving_)
      drop = std::max(drop, scene_.bodies[std::size_t(i)].position.y - engine.pose(i).position.y);
    return {{"pin gap m", gap_},
            {"end gap m", probe_.worstPinGap(engine)},
            {"max drop m", drop},
            {"end speed m/s", fastest(engine, moving_)}};
  }

 private:
  const SceneDescription& scene_;
  JointProbe probe_;
  std::vector<int> moving_;
  double gap_ = 0;
};

// ---- contact scenes --------------------------------------------------------

SceneDescription singleBox() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::segment({-66, 0}, {66, 0}), {}, 0.5);
  addBody(scene, s2Body(ShapeDesc::box(1, 1), {0, 4}, 0.5));
  return scene;
}

/// The box lands 3 m down.
std::vector<RestTarget> singleBoxRest(const SceneDescription&) { return {{1, {0, -3}}}; }

/// Three pyramids of 2 m boxes, 10 at the base, each topped by a box of
/// 100, 200 and 300 times their density dropped from 2 m above its place.
SceneDescription highMassRatio1() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::segment({-66, 0}, {66, 0}), {}, 0.5);
  for (int j = 0; j < 3; ++j) {
    const double offset = -20 + 2 * 11 * j;
    double y = 1;
    for (int count = 10; count > 0; --count, y += 2) {
      for (int i = 0; i < count; ++i) {
        const double x = 2 * (i - 0.5 * count) + offset;
        const bool top = count == 1;
        addBody(scene,
                s2Body(ShapeDesc::box(1, 1), {x, top ? y + 2 : y}, 0.5, top ? (j + 1) * 100.0 : 1));
      }
    }
  }
  return scene;
}

/// The heavy tops land 2 m down; every other box stays.
std::vector<RestTarget> highMassRatio1Rest(const SceneDescription& scene) {
  return restingAll(scene, [&](int i) {
    return Vec2d{0, scene.bodies[std::size_t(i)].density > 1 ? -2.0 : 0.0};
  });
}

/// A 20 m box dropped 15 m onto two 1 m boxes 18 m apart (400:1 each), on a
/// segment (2) or on a thick box (3).
SceneDescription highMassRatio(bool thickGround) {
  SceneDescription scene = solver2DWorld();
  if (thickGround) {
    addStatic(scene, ShapeDesc::box(40, 2), {0, -2});
  } else {
    addStatic(scene, ShapeDesc::segment({-20, 0}, {20, 0}));
  }
  addBody(scene, s2Body(ShapeDesc::box(0.5, 0.5), {-9, 0.5}));
  addBody(scene, s2Body(ShapeDesc::box(0.5, 0.5), {9, 0.5}));
  addBody(scene, s2Body(ShapeDesc::box(10, 10), {0, 26}));
  return scene;
}

/// The big box comes to rest on the small ones (its centre 15 m lower),
/// level, with both still under it: how far it sank below that, its tilt,
/// and how far the small boxes slid.
class HighMassRatioWatch final : public Measure {
 public:
  explicit HighMassRatioWatch(const SceneDescription& scene) : scene_(scene) {}
  void observe(const EngineAdapter&, int) override {}
  std::vector<Metric> results(const EngineAdapter& engine) override {
    const Pose big = engine.pose(3);
    double slide = 0;
    for (int small : {1, 2})
      slide = std::max(slide, distance(engine.pose(small).position, start(small)));
    return {{"sink m", start(3).y - 15 - big.position.y},
            {"tilt rad", std::abs(big.angle)},
            {"support slide m", slide}};
  }

 private:
  const Vec2d& start(int body) const { return scene_.bodies[std::size_t(body)].position; }
  const SceneDescription& scene_;
};

/// Four rows of 1 m boxes, each a quarter inside its neighbours, on a segment.
SceneDescription overlapRecovery() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::segment({-40, 0}, {40, 0}));
  const int baseCount = 4;
  const double extent = 0.5, fraction = 0.75;
  double y = extent;
  for (int i = 0; i < baseCount; ++i, y += 2 * fraction * extent) {
    double x = fraction * extent * (i - baseCount);
    for (int j = i; j < baseCount; ++j, x += 2 * fraction * extent) {
      addBody(scene, s2Body(ShapeDesc::box(extent, extent), {x, y}));
    }
  }
  return scene;
}

/// 15 boxes 10 cm apart, alternately 1 cm left and right, friction 0.3:
/// each falls onto the one below and the column must stay straight.
SceneDescription verticalStack() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::box(100, 1), {0, -1});
  for (int i = 0; i < 15; ++i) {
    addBody(scene,
            s2Body(ShapeDesc::box(0.5, 0.5), {i % 2 == 0 ? -0.01 : 0.01, 0.55 + 1.1 * i}, 0.3));
  }
  return scene;
}

/// Box k (body k + 1) lands 5 cm + 10 cm times k lower, straight down.
std::vector<RestTarget> verticalStackRest(const SceneDescription& scene) {
  return restingAll(scene, [](int i) { return Vec2d{0, -0.05 - 0.1 * (i - 1)}; });
}

/// The anticlockwise quadrilateral through four corners, as a polygon about
/// their mean (the body's origin), added as one body.
void addQuad(SceneDescription& scene, std::array<Vec2d, 4> corners) {
  Vec2d mean;
  for (const Vec2d& p : corners) {
    mean.x += 0.25 * p.x;
    mean.y += 0.25 * p.y;
  }
  double twiceArea = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec2d &a = corners[i], &b = corners[(i + 1) % 4];
    twiceArea += a.x * b.y - b.x * a.y;
  }
  if (twiceArea < 0) std::reverse(corners.begin(), corners.end());
  std::vector<Vec2d> local;
  for (const Vec2d& p : corners) local.push_back({p.x - mean.x, p.y - mean.y});
  addBody(scene, s2Body(ShapeDesc::polygon(local), mean));
}

/// 17 stones between two curves, no mortar, friction 0.6, and four slabs on
/// the keystone.
SceneDescription arch() {
  // Solver2D's inner and outer curves (x, y), scaled by 0.25 below.
  const Vec2d inner[9] = {{16.0, 0.0},
                          {14.93803712795643, 5.133601056842984},
                          {13.79871746027416, 10.24928069555078},
                          {12.56252963284711, 15.34107019122473},
                          {11.20040987372525, 20.39856541571217},
                          {9.66521217819836, 25.40369899225096},
                          {7.87179930638133, 30.3179337000085},
                          {5.635199558196225, 35.03820717801641},
                          {2.405937953536585, 39.09554102558315}};
  const Vec2d outer[9] = {{24.0, 0.0},
                          {22.33619528222415, 6.02299846205841},
                          {20.54936888969905, 12.00964361211476},
                          {18.60854610798073, 17.9470321677465},
                          {16.46769273811807, 23.81367936585418},
                          {14.05325025774858, 29.57079353071012},
                          {11.23551045834022, 35.13775818285372},
                          {7.752568160730571, 40.30450679009583},
                          {3.016931552701656, 44.28891593799322}};
  auto in = [&](int i, double side) { return Vec2d{0.25 * side * inner[i].x, 0.25 * inner[i].y}; };
  auto out = [&](int i, double side) { return Vec2d{0.25 * side * outer[i].x, 0.25 * outer[i].y}; };
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::segment({-100, 0}, {100, 0}));
  for (double side : {1.0, -1.0}) {
    for (int i = 0; i < 8; ++i)
      addQuad(scene, {in(i, side), out(i, side), out(i + 1, side), in(i + 1, side)});
  }
  addQuad(scene, {in(8, 1), out(8, 1), out(8, -1), in(8, -1)});
  for (int i = 0; i < 4; ++i)
    addBody(scene, s2Body(ShapeDesc::box(2, 0.5), {0, 0.5 + out(8, 1).y + i}));
  return scene;
}

/// 15 dominoes 1 m apart, the first pushed at its top by 0.2 N*s.
SceneDescription doubleDomino() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::box(100, 1), {0, -1});
  for (int i = 0; i < 15; ++i) {
    BodyDesc domino = s2Body(ShapeDesc::box(0.125, 0.5), {-7.5 + i, 0.5});
    if (i == 0) {
      const double m = mass(domino), inertia = m * (0.25 * 0.25 + 1) / 12, push = 0.2, lever = 0.5;
      domino.velocity = {push / m, 0};
      domino.angularVelocity = -lever * push / inertia;
    }
    addBody(scene, domino);
  }
  return scene;
}

/// When each domino tipped past 30 degrees: how many did, and whether each
/// tipped after the one before it.
class DominoWatch final : public Measure {
 public:
  explicit DominoWatch(const SceneDescription& scene)
      : dominoes_(dynamicBodies(scene)), tipped_(dominoes_.size(), -1) {}
  void observe(const EngineAdapter& engine, int step) override {
    for (std::size_t i = 0; i < dominoes_.size(); ++i) {
      if (tipped_[i] < 0 && std::abs(engine.pose(dominoes_[i]).angle) > kPi / 6)
        tipped_[i] = (step + 1) * kDt;
    }
  }
  std::vector<Metric> results(const EngineAdapter&) override {
    const double fallen =
        double(std::count_if(tipped_.begin(), tipped_.end(), [](double t) { return t >= 0; }));
    bool inOrder = fallen == double(tipped_.size());
    for (std::size_t i = 1; inOrder && i < tipped_.size(); ++i)
      inOrder = tipped_[i] > tipped_[i - 1];
    // Headline: how many did not fall (lower is better).
    return {{"standing", double(tipped_.size()) - fallen},
            {"in order", inOrder ? 1.0 : 0.0},
            {"last tip s", inOrder ? tipped_.back() : 99.0}};
  }

 private:
  std::vector<int> dominoes_;
  std::vector<double> tipped_;
};

/// Where a card house's cards stand (its storeys from the ground up): each
/// storey's pairs of cards leaning at 25 degrees, 35 cm apart, with flat
/// cards lying across neighbouring pairs, each storey's first pair 17.5 cm
/// right of the one below.
struct CardHouseLayout {
  double firstLeanY;      ///< height of the first storey's leaning cards' centres
  double storeyRise;      ///< from one storey's leaning cards' centres to the next's
  double flatAboveLean;   ///< from a storey's leaning cards' centres to its flat cards'
  double leanFromMiddle;  ///< a leaning card's centre from its pair's middle, sideways
  /// Flat cards of a storey collide with each other (each storey's overlap
  /// 5 cm end to end at the same height).
  bool flatsCollide;
};

constexpr double kCardHalfLength = 0.2, kCardHalfThickness = 0.001;
constexpr double kCardLean = 25 * kPi / 180;

/// PEEL's card house: five storeys of 2 mm x 40 cm cards leaning at 25
/// degrees, flat cards between, friction 0.7. Its gaps (2.3 mm under each
/// flat card and under each pair above the first storey, 4.1 mm between
/// the tops of a pair) put the top cards' resting place about 2 cm lower;
/// its first storey's feet start 1.7 mm inside the ground.
constexpr CardHouseLayout kPeelCardHouse{0.18, 0.37, 0.185, 0.0875, true};

/// The same house with every card where it rests touching its supports:
/// each leaning card's lowest corner on the ground or the flat card below,
/// a pair's inner top corners meeting at the pair's middle, the flat cards
/// on the pairs' outer top corners (the highest). Flat cards of a storey lie
/// side by side (in 3D) and do not collide with each other.
CardHouseLayout touchingCardHouse() {
  const double h = kCardHalfLength, t = kCardHalfThickness;
  const double s = std::sin(kCardLean), c = std::cos(kCardLean);
  const double leanAboveSupport = h * c + t * s;   // centre over its lowest corner
  const double flatAboveLean = h * c + t * s + t;  // highest corner, then half a card
  return {leanAboveSupport, leanAboveSupport + flatAboveLean + t, flatAboveLean, h * s + t * c,
          false};
}

SceneDescription cardHouse(const CardHouseLayout& layout) {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::box(40, 2), {0, -2}, 0.7);
  auto card = [&](Vec2d at, double angle, bool flat) {
    BodyDesc body = s2Body(ShapeDesc::box(kCardHalfThickness, kCardHalfLength), at, 0.7);
    if (flat && !layout.flatsCollide) body.shape.filter.group = -1;
    body.angle = angle;
    addBody(scene, body);
  };
  constexpr double kPairPitch = 0.35, kFlatFromPair = 0.25;
  double z0 = 0, y = layout.firstLeanY;
  for (int pairs = 5; pairs > 0; --pairs, y += layout.storeyRise, z0 += 0.5 * kPairPitch) {
    for (int i = 0; i < pairs; ++i) {
      const double z = z0 + i * kPairPitch, middle = z + 0.25 * kPairPitch;
      if (i != pairs - 1) card({z + kFlatFromPair, y + layout.flatAboveLean}, 0.5 * kPi, true);
      card({middle - layout.leanFromMiddle, y}, -kCardLean, false);
      card({middle + layout.leanFromMiddle, y}, kCardLean, false);
    }
  }
  return scene;
}

/// Ten 1 m circles dropped one above another, 1 m apart.
SceneDescription circleStack() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::segment({-40, 0}, {40, 0}));
  for (int i = 0; i < 10; ++i) addBody(scene, s2Body(ShapeDesc::circle(1), {0, 4 + 3.0 * i}));
  return scene;
}

/// Circle k (body k + 1) rests straight below its start, at 1 + 2 k.
std::vector<RestTarget> circleStackRest(const SceneDescription& scene) {
  return restingAll(scene, [](int i) { return Vec2d{0, -3.0 - (i - 1)}; });
}

// ---- far twins' own layouts ------------------------------------------------

/// Ten rows of 1 m boxes built 25 cm apart every way, falling into a pyramid.
SceneDescription loosePyramid() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::box(100, 1), {0, -1});
  const int baseCount = 10;
  const double h = 0.5, shift = 1.25 * h;
  for (int i = 0; i < baseCount; ++i) {
    const double y = (2 * i + 1) * shift + 0.5;
    for (int j = i; j < baseCount; ++j) {
      addBody(scene, s2Body(ShapeDesc::box(h, h),
                            {(i + 1) * shift + 2 * (j - i) * shift - h * baseCount, y}));
    }
  }
  return scene;
}

/// Row r lands on row r - 1, straight down: it starts 1.25 r above the base
/// row and 0.625 + 0.25 r above its rest.
std::vector<RestTarget> loosePyramidRest(const SceneDescription& scene) {
  const double base = scene.bodies[std::size_t(dynamicBodies(scene).front())].position.y;
  return restingAll(scene, [&](int i) {
    const double row = std::round((scene.bodies[std::size_t(i)].position.y - base) / 1.25);
    return Vec2d{0, -0.625 - 0.25 * row};
  });
}

/// A plank on a small circle and a small box, two squares on the plank.
SceneDescription smallStack() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::box(10, 1), {0, -1});
  addBody(scene, s2Body(ShapeDesc::circle(0.1), {1.875, 0.125}));
  addBody(scene, s2Body(ShapeDesc::box(0.1, 0.125), {-1.875, 0.15}));
  addBody(scene, s2Body(ShapeDesc::box(2, 0.05), {0, 0.325}));
  addBody(scene, s2Body(ShapeDesc::box(0.25, 0.25), {-0.5, 0.9}));
  addBody(scene, s2Body(ShapeDesc::box(0.5, 0.5), {-0.55, 1.7}));
  return scene;
}

// ---- joint scenes ----------------------------------------------------------

/// 160 planks 1 m long (density 20) pinned end to end between two world pins
/// 160 m apart: it sags only as far as its pins stretch.
SceneDescription bridge() {
  SceneDescription scene = solver2DWorld();
  const int count = 160;
  const double left = -80, height = 20;
  int previous = kWorldBody;
  for (int i = 0; i < count; ++i) {
    BodyDesc plank = s2Body(ShapeDesc::box(0.5, 0.125), {left + 0.5 + i, height}, 0.6, 20);
    plank.linearDamping = 0.1;
    const int index = addBody(scene, plank);
    addJoint(scene, makePin(index, previous, {left + i, height}));
    previous = index;
  }
  addJoint(scene, makePin(previous, kWorldBody, {left + count, height}));
  return scene;
}

/// A horizontal chain of `count` capsule links (half length hx, density 20)
/// hung from a world pin at its left end, starting at y = count * hx;
/// returns the last link.
int addHangingChain(SceneDescription& scene, int count, double hx, double radius) {
  const double y = count * hx;
  int previous = kWorldBody;
  for (int i = 0; i < count; ++i) {
    BodyDesc link =
        s2Body(ShapeDesc::capsule({-hx, 0}, {hx, 0}, radius), {(1 + 2 * i) * hx, y}, 0.6, 20);
    link.linearDamping = 0.1;
    const int index = addBody(scene, link);
    addJoint(scene, makePin(index, previous, {2 * i * hx, y}));
    previous = index;
  }
  return previous;
}

/// 40 links of 1 m and an 8 m ball of the same density (about 670 links'
/// mass) at the end.
SceneDescription ballAndChain() {
  SceneDescription scene = solver2DWorld();
  const int count = 40;
  const double hx = 0.5, radius = 8;
  const int last = addHangingChain(scene, count, hx, 0.125);
  BodyDesc ball =
      s2Body(ShapeDesc::circle(radius), {(1 + 2 * count) * hx + radius - hx, count * hx}, 0.6, 20);
  ball.linearDamping = 0.1;
  addJoint(scene, makePin(addBody(scene, ball), last, {2 * count * hx, count * hx}));
  return scene;
}

/// 40 links of 20 cm (radius 2.5 cm).
SceneDescription chain() {
  SceneDescription scene = solver2DWorld();
  addHangingChain(scene, 40, 0.1, 0.025);
  return scene;
}

/// One bone of Solver2D's human (samples/collection/human.cpp) at scale 1:
/// a capsule along y about the body's origin at height `y`, pinned to its
/// parent at `pivotY` with limits (in half-turns) and a friction motor of
/// `torque` times 0.025 N*m.
struct Bone {
  double y;
  double bottom, top, radius;
  int parent;  ///< index into kHuman; -1 for the hip
  double pivotY, lowerTurns, upperTurns;
  double torque;
};

// hip, torso, head, upper and lower left leg, upper and lower right leg,
// upper and lower left arm, upper and lower right arm.
constexpr Bone kHuman[] = {
    {0.95, -0.02, 0.025, 0.095, -1, 0, 0, 0, 0},
    {1.2, -0.135, 0.135, 0.09, 0, 1.025, -0.25, 0, 0.5},
    {1.5, -0.0325, 0.0325, 0.08, 1, 1.4, -0.3, 0.1, 0.25},
    {0.775, -0.125, 0.125, 0.055, 0, 0.9, -0.05, 0.4, 1},
    {0.475, -0.14, 0.125, 0.045, 3, 0.625, -0.5, -0.02, 0.5},
    {0.775, -0.125, 0.125, 0.055, 0, 0.9, -0.05, 0.4, 1},
    {0.475, -0.14, 0.125, 0.045, 5, 0.625, -0.5, -0.02, 0.5},
    {1.225, -0.125, 0.125, 0.035, 1, 1.35, -0.05, 0.8, 0.25},
    {0.975, -0.125, 0.125, 0.03, 7, 1.1, 0.01, 0.5, 0.1},
    {1.225, -0.125, 0.125, 0.035, 1, 1.35, -0.05, 0.8, 0.25},
    {0.975, -0.125, 0.125, 0.03, 9, 1.1, 0.01, 0.5, 0.1},
};
constexpr int kHead = 2;
constexpr int kLowerLegs[] = {4, 6};

/// Solver2D's human at `at` (its feet's level), friction 0.4 (its feet 0.1);
/// its bones never touch each other (group -group).
void addHuman(SceneDescription& scene, Vec2d at, int group) {
  const int first = static_cast<int>(scene.bodies.size());
  for (int b = 0; b < static_cast<int>(std::size(kHuman)); ++b) {
    const Bone& bone = kHuman[b];
    BodyDesc body = s2Body(ShapeDesc::capsule({0, bone.bottom}, {0, bone.top}, bone.radius),
                           {at.x, at.y + bone.y}, 0.4);
    body.shape.filter.group = -group;
    if (b == kHead) body.extraShapes.push_back(ShapeDesc::capsule({0, -0.12}, {0, -0.08}, 0.05));
    if (std::find(std::begin(kLowerLegs), std::end(kLowerLegs), b) != std::end(kLowerLegs)) {
      body.extraShapes.push_back(ShapeDesc::capsule({-0.02, -0.175}, {0.13, -0.175}, 0.03));
      body.extraShapes.back().friction = 0.1;
    }
    for (ShapeDesc& shape : body.extraShapes) shape.filter.group = -group;
    addBody(scene, body);
  }
  for (int b = 1; b < static_cast<int>(std::size(kHuman)); ++b) {
    const Bone& bone = kHuman[b];
    JointDesc pin = makePin(first + bone.parent, first + b, {at.x, at.y + bone.pivotY});
    pin.enableLimit = true;
    pin.lowerAngle = bone.lowerTurns * kPi;
    pin.upperAngle = bone.upperTurns * kPi;
    pin.enableMotor = true;
    pin.maxMotorTorque = 0.025 * bone.torque;
    addJoint(scene, pin);
  }
}

/// One human dropped from 4 m onto the ground.
SceneDescription ragdoll() {
  SceneDescription scene = solver2DWorld();
  addStatic(scene, ShapeDesc::box(20, 1), {0, -1});
  addHuman(scene, {0, 4}, 1);
  return scene;
}

/// Six humans dropped in a heap into a V of two tilted slabs.
SceneDescription ragdollPile() {
  SceneDescription scene = solver2DWorld();
  for (double side : {-1.0, 1.0}) {
    BodyDesc slab = s2Body(ShapeDesc::box(10, 0.5), {5 * side, 1}, 0.6, 1, true);
    slab.angle = 0.15 * kPi * side;
    addBody(scene, slab);
  }
  const Vec2d places[] = {{0, 0.5}, {-0.2, 1}, {0.2, 1}, {-0.4, 1.5}, {0.4, 1.5}, {0, 2}};
  for (int i = 0; i < 6; ++i) addHuman(scene, places[i], i + 1);
  return scene;
}

/// An n x n grid of 0.4 m circles (which never touch) pinned to their
/// neighbours 1 m apart, seven of its top row fixed, under twice gravity.
SceneDescription jointGrid(int n) {
  SceneDescription scene = solver2DWorld();
  scene.gravity = {0, -20};
  auto fixed = [&](int k, int i) { return k >= n / 2 - 3 && k <= n / 2 + 3 && i == 0; };
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < n; ++i) {
      ShapeDesc circle = ShapeDesc::circle(0.4);
      circle.filter.category = 2;
      circle.filter.mask = ~2u;
      const int body = addBody(scene, s2Body(circle, {double(k), double(-i)}, 0.6, 1, fixed(k, i)));
      // Pins between two fixed circles hold nothing.
      if (i > 0 && !(fixed(k, i) && fixed(k, i - 1)))
        addJoint(scene, makePin(body - 1, body, {double(k), -i + 0.5}));
      if (k > 0 && !(fixed(k, i) && fixed(k - 1, i)))
        addJoint(scene, makePin(body - n, body, {k - 0.5, double(-i)}));
    }
  }
  return scene;
}

constexpr Vec2d kStretchedTop{0, 39.5};

/// 40 circles that touch nothing, on pins meant 1 m apart but built 2 m
/// apart: every pin starts 1 m open and must pull shut.
SceneDescription stretchedChain() {
  SceneDescription scene = solver2DWorld();
  const int count = 40;
  int previous = kWorldBody;
  Vec2d above = kStretchedTop;
  for (int i = 0; i < count; ++i) {
    ShapeDesc circle = ShapeDesc::circle(0.2);
    circle.filter.mask = 0;
    const double y = 38.0 - 2 * i;
    const int body = addBody(scene, s2Body(circle, {0, y}));
    JointDesc pin = makePin(body, previous, {0, y + 0.5});
    pin.anchorB = above;
    addJoint(scene, pin);
    previous = body;
    above = {0, y - 0.5};
  }
  return scene;
}

/// The worst pin gap after the first second, the farthest any circle got
/// from the top pin, and the fastest circle after the first second.
class StretchedChainWatch final : public Measure {
 public:
  explicit StretchedChainWatch(const SceneDescription& scene)
      : probe_(scene), circles_(dynamicBodies(scene)) {}
  void observe(const EngineAdapter& engine, int step) override {
    for (int i : circles_)
      reach_ = std::max(reach_, distance(engine.pose(i).position, kStretchedTop));
    if ((step + 1) * kDt < 1 - 1e-9) return;
    gap_ = std::max(gap_, probe_.worstPinGap(engine));
    speed_ = std::max(speed_, fastest(engine, circles_));
  }
  std::vector<Metric> results(const EngineAdapter&) override {
    return {{"gap after 1 s m", gap_}, {"max reach m", reach_}, {"speed after 1 s m/s", speed_}};
  }

 private:
  JointProbe probe_;
  std::vector<int> circles_;
  double gap_ = 0;
  double reach_ = 0;
  double speed_ = 0;
};

/// A scene watched by a Measure built from its description alone (one of the
/// watches above), registered near or far from the origin.
/// `repeats`: timed runs (the large scenes run once).
template <class Watch>
void addScene(SceneList& scenes, bool quick, const std::string& name, SceneDescription (*layout)(),
              double seconds, Vec2d origin = {}, int repeats = 3) {
  const int steps = int(std::lround(seconds / kDt));
  addListedScene<Watch>(
      scenes, quick, "s2d-" + name, [layout, origin] { return shifted(layout(), origin); },
      RunLength{0, steps, repeats, 1}, RunLength{0, 5, 1, 1});
}

}  // namespace

void addSolver2DScenes(SceneList& scenes, bool quick) {
  addScene<RestWatch<singleBoxRest>>(scenes, quick, "single-box", singleBox, 2);
  addScene<RestWatch<highMassRatio1Rest>>(scenes, quick, "high-mass-ratio-1", highMassRatio1, 5);
  addScene<HighMassRatioWatch>(
      scenes, quick, "high-mass-ratio-2", [] { return highMassRatio(false); }, 5);
  addScene<HighMassRatioWatch>(
      scenes, quick, "high-mass-ratio-3", [] { return highMassRatio(true); }, 5);
  addScene<RestWatch<verticalStackRest>>(scenes, quick, "vertical-stack", verticalStack, 5);
  addScene<MoveWatch>(scenes, quick, "arch", arch, 10);
  addScene<DominoWatch>(scenes, quick, "double-domino", doubleDomino, 10);
  addScene<ContactSlipWatch>(
      scenes, quick, "card-house", [] { return cardHouse(kPeelCardHouse); }, 10);
  addScene<ContactSlipWatch>(
      scenes, quick, "card-house-touching", [] { return cardHouse(touchingCardHouse()); }, 10);
  addScene<RestWatch<circleStackRest>>(scenes, quick, "circle-stack", circleStack, 5);
  addScene<HoldWatch>(scenes, quick, "bridge", bridge, 5, {}, 1);
  addScene<HoldWatch>(scenes, quick, "ball-and-chain", ballAndChain, 5);
  addScene<HoldWatch>(scenes, quick, "ragdoll", ragdoll, 3);
  // Solver2D's release size, and a 30 x 30 grid small enough for a test.
  addScene<HoldWatch>(
      scenes, quick, "joint-grid", [] { return jointGrid(100); }, 2, {}, 1);
  addScene<HoldWatch>(
      scenes, quick, "joint-grid-30", [] { return jointGrid(30); }, 2);
  addScene<StretchedChainWatch>(scenes, quick, "stretched-chain", stretchedChain, 2);
  // The far scenes and their near twins, 40-100 km out as in Solver2D.
  addScene<RestWatch<loosePyramidRest>>(scenes, quick, "loose-pyramid", loosePyramid, 5);
  addScene<RestWatch<loosePyramidRest>>(scenes, quick, "far-pyramid", loosePyramid, 5,
                                        {100000, -80000});
  addScene<MoveWatch>(scenes, quick, "stack", smallStack, 5);
  addScene<MoveWatch>(scenes, quick, "far-stack", smallStack, 5, {40000, -25000});
  addScene<OverlapWatch>(scenes, quick, "overlap-recovery", overlapRecovery, 5);
  addScene<OverlapWatch>(scenes, quick, "far-recovery", overlapRecovery, 5, {80000, -70000});
  addScene<HoldWatch>(scenes, quick, "ragdoll-pile", ragdollPile, 3);
  addScene<HoldWatch>(scenes, quick, "far-ragdoll-pile", ragdollPile, 3, {80000, -60000});
  addScene<HoldWatch>(scenes, quick, "chain", chain, 3);
  addScene<HoldWatch>(scenes, quick, "far-chain", chain, 3, {40000, -35000});
}

}  // namespace bench
