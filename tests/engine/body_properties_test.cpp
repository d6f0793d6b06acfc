// Per-body properties given through BodyOptions (docs/protocol.md "Per-body
// properties"): density, friction, restitution, damping and gravity scale,
// checked against closed forms and reported back by bodyDescription.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

CreateResult addBall(World& world, const BodyOptions& options, Vec2 centre = Vec2(0, 10)) {
  return world.createCircle(centre, Real(0.5), options);
}

BodyId mustAddBall(World& world, const BodyOptions& options, Vec2 centre = Vec2(0, 10)) {
  CreateResult result = addBall(world, options, centre);
  EXPECT_TRUE(result.ok()) << result.error;
  return result.id;
}

TEST(BodyProperties, DampingDecaysVelocityAsExpOfMinusCT) {
  // dv/dt = -c v  =>  v(t) = v0 exp(-c t); the engine's factor is exact per
  // sub-step, so only float round-off (1e-4 relative) remains.
  World world;
  const Real c = Real(1.5);
  const Real cAngular = Real(0.4);
  BodyId id = mustAddBall(world, {.properties = {.ignoreGravity = true, .linearDrag = c, .angularDrag = cAngular},
                                  .linearVelocity = Vec2(3, -2),
                                  .angularVelocity = 5});
  const double t = 2;
  simulate(world, t);
  BodyState s = stateOf(world, id);
  const double decay = std::exp(-c * t);
  EXPECT_NEAR(s.linearVelocity.x(), 3 * decay, 1e-4 * 3);
  EXPECT_NEAR(s.linearVelocity.y(), -2 * decay, 1e-4 * 2);
  EXPECT_NEAR(s.angularVelocity, 5 * std::exp(-cAngular * t), 1e-4 * 5);
}

// Drop of a body released at rest after `seconds` with the given options.
double dropAfter(const BodyOptions& options, double seconds) {
  World world;
  BodyId id = mustAddBall(world, options);
  simulate(world, seconds);
  return 10 - double(stateOf(world, id).position.y());
}

TEST(BodyProperties, GravityScaleZeroFloats_TwoFallsTwiceAsFast) {
  const double t = 1;
  EXPECT_EQ(dropAfter({.properties = {.gravityScale = 0}}, t), 0) << "no force at all: not a millimetre";
  const double normal = dropAfter({}, t);
  const double doubled = dropAfter({.properties = {.gravityScale = 2}}, t);
  // Free fall s = g' t^2 / 2 with g' = 2 g. The solver's sub-steps (n = 240
  // in 1 s) integrate semi-implicitly: s_n = g' h^2 n (n + 1) / 2, above
  // the closed form by a factor 1 + 1/n (0.42%).
  const int n = stepsFor(t) * WorldSettings{}.subSteps;
  const double closedForm = 0.5 * 2 * kG * t * t;
  EXPECT_NEAR(doubled, closedForm * (1 + 1.0 / n), 1e-4 * closedForm);
  // Twice the unscaled drop, up to float round-off on positions near 10 m.
  EXPECT_NEAR(doubled / normal, 2, 1e-4);
}

TEST(BodyProperties, NegativeGravityScaleRises) {
  EXPECT_NEAR(dropAfter({.properties = {.gravityScale = Real(-0.5)}}, 1), -0.5 * dropAfter({}, 1), 1e-4);
}

TEST(BodyProperties, DensityChangesMassExactly) {
  World world;
  const Real density = 1234;
  BodyId ball = mustAddBall(world, {.materialOverride = {.density = density}});
  const BodyDescription d = *world.bodyDescription(ball);
  const double area = kPi * 0.25;
  EXPECT_NEAR(d.mass.mass, density * area, 1e-6 * density * area);
  EXPECT_NEAR(d.mass.inertia, 0.5 * density * area * 0.25, 1e-6 * density * area);
  EXPECT_EQ(d.density, density);
}

TEST(BodyProperties, DescriptionReportsTheValuesInForce) {
  World world;
  BodyId given = mustAddBall(
      world, {.material = Material::Wood,
              .properties = {.linearDrag = Real(0.25), .angularDrag = Real(0.75), .gravityScale = Real(0.5)},
              .materialOverride = {.restitution = Real(0.9),
                                   .staticFriction = Real(0.1),
                                   .dynamicFriction = Real(0.1)}});
  const BodyDescription d = *world.bodyDescription(given);
  EXPECT_EQ(d.restitution, Real(0.9));
  EXPECT_EQ(d.staticFriction, Real(0.1));
  EXPECT_EQ(d.dynamicFriction, Real(0.1));
  EXPECT_EQ(d.properties.linearDrag, Real(0.25));
  EXPECT_EQ(d.properties.angularDrag, Real(0.75));
  EXPECT_EQ(d.properties.gravityScale, Real(0.5));
  EXPECT_EQ(d.density, materialProperties(Material::Wood).density) << "unset: the material's";

  BodyId plain = mustAddBall(world, {.material = Material::Glass}, Vec2(3, 10));
  const BodyDescription p = *world.bodyDescription(plain);
  const MaterialProperties& glass = materialProperties(Material::Glass);
  EXPECT_EQ(p.density, glass.density);
  EXPECT_EQ(p.restitution, glass.restitution);
  EXPECT_EQ(p.staticFriction, glass.staticFriction);
  EXPECT_EQ(p.properties.gravityScale, 1);
}

