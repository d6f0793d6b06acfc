// The scenes of docs/product.md. Layout follows the seed's 800x600 px canvas at
// 32 px/m: a floor and two walls whose visible parts are 25 px (0.78 m) thick,
// ramps as static triangles, balls of 20 px (0.625 m) radius.

#include <array>
#include <cmath>
#include <numbers>

#include "impulse/field_kinds.h"
#include "impulse/scenes/field_scenes.h"
#include "impulse/scenes/presets.h"
#include "shape_presets.h"

namespace impulse {

namespace {

constexpr Real kBorder = kSceneBorder;
constexpr Real kFloor = kBorder;         // top of the floor
constexpr Real kBallRadius = Real(0.625);
// The seed's balls roll to a stop on the floor; ours do it with real rolling
// resistance (in the material) plus this air drag, in 1/s.
constexpr Real kAirDrag = Real(0.25);

}  // namespace

void addStaticBox(World& world, Vec2 lower, Vec2 upper) {
  std::array<Vec2, 4> corners = {lower, Vec2(upper.x(), lower.y()), upper, Vec2(lower.x(), upper.y())};
  world.createPolygon(corners, {.properties = {.isStatic = true}});
}

/// Floor and two side walls, centred on the canvas edges as in the seed.
void addBoundary(World& world) {
  const Vec2 size = kSceneSize;
  addStaticBox(world, Vec2(0, -kBorder), Vec2(size.x(), kBorder));
  addStaticBox(world, Vec2(-kBorder, 0), Vec2(kBorder, size.y()));
  addStaticBox(world, Vec2(size.x() - kBorder, 0), Vec2(size.x() + kBorder, size.y()));
}

namespace {

void addCeiling(World& world) {
  const Vec2 size = kSceneSize;
  addStaticBox(world, Vec2(0, size.y() - kBorder), Vec2(size.x(), size.y() + kBorder));
}

/// A right-angled ramp on the floor `base`, tall side against the left wall,
/// descending to the right.
struct Ramp {
  Real base;    // height of the surface it stands on
  Real height;  // rise at the left end
  Real length;  // horizontal run
  Real left = kBorder;

