// Per-body coefficients that replace the material table's.

#include <gtest/gtest.h>

#include <cmath>

#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

BodyDef ballDef(Vec2 centre, const MaterialOverride& override) {
  BodyDef def;
  def.shape = Shape::makeCircle(Real(0.5));
  def.position = centre;
  def.materialOverride = override;
  return def;
}

TEST(MaterialOverride, DensityOverrideSetsMass) {
  World world;
  CreateResult ball = world.createBody(ballDef(Vec2(0, 5), {.density = 300}));
  ASSERT_TRUE(ball.ok()) << ball.error;
  // Relative 1e-5: mass = density x pi r^2 in float.
  const double expected = 300 * M_PI * 0.25;
  EXPECT_NEAR(world.bodyDescription(ball.id)->mass.mass, expected, 1e-5 * expected);
}

TEST(MaterialOverride, UnsetFieldsKeepTheMaterialsValues) {
  World world;
  BodyDef def = ballDef(Vec2(0, 5), {.staticFriction = Real(0.75)});
  def.material = Material::Rubber;
  BodyDescription d = *world.bodyDescription(world.createBody(def).id);
  EXPECT_FLOAT_EQ(d.staticFriction, 0.75f);
  EXPECT_FLOAT_EQ(d.dynamicFriction, materialProperties(Material::Rubber).dynamicFriction);
  EXPECT_FLOAT_EQ(d.restitution, materialProperties(Material::Rubber).restitution);
}

TEST(MaterialOverride, ZeroRestitutionOnBothBodiesGivesNoBounce) {
  World world;
  BodyDef floor;
  floor.shape = Shape::makePolygon(makeBox(10, 1));
  floor.position = Vec2(0, -1);
  floor.properties.isStatic = true;
  floor.materialOverride.restitution = 0;
  world.createBody(floor);
  BodyId ball = world.createBody(ballDef(Vec2(0, 3), {.restitution = 0})).id;
  double highestAfterImpact = 0;
  bool landed = false;
  simulateUntil(world, 2, [&] {
    BodyState s = stateOf(world, ball);
    landed = landed || s.position.y() < 0.52;  // touching, within 2 cm
    if (landed) highestAfterImpact = std::max(highestAfterImpact, double(s.position.y()));
    return false;
  });
  ASSERT_TRUE(landed);
  // 1 cm above resting height (0.5 m): a SOLID pair (e = 0.7) would rebound ~1.2 m.
  EXPECT_LT(highestAfterImpact, 0.51);
}

TEST(MaterialOverride, OutOfRangeCoefficientsAreRefusedWithAMessage) {
  World world;
  const MaterialOverride bad[] = {{.density = 0},
                                  {.density = std::nanf("")},
                                  {.restitution = Real(1.5)},
                                  {.staticFriction = -1},
                                  {.dynamicFriction = std::numeric_limits<Real>::infinity()},
                                  {.rollingResistance = -Real(0.1)}};
  for (const MaterialOverride& o : bad) {
    CreateResult result = world.createBody(ballDef(Vec2(0, 5), o));
    EXPECT_FALSE(result.ok());
    EXPECT_FALSE(result.error.empty());
  }
  EXPECT_EQ(world.bodyCount(), 0) << "a refused body changes nothing";
}

}  // namespace
}  // namespace impulse