TEST(BodyProperties, FrictionGivenSlidesLikeCoulomb) {
  // A box launched at v0 on a floor of friction 0 slows at mu g with mu the
  // mean of its 0.6 and the floor's: it stops after v0^2 / (2 mu g).
  World world;
  CreateResult floor = world.createPolygon(
      std::array{Vec2(-30, -1), Vec2(30, -1), Vec2(30, 0), Vec2(-30, 0)},
      {.properties = {.isStatic = true}, .materialOverride = {.staticFriction = 0, .dynamicFriction = 0}});
  ASSERT_TRUE(floor.ok()) << floor.error;
  const Real mu = Real(0.6);
  CreateResult box = world.createPolygon(
      std::array{Vec2(-0.5, 0), Vec2(0.5, 0), Vec2(0.5, 1), Vec2(-0.5, 1)},
      {.linearVelocity = Vec2(5, 0),
       .materialOverride = {.staticFriction = mu, .dynamicFriction = mu}});
  ASSERT_TRUE(box.ok()) << box.error;
  simulate(world, 3);
  const double mixed = 0.5 * mu;
  const double expected = 25 / (2 * mixed * kG);
  // Within 3 %: the first contact step and the stop are resolved to a tick.
  EXPECT_NEAR(stateOf(world, box.id).position.x(), expected, 0.03 * expected);
}

TEST(BodyProperties, OutOfRangeValuesAreRefusedNamingTheField) {
  World world;
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const struct {
    BodyOptions options;
    std::string mentions;
  } cases[] = {
      {{.properties = {.linearDrag = -1}}, "linear damping"},
      {{.properties = {.linearDrag = 2000}}, "linear damping"},
      {{.properties = {.angularDrag = nan}}, "non-finite"},
      {{.properties = {.angularDrag = -Real(0.5)}}, "angular damping"},
      {{.properties = {.gravityScale = 11}}, "gravity scale"},
      {{.properties = {.gravityScale = nan}}, "gravity scale"},
      {{.materialOverride = {.density = -3}}, "density"},
      {{.materialOverride = {.restitution = 2}}, "restitution"},
      {{.materialOverride = {.staticFriction = 11, .dynamicFriction = 11}}, "friction"},
  };
  for (const auto& c : cases) {
    CreateResult result = addBall(world, c.options);
    EXPECT_FALSE(result.ok());
    EXPECT_NE(result.error.find(c.mentions), std::string::npos) << result.error;
  }
  EXPECT_EQ(world.bodyCount(), 0) << "a refused body changes nothing";
}

TEST(BodyProperties, SaveAndLoadCarryThePropertiesWhole) {
  // Every property away from its default: the loaded body reports the same
  // struct, so no property can be left out of a save.
  World world;
  const BodyProperties given{.isKinematic = true,
                             .ignoreGravity = true,
                             .linearDrag = Real(0.25),
                             .angularDrag = Real(0.75),
                             .gravityScale = Real(-2.5)};
  const BodyId id = mustAddBall(world, {.properties = given});
  World loaded;
  const InputResult imported = loaded.importState(world.exportState());
  ASSERT_TRUE(imported.ok()) << imported.error;
  EXPECT_TRUE(loaded.bodyDescription(id)->properties == given);
  EXPECT_TRUE(world.bodyDescription(id)->properties == given);
}

TEST(BodyProperties, SceneOutsideTheCreationRangesIsRefusedNamingTheField) {
  // A scene comes from anyone: it is held to the ranges createBody holds
  // bodies to, by the same check, and a refusal changes nothing.
  World world;
  const BodyId id = mustAddBall(world, {});
  WorldState state = world.exportState();
  state.bodies[std::size_t(id.slot())].properties.linearDrag = 2 * kMaxDrag;
  World loaded;
  const InputResult refused = loaded.importState(state);
  EXPECT_FALSE(refused.ok());
  EXPECT_NE(refused.error.find("linear damping 2000 must be in [0, 1000]"), std::string::npos) << refused.error;
  EXPECT_EQ(loaded.bodyCount(), 0);
}

TEST(BodyProperties, NewMaterialsMassesFollowTheirDensities) {
  // Equal balls: masses in the ratio of the table's densities, FOAM < ICE
  // < ... < STONE < GLASS.
  World world;
  double previous = 0;
  Real x = 0;
  for (Material material : {Material::Foam, Material::Ice, Material::Stone, Material::Glass}) {
    SCOPED_TRACE(materialProperties(material).name);
    x += 2;
    const double mass =
        world.bodyDescription(mustAddBall(world, {.material = material}, Vec2(x, 10)))->mass.mass;
    EXPECT_NEAR(mass, materialProperties(material).density * kPi * 0.25, 1e-6 * mass);
    EXPECT_GT(mass, previous);
    previous = mass;
  }
}

}  // namespace
}  // namespace impulse