  Real surfaceAt(Real x) const { return base + height * (1 - (x - left) / length); }
  Real slopeAngle() const { return std::atan2(height, length); }
};

void addRamp(World& world, const Ramp& ramp) {
  std::array<Vec2, 3> corners = {Vec2(ramp.left, ramp.base), Vec2(ramp.left + ramp.length, ramp.base),
                                 Vec2(ramp.left, ramp.base + ramp.height)};
  world.createPolygon(corners, {.properties = {.isStatic = true}});
}

BodyOptions ballOptions(Material material) {
  return {.material = material, .properties = {.linearDrag = kAirDrag, .angularDrag = kAirDrag}};
}

/// A ball resting on the ramp, `along` metres from its top end.
void addBallOnRamp(World& world, const Ramp& ramp, Real along, Material material) {
  Real x = ramp.left + along;
  // Centre one radius from the slope along its normal, plus a hair of gap.
  Real y = ramp.surfaceAt(x) + kBallRadius / std::cos(ramp.slopeAngle()) + Real(0.01);
  world.createCircle(Vec2(x, y), kBallRadius, ballOptions(material));
}

void addBallOnSurface(World& world, Real x, Real surface, Real radius) {
  world.createCircle(Vec2(x, surface + radius), radius, ballOptions(Material::Solid));
}

constexpr Real kShelfTop = Real(5.5);
constexpr Real kShelfThickness = Real(0.5);

void addShelf(World& world) {
  addStaticBox(world, Vec2(kBorder, kShelfTop - kShelfThickness),
               Vec2(kSceneSize.x() - kBorder, kShelfTop));
}

PresetInfo sandbox(World& world) {
  addBoundary(world);
  return {0, "Sandbox", {"Draw polygons (P) and circles (O); X shows the controls."}, {}, true, {}};
}

PresetInfo rampPreset(World& world) {
  addBoundary(world);
  Ramp ramp{kFloor, 2, 9};
  addRamp(world, ramp);
  addBallOnRamp(world, ramp, Real(0.9), Material::Solid);
  return {1,
          "Ramp",
          {"A ball rolls down the ramp under gravity and along the floor.",
           "It stops well short of the right wall: rolling resistance at the contact",
           "and air drag take its kinetic energy."},
          {},
          false, {}};
}

PresetInfo valleyPreset(World& world) {
  addBoundary(world);
  const Real height = 5;
  const Real right = kSceneSize.x() - kBorder;
  std::array<Vec2, 3> left = {Vec2(kBorder, kFloor), Vec2(Real(11.5), kFloor),
                              Vec2(kBorder, kFloor + height)};
  std::array<Vec2, 3> rightSide = {Vec2(Real(13.5), kFloor), Vec2(right, kFloor),
                                   Vec2(right, kFloor + height)};
  world.createPolygon(left, {.properties = {.isStatic = true}});
  world.createPolygon(rightSide, {.properties = {.isStatic = true}});
  addBallOnRamp(world, Ramp{kFloor, height, Real(11.5) - kBorder}, Real(1.0), Material::Solid);
  return {2,
          "Valley",
          {"The ball gains speed rolling down the first side but loses energy to",
           "rolling resistance and drag, so it cannot climb as high on the other side.",
           "It rolls back, oscillates with shrinking amplitude and rests in the middle."},
          {},
          false, {}};
}

PresetInfo polygonTutorial(World& world) {
  addBoundary(world);
  const Real r = Real(0.3125);
  return {3,
          "Polygon tutorial",
          {"Press P to start polygon mode.",
           "Click to place a point (a red cursor means the point would make the",
           "polygon non-convex). Press P again to create it (3 or more points).",
           "Try it now with the three markers."},
          {{Vec2(Real(12.5), Real(9.375)), r},
           {Vec2(Real(15.625), Real(10.9375)), r},
           {Vec2(Real(18.75), Real(9.375)), r}},
          true, {}};
}

PresetInfo circleTutorial(World& world) {
  addBoundary(world);
  const Vec2 centre(Real(12.5), Real(9.375));
  return {4,
          "Circle tutorial",
          {"Press O to start circle mode.",
           "Press and drag: the press sets the centre, the drag the radius.",
           "Press O again to create the circle. Try it with the two markers."},
          {{centre, Real(0.3125)}, {centre, Real(1.25)}},
          true, {}};
}

PresetInfo collisionPreset(World& world) {
  addBoundary(world);
  Ramp ramp{kFloor, 2, 9};
  addRamp(world, ramp);
  addBallOnRamp(world, ramp, Real(0.9), Material::Solid);
  addBallOnSurface(world, 15, kFloor, kBallRadius);
  return {5,
          "Collision",
          {"The ball gathers speed down the ramp and hits an equal ball at rest.",
           "The first slows down and the second moves off: momentum is conserved,",
           "and the restitution of the material decides how much energy is kept."},
          {},
          false, {}};
}

/// Two levels, each a ramp with a ball and a target ball at the same place.
void addTwoLevels(World& world, Real upperRampHeight, Real upperTargetRadius,
                  Real lowerTargetRadius, Material upperBall) {
  addBoundary(world);
  addShelf(world);
  Ramp lower{kFloor, Real(1.5), 6};
  Ramp upper{kShelfTop, upperRampHeight, 6};
  addRamp(world, lower);
  addRamp(world, upper);
  addBallOnRamp(world, lower, Real(0.9), Material::Solid);
  addBallOnRamp(world, upper, Real(0.9), upperBall);
  if (lowerTargetRadius > 0) addBallOnSurface(world, 13, kFloor, lowerTargetRadius);
  if (upperTargetRadius > 0) addBallOnSurface(world, 13, kShelfTop, upperTargetRadius);
}

PresetInfo massPreset(World& world) {
  addTwoLevels(world, Real(1.5), kBallRadius, 2 * kBallRadius, Material::Solid);
  return {6,
          "Mass",
          {"Equal balls roll down equal ramps and hit targets at the same distance.",
           "The lower target has twice the radius, so four times the mass:",
           "the same impulse gives it less speed and it ends nearer its start."},
          {},
          false, {}};
}

PresetInfo speedPreset(World& world) {
  addTwoLevels(world, Real(3.5), kBallRadius, kBallRadius, Material::Solid);
  return {7,
          "Speed",
          {"The upper ramp is steeper, so its ball arrives faster.",
           "A faster ball exerts a greater impulse on an equal target,",
           "which then travels further."},
          {},
          false, {}};
}

PresetInfo weightlessCrowd(World& world) {
  addBoundary(world);
  addCeiling(world);
  // A loose grid of small weightless balls; drag lets the crowd settle.
  const Real radius = Real(0.5);
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 5; ++column) {
      Vec2 centre(Real(6 + 3 * column + (row % 2)), Real(2 + 1.6 * row));
      world.createCircle(centre, radius,
                         {.properties = {.ignoreGravity = true, .linearDrag = Real(0.5), .angularDrag = Real(0.5)}});
    }
  }
  world.createCircle(Vec2(Real(11.5), Real(14.5)), Real(3.125), ballOptions(Material::Solid));
  return {8,
          "Weightless crowd",
          {"Twenty balls ignore gravity; one large ball falls into them.",
           "Many simultaneous collisions: everything settles and nothing",
           "leaves the box."},
          {},
          false, {}};
}

