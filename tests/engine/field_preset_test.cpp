// The field presets (15-17) do what their explanation says: planets keep
// Kepler's period, boxes float as deep as their density, fans hold light
// balls in the air and nothing outside a cone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "impulse/scenes/field_scenes.h"
#include "impulse/scenes/presets.h"
#include "impulse/submerged.h"
#include "world_test_support.h"

namespace impulse::test {
namespace {

std::vector<BodyId> dynamicBodies(const World& world) {
  std::vector<BodyId> ids;
  for (BodyId id : world.bodyIds()) {
    if (!world.bodyDescription(id)->isStatic) ids.push_back(id);
  }
  return ids;
}

TEST(Preset15Orbits, EachPlanetKeepsItsRadiusAndKeplersPeriod) {
  World world;
  ASSERT_TRUE(loadPreset(world, 15).has_value());
  EXPECT_EQ(world.fieldCount(), 1);
  const Vec2 centre = kSceneSize / 2;
  const double sunMass = kPi * kSunRadius * kSunRadius * materialProperties(Material::Metal).density;
  const std::vector<BodyId> planets = dynamicBodies(world);
  ASSERT_EQ(planets.size(), 3u);
  // The outer planet's period is about 16 s: two of its orbits.
  std::vector<double> lowest(3, 1e9), highest(3, 0), turned(3, 0), previousAngle(3, 0);
  for (int k = 0; k < 3; ++k) {
    const Vec2 offset = stateOf(world, planets[k]).position - centre;
    previousAngle[k] = std::atan2(offset.y(), offset.x());
  }
  const double seconds = 32;
  for (int step = 0; step < stepsFor(seconds); ++step) {
    world.step(kDt);
    for (int k = 0; k < 3; ++k) {
      const Vec2 offset = stateOf(world, planets[k]).position - centre;
      lowest[k] = std::min<double>(lowest[k], offset.norm());
      highest[k] = std::max<double>(highest[k], offset.norm());
      const double angle = std::atan2(offset.y(), offset.x());
      turned[k] += std::remainder(angle - previousAngle[k], 2 * kPi);
      previousAngle[k] = angle;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const double r = kPlanetOrbits[k];
    const double kepler = 2 * kPi * std::sqrt(r * r * r / (kOrbitConstant * sunMass));
    const double measured = seconds * 2 * kPi / turned[k];
    std::printf("planet at %.1f m: radius %.4f..%.4f, period %.4f s (Kepler %.4f)\n", r, lowest[k], highest[k],
                measured, kepler);
    // The planets pull on each other too (0.05 % of the sun's mass each).
    EXPECT_NEAR(lowest[k], r, 0.02 * r);
    EXPECT_NEAR(highest[k], r, 0.02 * r);
    EXPECT_NEAR(measured, kepler, 0.02 * kepler);
  }
}

TEST(Preset16Floating, EachBoxFloatsAsDeepAsItsDensity_AndMetalSinks) {
  World world;
  ASSERT_TRUE(loadPreset(world, 16).has_value());
  simulate(world, 20);
  std::map<Material, double> submerged;
  for (BodyId id : dynamicBodies(world)) {
    const BodyDescription description = *world.bodyDescription(id);
    if (description.material == Material::Wood && description.mass.area > 1.8) continue;  // the plank
    const BodyState state = stateOf(world, id);
    Transform at;
    at.p = state.position;
    at.q = Rot::fromAngle(state.angle);
    const std::vector<Vec2> pool = {Vec2(0, 0), Vec2(25, 0), Vec2(25, kWaterLevel), Vec2(0, kWaterLevel)};
    submerged[description.material] = submergedPart(description.shape, at, pool).area / description.mass.area;
  }
  for (Material material : {Material::Ice, Material::Rubber, Material::Solid, Material::Wood}) {
    const double expected = materialProperties(material).density / kWaterDensity;
    std::printf("%s box: %.4f submerged (%.2f)\n", materialProperties(material).name.data(), submerged[material],
                expected);
    // Sleep takes a box once it moves slower than 0.05 m/s: up to about
    // 0.05 / omega (1-3 cm) off its rest depth.
    EXPECT_NEAR(submerged[material], expected, 0.03) << materialProperties(material).name;
  }
  EXPECT_NEAR(submerged[Material::Metal], 1.0, 1e-6) << "METAL sinks";
}

TEST(Preset16Floating, ThePlankRightsItselfFlat) {
  World world;
  ASSERT_TRUE(loadPreset(world, 16).has_value());
  simulate(world, 20);
  for (BodyId id : dynamicBodies(world)) {
    if (world.bodyDescription(id)->mass.area > 1.8) {
      EXPECT_NEAR(std::remainder(double(stateOf(world, id).angle), kPi), 0, 0.02);
    }
  }
}

TEST(Preset17Fans, LightBallsRideTheAir_NoHigherThanTheRange) {
  World world;
  ASSERT_TRUE(loadPreset(world, 17).has_value());
  EXPECT_EQ(world.fieldCount(), 2);
  // How many balls ride the air at one instant is chaotic (balls knock each
  // other out of the cones and fall back in: 0 to 7 of 21 between 5 and
  // 16 s), so the count is averaged over ten seconds, sampled twice a second.
  // The average also depends on the order contacts are solved in at 4
  // sub-steps (over 12 slightly perturbed starts: 4.3 with the contact order
  // before issue 10's slot bits, 3.1 after; 3.8 with either at 8 sub-steps).
  constexpr int kSamples = 20;
  double aloftSum = 0;
  double highest = 0;
  simulate(world, 2);
  for (int sample = 0; sample < kSamples; ++sample) {
    simulate(world, 0.5);
    for (BodyId id : dynamicBodies(world)) {
      const Vec2 p = stateOf(world, id).position;
      if (p.y() < 2) continue;
      ++aloftSum;
      highest = std::max<double>(highest, p.y());
    }
  }
  const double meanAloft = aloftSum / kSamples;
  // A single ball hovers where 1/2 rho Cd (2r) u^2 = m g, u = S (1 - h / R).
  const double mass = kPi * kLightBallRadius * kLightBallRadius * materialProperties(Material::Ice).density;
  const double hoverSpeed = std::sqrt(mass * kG / (0.5 * 1.2 * 2 * kLightBallRadius));
  const double hover = kFanRange * (1 - hoverSpeed / kFanSpeed);
  std::printf("fans: %.2f balls aloft on average, highest %.2f m (one ball alone hovers %.2f m above a fan)\n",
              meanAloft, highest, hover);
  EXPECT_GE(meanAloft, 2);
  EXPECT_LT(highest, 0.78 + kFanRange) << "no air beyond the range";
}

}  // namespace
}  // namespace impulse::test
