// Presets 18-21: what shapes of their own make possible. A car on chain
// terrain, a kinematic elevator, a tumbler (one body of four boxes turned by
// a motor) and capsule ragdolls falling down stairs.

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "shape_presets.h"

namespace impulse {

namespace {

constexpr Real kPi = std::numbers::pi_v<Real>;
const Vec2 kSceneCentre = Real(0.5) * kSceneSize;

// ------------------------------------------------------------ terrain car

// Rolling hills under the car: y = base + height * (1 - cos) / 2 over each
// of three waves, sampled every 0.5 m.
std::vector<Vec2> hillPoints() {
  constexpr Real kBase = kSceneBorder + Real(0.5);
  constexpr Real kHeight = Real(0.9);
  constexpr Real kStep = Real(0.5);
  const Real left = 0, right = kSceneSize.x();
  std::vector<Vec2> points;
  // Right to left, so the ground is solid below the line (a chain collides
  // on the right of the way its points run).
  for (Real x = right; x >= left - Real(1e-3); x -= kStep) {
    const Real wave = 2 * kPi * 3 * (x - left) / (right - left);
    points.push_back(Vec2(x, kBase + kHeight * (1 - std::cos(wave)) / 2));
  }
  return points;
}

}  // namespace

PresetInfo terrainCarPreset(World& world) {
  addBoundary(world);
  const std::vector<Vec2> hills = hillPoints();
  world.createChain(hills, false, {.material = Material::Stone});
  addCar(world, Real(1.5), hills[hills.size() - 5].y() + Real(0.2));
  return {18,
          "Car on terrain",
          {"The car of preset 14 drives over rolling hills: one chain of 50",
           "one-sided segments, so the wheels roll over every join without a bump."},
          {},
          false, {}};
}

// ------------------------------------------------------------ elevator

namespace {

constexpr Real kElevatorLow = Real(1.5);   // platform centre at the bottom
constexpr Real kElevatorRise = Real(10);   // to the top
constexpr double kElevatorPeriod = 8;      // seconds up and down again
constexpr Real kElevatorHalfWidth = Real(2.5);

// Where the platform's centre is at `time`: a smooth rise and fall (zero
// speed at both ends, so the cargo is not thrown at the turn).
Real elevatorHeight(double time) {
  const double phase = 2 * std::numbers::pi * time / kElevatorPeriod;
  return kElevatorLow + kElevatorRise * Real((1 - std::cos(phase)) / 2);
}

}  // namespace

PresetInfo elevatorPreset(World& world) {
  addBoundary(world);
  const Real x = kSceneCentre.x();
  BodyOptions platformOptions{.material = Material::Metal, .properties = {.isKinematic = true}};
  const std::array<Vec2, 4> slab{Vec2(x - kElevatorHalfWidth, kElevatorLow - Real(0.25)),
                                 Vec2(x + kElevatorHalfWidth, kElevatorLow - Real(0.25)),
                                 Vec2(x + kElevatorHalfWidth, kElevatorLow + Real(0.25)),
                                 Vec2(x - kElevatorHalfWidth, kElevatorLow + Real(0.25))};
  const BodyId platform = world.createPolygon(slab, platformOptions).id;
  // Three crates side by side on the platform.
  for (int i = -1; i <= 1; ++i) {
    const Real cx = x + Real(1.4) * Real(i);
    const Real bottom = kElevatorLow + Real(0.25);
    const std::array<Vec2, 4> crate{Vec2(cx - Real(0.5), bottom), Vec2(cx + Real(0.5), bottom),
                                    Vec2(cx + Real(0.5), bottom + 1), Vec2(cx - Real(0.5), bottom + 1)};
    world.createPolygon(crate, {.material = Material::Wood});
  }
  PresetInfo info{19,
                  "Elevator",
                  {"A kinematic platform rises 10 m and comes down again every 8 s,",
                   "carrying three crates: it moves by its own velocity, is never pushed,",
                   "and the crates ride on it by friction and contact alone."},
                  {},
                  false, {}};
  info.drive = [platform, x](World& driven, double time, Real dt) {
    driven.setTargetTransform(platform, Vec2(x, elevatorHeight(time + dt)), 0, dt);
  };
  return info;
}

// ------------------------------------------------------------ tumbler

namespace {

constexpr Real kTumblerHalfSize = 5;
constexpr Real kTumblerWall = Real(0.25);
constexpr Real kTumblerSpeed = Real(0.6);  // rad/s, anticlockwise

// The four walls of the drum, body-local (centred on the body's origin).
std::vector<ShapeDef> tumblerWalls() {
  const Real h = kTumblerHalfSize, t = kTumblerWall;
  auto wall = [](Vec2 centre, Real halfWidth, Real halfHeight) {
    ShapeDef def{translated(Shape::makePolygon(makeBox(halfWidth, halfHeight)), centre), Material::Metal, {}, {}};
    return def;
  };
  return {wall(Vec2(0, -h), h + t, t), wall(Vec2(0, h), h + t, t), wall(Vec2(-h, 0), t, h - t),
          wall(Vec2(h, 0), t, h - t)};
}

}  // namespace

PresetInfo tumblerPreset(World& world) {
  addBoundary(world);
  const Vec2 centre(kSceneCentre.x(), kSceneCentre.y() + Real(0.5));
  std::vector<ShapeDef> walls = tumblerWalls();
  BodyDef drum = makeBodyDef(walls.front().shape, centre, {.material = Material::Metal});
  drum.extraShapes.assign(walls.begin() + 1, walls.end());
  const BodyId frame = world.createBody(drum).id;
  // Turned at a steady speed by a motor strong enough for the drum and its load.
  // The motor turns B (the world) against A (the drum): the drum turns the
  // other way.
  RevoluteJointSettings motor{.enableMotor = true, .motorSpeed = -kTumblerSpeed, .maxMotorTorque = 1e6f};
  world.createJoint({frame, BodyId{}, centre, centre, false, motor});
  // Forty pieces inside: boxes, circles and capsules in a grid.
  for (int row = 0; row < 5; ++row) {
    for (int column = 0; column < 8; ++column) {
      const Vec2 at = centre + Vec2(Real(-3.5) + Real(column), Real(-3) + Real(row) * Real(0.9));
      switch ((row + column) % 3) {
        case 0: world.createCircle(at, Real(0.35), {.material = Material::Rubber}); break;
        case 1: {
          const std::array<Vec2, 4> box{at + Vec2(-Real(0.3), -Real(0.3)), at + Vec2(Real(0.3), -Real(0.3)),
                                        at + Vec2(Real(0.3), Real(0.3)), at + Vec2(-Real(0.3), Real(0.3))};
          world.createPolygon(box, {.material = Material::Wood});
          break;
        }
        default: world.createCapsule(at - Vec2(Real(0.25), 0), at + Vec2(Real(0.25), 0), Real(0.2)); break;
      }
    }
  }
  return {20,
          "Tumbler",
          {"One body of four walls (four shapes) turned by a motor at 0.6 rad/s:",
           "the boxes, balls and capsules inside tumble over each other and never",
           "leave it."},
          {},
          false, {}};
}

// ------------------------------------------------------------ ragdolls

namespace {

// A ragdoll's parts, relative to its hips: capsules (centre1, centre2,
// radius) and a round head; and its joints (the parts they join, the pivot
// relative to the hips, the angle limits).
struct Limb {
  Vec2 from, to;
  Real radius;
};
constexpr int kTorso = 0;
const std::array<Limb, 7> kLimbs{{
    {Vec2(0, Real(0.1)), Vec2(0, Real(0.7)), Real(0.18)},                     // torso
    {Vec2(-Real(0.1), -Real(0.05)), Vec2(-Real(0.1), -Real(0.45)), Real(0.1)},  // left thigh
    {Vec2(-Real(0.1), -Real(0.55)), Vec2(-Real(0.1), -Real(0.95)), Real(0.09)},  // left shin
    {Vec2(Real(0.1), -Real(0.05)), Vec2(Real(0.1), -Real(0.45)), Real(0.1)},    // right thigh
    {Vec2(Real(0.1), -Real(0.55)), Vec2(Real(0.1), -Real(0.95)), Real(0.09)},   // right shin
    {Vec2(-Real(0.3), Real(0.75)), Vec2(-Real(0.3), Real(0.25)), Real(0.08)},   // left arm
    {Vec2(Real(0.3), Real(0.75)), Vec2(Real(0.3), Real(0.25)), Real(0.08)},     // right arm
}};
struct Hinge {
  int a, b;
  Vec2 pivot;
  Real lower, upper;
};
const std::array<Hinge, 6> kHinges{{
    {kTorso, 1, Vec2(-Real(0.1), 0), -Real(1.2), Real(0.6)},
    {1, 2, Vec2(-Real(0.1), -Real(0.5)), -Real(0.1), Real(2)},
    {kTorso, 3, Vec2(Real(0.1), 0), -Real(1.2), Real(0.6)},
    {3, 4, Vec2(Real(0.1), -Real(0.5)), -Real(0.1), Real(2)},
    {kTorso, 5, Vec2(-Real(0.3), Real(0.75)), -Real(2.5), Real(2.5)},
    {kTorso, 6, Vec2(Real(0.3), Real(0.75)), -Real(2.5), Real(2.5)},
}};

void addRagdoll(World& world, const Vec2& hips) {
  std::array<BodyId, kLimbs.size()> parts;
  for (std::size_t i = 0; i < kLimbs.size(); ++i) {
    parts[i] = world.createCapsule(hips + kLimbs[i].from, hips + kLimbs[i].to, kLimbs[i].radius,
                                   {.material = Material::Wood})
                   .id;
  }
  // The head rides on the torso's body as a second shape: a compound body.
  world.createShape(parts[kTorso], {Shape::makeCircle(Real(0.2), hips + Vec2(0, Real(1.0)) -
                                                                     world.bodyState(parts[kTorso])->position),
                                    Material::Wood, {}, {}});
  for (const Hinge& hinge : kHinges) {
    RevoluteJointSettings limits{.enableLimit = true, .lowerAngle = hinge.lower, .upperAngle = hinge.upper};
    world.createJoint({parts[std::size_t(hinge.a)], parts[std::size_t(hinge.b)], hips + hinge.pivot,
                       hips + hinge.pivot, false, limits});
  }
}

constexpr int kStairCount = 12;
constexpr Real kStairRun = Real(1.2);
constexpr Real kStairRise = Real(0.8);

}  // namespace

PresetInfo ragdollStairsPreset(World& world) {
  addBoundary(world);
  // Stairs down to the right from the left wall.
  for (int i = 0; i < kStairCount; ++i) {
    const Real left = kSceneBorder + kStairRun * Real(i);
    const Real top = kSceneBorder + kStairRise * Real(kStairCount - 1 - i);
    if (top > kSceneBorder) addStaticBox(world, Vec2(left, kSceneBorder), Vec2(left + kStairRun, top));
  }
  const Real topStep = kSceneBorder + kStairRise * Real(kStairCount - 1);
  for (int i = 0; i < 3; ++i) addRagdoll(world, Vec2(Real(1.3) + Real(0.9) * Real(i), topStep + Real(1.2) + Real(i)));
  // A push to send them over the edge.
  for (BodyId id : world.bodyIds()) {
    if (!world.bodyDescription(id)->properties.isStatic) world.setVelocity(id, Vec2(3, 0), 0);
  }
  return {21,
          "Ragdolls on stairs",
          {"Three ragdolls of capsules (the head a second shape on the torso) with",
           "limited hinges tumble down twelve steps. A hard landing stretches a joint",
           "by up to 10 cm for a moment; at rest every joint is closed again."},
          {},
          false, {}};
}

}  // namespace impulse