PresetInfo frictionPreset(World& world, Material selected) {
  addTwoLevels(world, Real(1.5), 0, 0, selected);
  return {9,
          "Friction",
          {"Two balls roll down identical ramps: the lower one SOLID, the upper one",
           "of the material selected now (keypad 1-5 or F5-F9, then reload).",
           "Friction and rolling resistance decide how far each rolls."},
          {},
          false, {}};
}

PresetInfo restitutionPreset(World& world) {
  addBoundary(world);
  constexpr std::array<Material, 5> order = {Material::Solid, Material::Ice, Material::Metal,
                                             Material::Wood, Material::Rubber};
  for (std::size_t i = 0; i < order.size(); ++i) {
    Vec2 centre(Real(2.5) + 5 * static_cast<Real>(i), Real(7.8125));
    world.createCircle(centre, kBallRadius, {.material = order[i]});
  }
  return {10,
          "Restitution",
          {"Five balls, one per material, dropped from the same height.",
           "Each bounces back by its restitution: RUBBER highest, METAL lowest."},
          {},
          false, {}};
}


// ------------------------------------------------------- presets with joints

/// Period of the spring preset's oscillation, s.
constexpr Real kSpringPeriod = 2;

/// A rigid distance joint (rod) between the anchors, or a spring; body A
/// must be a body (B may be the world, a null id).
JointId join(World& world, BodyId a, BodyId b, Vec2 anchorA, Vec2 anchorB,
             JointSettings settings = DistanceJointSettings{}) {
  return world.createJoint({a, b, anchorA, anchorB, false, settings}).id;
}

PresetInfo springPreset(World& world) {
  addBoundary(world);
  const Vec2 hook(Real(12.5), 16);
  addStaticBox(world, hook - Vec2(1, 0), hook + Vec2(1, Real(0.5)));
  // k from the ball's own mass, so the period is exactly kSpringPeriod.
  const BodyId ball = world.createCircle(Vec2(12.5f, 9), Real(0.5), {}).id;
  const Real mass = world.bodyDescription(ball)->mass.mass;
  const Real omega = 2 * std::numbers::pi_v<Real> / kSpringPeriod;
  // Rest length 5; equilibrium m*g/k lower; the ball starts 1 m below that.
  const Real restLength = 5;
  const Real k = mass * omega * omega;
  join(world, ball, BodyId{}, Vec2(12.5f, 9), hook, DistanceJointSettings{restLength, k, 0});
  return {11,
          "Spring",
          {"A ball on an undamped spring: simple harmonic motion.",
           "Its period is 2*pi*sqrt(m/k) = 2 s whatever the amplitude, and gravity",
           "only moves the middle of the swing down by m*g/k."},
          {},
          false, {}};
}

/// One ball of the cradle or the pendulum hanging by a rod from `pivot`.
BodyId addHungBall(World& world, Vec2 pivot, Vec2 at, Real radius, Material material) {
  const BodyId ball = world.createCircle(at, radius, {.material = material}).id;
  join(world, ball, BodyId{}, at, pivot);
  return ball;
}

