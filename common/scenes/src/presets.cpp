// The scenes of SPEC.md. Layout follows the seed's 800x600 px canvas at
// 32 px/m: a floor and two walls whose visible parts are 25 px (0.78 m) thick,
// ramps as static triangles, balls of 20 px (0.625 m) radius.

#include <array>
#include <cmath>

#include "impulse/scenes/presets.h"

namespace impulse {

namespace {

constexpr Real kBorder = Real(0.78125);  // visible wall and floor thickness
constexpr Real kFloor = kBorder;         // top of the floor
constexpr Real kBallRadius = Real(0.625);
// The seed's balls roll to a stop on the floor; ours do it with real rolling
// resistance (in the material) plus this air drag, in 1/s.
constexpr Real kAirDrag = Real(0.25);

void addStaticBox(World& world, Vec2 lower, Vec2 upper) {
  std::array<Vec2, 4> corners = {lower, Vec2(upper.x(), lower.y()), upper, Vec2(lower.x(), upper.y())};
  world.createPolygon(corners, {.isStatic = true});
}

/// Floor and two side walls, centred on the canvas edges as in the seed.
void addBoundary(World& world) {
  const Vec2 size = kSceneSize;
  addStaticBox(world, Vec2(0, -kBorder), Vec2(size.x(), kBorder));
  addStaticBox(world, Vec2(-kBorder, 0), Vec2(kBorder, size.y()));
  addStaticBox(world, Vec2(size.x() - kBorder, 0), Vec2(size.x() + kBorder, size.y()));
}

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
  world.createPolygon(corners, {.isStatic = true});
}

BodyOptions ballOptions(Material material) {
  return {.material = material, .linearDrag = kAirDrag, .angularDrag = kAirDrag};
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
  return {0, "Sandbox", {"Draw polygons (P) and circles (O); X shows the controls."}, {}, true};
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
          false};
}

PresetInfo valleyPreset(World& world) {
  addBoundary(world);
  const Real height = 5;
  const Real right = kSceneSize.x() - kBorder;
  std::array<Vec2, 3> left = {Vec2(kBorder, kFloor), Vec2(Real(11.5), kFloor),
                              Vec2(kBorder, kFloor + height)};
  std::array<Vec2, 3> rightSide = {Vec2(Real(13.5), kFloor), Vec2(right, kFloor),
                                   Vec2(right, kFloor + height)};
  world.createPolygon(left, {.isStatic = true});
  world.createPolygon(rightSide, {.isStatic = true});
  addBallOnRamp(world, Ramp{kFloor, height, Real(11.5) - kBorder}, Real(1.0), Material::Solid);
  return {2,
          "Valley",
          {"The ball gains speed rolling down the first side but loses energy to",
           "rolling resistance and drag, so it cannot climb as high on the other side.",
           "It rolls back, oscillates with shrinking amplitude and rests in the middle."},
          {},
          false};
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
          true};
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
          true};
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
          false};
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
          false};
}

PresetInfo speedPreset(World& world) {
  addTwoLevels(world, Real(3.5), kBallRadius, kBallRadius, Material::Solid);
  return {7,
          "Speed",
          {"The upper ramp is steeper, so its ball arrives faster.",
           "A faster ball exerts a greater impulse on an equal target,",
           "which then travels further."},
          {},
          false};
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
                         {.ignoreGravity = true, .linearDrag = Real(0.5), .angularDrag = Real(0.5)});
    }
  }
  world.createCircle(Vec2(Real(11.5), Real(14.5)), Real(3.125), ballOptions(Material::Solid));
  return {8,
          "Weightless crowd",
          {"Twenty balls ignore gravity; one large ball falls into them.",
           "Many simultaneous collisions: everything settles and nothing",
           "leaves the box."},
          {},
          false};
}

PresetInfo frictionPreset(World& world, Material selected) {
  addTwoLevels(world, Real(1.5), 0, 0, selected);
  return {9,
          "Friction",
          {"Two balls roll down identical ramps: the lower one SOLID, the upper one",
           "of the material selected now (keypad 1-5 or F5-F9, then reload).",
           "Friction and rolling resistance decide how far each rolls."},
          {},
          false};
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
          false};
}

}  // namespace

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
    default: return restitutionPreset(world);
  }
}

}  // namespace impulse