PresetInfo pendulumPreset(World& world) {
  addBoundary(world);
  // A pendulum of 4 m released 10 degrees out: period about 2*pi*sqrt(L/g).
  const Vec2 pivot(5, 16);
  const Real length = 4;
  const Real released = 10 * std::numbers::pi_v<Real> / 180;
  addHungBall(world, pivot, pivot + length * Vec2(std::sin(released), -std::cos(released)),
              Real(0.4), Material::Solid);
  // Newton's cradle: five RUBBER balls in a row; the first pulled out 60 degrees.
  constexpr int kBalls = 5;
  constexpr Real kRadius = Real(0.5);
  // A small gap: the collisions pass along the row one pair at a time
  // instead of being solved as one block that swings together.
  constexpr Real kCradleGap = Real(0.05);
  for (int i = 0; i < kBalls; ++i) {
    const Vec2 top(13 + (2 * kRadius + kCradleGap) * Real(i), 16);
    const Real swing = i == 0 ? -std::numbers::pi_v<Real> / 3 : 0;
    addHungBall(world, top, top + length * Vec2(std::sin(swing), -std::cos(swing)), kRadius,
                Material::Rubber);
  }
  return {12,
          "Pendulum and Newton's cradle",
          {"Left: a 4 m pendulum swinging 10 degrees: period 2*pi*sqrt(L/g) = 4.01 s.",
           "Right: Newton's cradle. The first ball strikes the row and its momentum",
           "passes through the three at rest to the last, which swings out."},
          {},
          false, {}};
}

/// A plank of `length` from `from` at `angle`, 0.2 m thick below the line.
BodyId addPlank(World& world, Vec2 from, Real length, Real angle) {
  const Vec2 along = length * Vec2(std::cos(angle), std::sin(angle));
  const Vec2 down = Real(0.2) * rightPerp(along) / length;
  std::array<Vec2, 4> corners = {from + down, from + along + down, from + along, from};
  return world.createPolygon(corners, {.material = Material::Wood}).id;
}

PresetInfo chainBridgePreset(World& world) {
  addBoundary(world);
  // Fourteen 1 m planks between posts 12 m apart: slack, so the chain sags
  // into its curve instead of hanging taut. Built as a V, it settles.
  constexpr int kPlanks = 14;
  constexpr Real kPlank = 1;
  const Real left = Real(6.5);
  const Real span = 12;
  const Real height = 8;
  // The pins hang in the air 0.4 m off the posts' tops, so no plank rests
  // on a post: the pins alone hold the bridge.
  const Real clearance = Real(0.4);
  addStaticBox(world, Vec2(left - clearance - 1, kFloor), Vec2(left - clearance, height));
  addStaticBox(world, Vec2(left + span + clearance, kFloor),
               Vec2(left + span + clearance + 1, height));
  const Real slope = std::acos(span / 2 / (kPlanks / 2 * kPlank));
  // The pins are exact (the joint tree pass), so without friction the chain
  // would swing on for minutes: each pin brakes with up to 100 N*m (a motor
  // held at speed 0), a seventh of the turn a 140 kg plank's weight gives it.
  const RevoluteJointSettings pin{.enableMotor = true, .motorSpeed = 0, .maxMotorTorque = 100};
  Vec2 joint(left, height);
  BodyId previous;  // the world, for the first pin
  for (int i = 0; i < kPlanks; ++i) {
    const Real angle = i < kPlanks / 2 ? -slope : slope;
    const BodyId plank = addPlank(world, joint, kPlank, angle);
    world.createJoint({plank, previous, joint, joint, false, pin});
    joint += kPlank * Vec2(std::cos(angle), std::sin(angle));
    previous = plank;
  }
  world.createJoint({previous, BodyId{}, joint, joint, false, pin});
  // Two balls dropped onto it.
  world.createCircle(Vec2(10, 9), Real(0.4), {.material = Material::Metal});
  world.createCircle(Vec2(15, 9), Real(0.6), {.material = Material::Rubber});
  return {13,
          "Chain bridge",
          {"Fourteen wooden planks pinned end to end between posts 12 m apart sag",
           "into a chain curve. The posts carry the whole weight: the vertical forces",
           "of the two end pins add up to the weight of the planks and the balls."},
          {},
          false, {}};
}

/// Uneven ground: bumps of alternating heights on the floor.
void addBumps(World& world) {
  for (int i = 0; i < 5; ++i) {
    const Real x = 10 + Real(2.5) * Real(i);
    const Real h = i % 2 == 0 ? Real(0.25) : Real(0.4);
    std::array<Vec2, 3> bump = {Vec2(x, kFloor), Vec2(x + 2, kFloor), Vec2(x + 1, kFloor + h)};
    world.createPolygon(bump, {.properties = {.isStatic = true}});
  }
}

/// Motor speed of the car's wheels, rad/s (negative: clockwise, driving right).
constexpr Real kCarWheelSpeed = -6;
constexpr Real kCarWheelRadius = Real(0.5);

}  // namespace

BodyId addCar(World& world, Real left, Real ground) {
  const Real axle = ground + kCarWheelRadius;
  const Real chassisBottom = axle + Real(0.3);
  std::array<Vec2, 4> body = {Vec2(left, chassisBottom), Vec2(left + 3, chassisBottom),
                              Vec2(left + 3, chassisBottom + Real(0.5)), Vec2(left, chassisBottom + Real(0.5))};
  const BodyId chassis = world.createPolygon(body, {.material = Material::Wood}).id;
  // Springs and motors from the masses: each axle carries half the chassis
  // on a 1.5 Hz suspension damped at 0.7 of critical; the motors could
  // climb a slope of 0.6.
  const Real share = world.bodyDescription(chassis)->mass.mass / 2;
  const Real omega = 2 * std::numbers::pi_v<Real> * Real(1.5);
  WheelJointSettings axleSettings{Vec2(0, 1), share * omega * omega,
                                  2 * Real(0.7) * share * omega, true, kCarWheelSpeed, 0};
  for (const Real x : {left + Real(0.5), left + Real(2.5)}) {
    const Vec2 centre(x, axle);
    const BodyId wheel =
        world.createCircle(centre, kCarWheelRadius, {.material = Material::Rubber}).id;
    const Real carried = share + world.bodyDescription(wheel)->mass.mass;
    axleSettings.maxMotorTorque = Real(0.6) * carried * Real(9.81) * kCarWheelRadius;
    world.createJoint({chassis, wheel, centre, centre, false, axleSettings});
  }
  return chassis;
}

namespace {

PresetInfo carPreset(World& world) {
  addBoundary(world);
  addBumps(world);
  addCar(world, 2, kFloor);
  return {14,
          "Car",
          {"A car with two motorised wheels on sprung axles drives over bumps.",
           "The motors hold the wheels at 6 rad/s; rolling without slipping the car",
           "moves at wheel speed times radius, 3 m/s, and the springs soak up the bumps."},
          {},
          false, {}};
}

// ------------------------------------------------------------ field scenes

PresetInfo orbitsPreset(World& world) {
  world.setGravity(Vec2::Zero());
  const Vec2 centre = kSceneSize / 2;
  const BodyId sun = world.createCircle(centre, kSunRadius, {.material = Material::Metal, .properties = {.isStatic = true}}).id;
  // A static body pulls with its area times density.
  const Real sunMass = world.bodyDescription(sun)->mass.area * materialProperties(Material::Metal).density;
  world.addField(makeGravitation({kOrbitConstant}).field);
  // Light planets (their pulls on each other are a few parts in ten
  // thousand of the sun's) on circular orbits, v = sqrt(G M / r), each a
  // quarter turn on.
  for (int k = 0; k < 3; ++k) {
    const Real radius = kPlanetOrbits[k];
    const Real speed = std::sqrt(Real(kOrbitConstant) * sunMass / radius);
    const Real angle = Real(k) * std::numbers::pi_v<Real> / 2;
    const Vec2 out(std::cos(angle), std::sin(angle));
    world.createCircle(centre + radius * out, kPlanetRadius,
                       {.material = Material::Ice, .linearVelocity = speed * Vec2(-out.y(), out.x())});
  }
  return {15,
          "Orbits",
          {"Newton's gravitation, no weight: three light planets circle a static sun.",
           "Kepler: T = 2*pi*sqrt(r^3 / (G M)), so radii 3, 5 and 7.5 m give periods",
           "of 8 s, 17.2 s and 31.7 s. The step is symplectic: the orbits do not spiral."},
          {},
          false, {}};
}

PresetInfo floatingPreset(World& world) {
  addBoundary(world);
  const Real left = kBorder, right = kSceneSize.x() - kBorder;
  const std::array<Vec2, 4> pool = {Vec2(left, kFloor), Vec2(right, kFloor), Vec2(right, kWaterLevel),
                                    Vec2(left, kWaterLevel)};
  world.addField(makeFluidRegion({.polygon = {pool.begin(), pool.end()}, .density = kWaterDensity,
                                  .linearDrag = 5, .angularDrag = 5})
                     .field);
  // Dropped from above the surface; each floats as deep as its density says.
  const Material materials[] = {Material::Ice, Material::Rubber, Material::Solid, Material::Wood, Material::Metal};
  for (int k = 0; k < 5; ++k) {
    const Vec2 at(Real(2.5 + 3.5 * k), kWaterLevel + 2);
    const std::array<Vec2, 4> box = {at + Vec2(-0.6f, -0.6f), at + Vec2(0.6f, -0.6f), at + Vec2(0.6f, 0.6f),
                                     at + Vec2(-0.6f, 0.6f)};
    world.createPolygon(box, {.material = materials[k]});
  }
  // A plank dropped tilted by 0.3 rad.
  BodyDef plank = makeBodyDef(Shape::makePolygon(makeBox(Real(1.8), Real(0.3))), Vec2(21, 13),
                              {.material = Material::Wood});
  plank.angle = Real(0.3);
  world.createBody(plank);
  return {16,
          "Floating",
          {"A pool of water (1000 kg/m^2): boxes sink until they displace their own mass.",
           "ICE floats 10 % under, RUBBER 20 %, SOLID 50 %, WOOD 70 %; METAL (2000)",
           "sinks. The plank lands tilted and rights itself: its metacentre is high."},
          {},
          false, {}};
}

PresetInfo fansPreset(World& world) {
  addBoundary(world);
  addCeiling(world);
  for (Real x : kFanPositions) {
    world.addField(makeFan({.position = Vec2(x, kFloor), .direction = Vec2(0, 1), .speed = kFanSpeed,
                            .range = kFanRange, .spread = kFanSpread})
                       .field);
  }
  // Light ICE balls dropped into each cone, fanned out in angle so that few
  // start in another's shadow, and a row on the floor between the fans.
  for (Real x : kFanPositions) {
    for (int k = 0; k < 8; ++k) {
      const Real angle = Real(-0.28 + 0.08 * k), height = Real(2 + 0.8 * k);
      world.createCircle(Vec2(x + height * std::tan(angle), kFloor + height), kLightBallRadius,
                         {.material = Material::Ice});
    }
  }
  for (int k = 0; k < 5; ++k) {
    world.createCircle(Vec2(Real(11.3 + 0.6 * k), kFloor + kLightBallRadius), kLightBallRadius,
                       {.material = Material::Ice});
  }
  return {17,
          "Fans",
          {"Two fans on the floor blow upward, the air slowing to nothing at 14 m",
           "and towards each cone's edge, drawing a ball on its flank back inwards.",
           "Light ICE balls hover where the drag 1/2 rho w u^2 equals their weight;",
           "balls behind others are in their shadow and drop. Outside the cones: no air."},
          {},
          false, {}};
}

}  // namespace

AABB presetLanding(const AABB& roomBounds) {
  if (roomBounds.contains(kPresetScene)) return kPresetScene;
  const Vec2 shift = (roomBounds.lower + roomBounds.upper) / 2 - (kPresetScene.lower + kPresetScene.upper) / 2;
  return {kPresetScene.lower + shift, kPresetScene.upper + shift};
}

std::optional<PresetInfo> loadPreset(World& world, int id, Material selected) {
  if (id < 0 || id >= kPresetCount) return std::nullopt;
  world.clear();
  world.setGravity(kDefaultGravity);
  switch (id) {
    case 0: return sandbox(world);
    case 1: return rampPreset(world);
    case 2: return valleyPreset(world);
    case 3: return polygonTutorial(world);
    case 4: return circleTutorial(world);
    case 5: return collisionPreset(world);
    case 6: return massPreset(world);
    case 7: return speedPreset(world);
    case 8: return weightlessCrowd(world);
    case 9: return frictionPreset(world, selected);
    case 10: return restitutionPreset(world);
    case 11: return springPreset(world);
    case 12: return pendulumPreset(world);
    case 13: return chainBridgePreset(world);
    case 14: return carPreset(world);
    case 15: return orbitsPreset(world);
    case 16: return floatingPreset(world);
    case 17: return fansPreset(world);
    case 18: return terrainCarPreset(world);
    case 19: return elevatorPreset(world);
    case 20: return tumblerPreset(world);
    default: return ragdollStairsPreset(world);
  }
}

}  // namespace impulse
