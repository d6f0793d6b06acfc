// The field presets (15-17) do what their explanation says: planets keep
// Kepler's period, boxes float as deep as their density, fans hold light
// balls in the air within their cones.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "impulse/fan.h"
#include "impulse/scenes/field_scenes.h"
#include "impulse/scenes/presets.h"
#include "impulse/submerged.h"
#include "world_test_support.h"

namespace impulse::test {
namespace {

std::vector<BodyId> dynamicBodies(const World& world) {
  std::vector<BodyId> ids;
  for (BodyId id : world.bodyIds()) {
    if (!world.bodyDescription(id)->properties.isStatic) ids.push_back(id);
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

std::vector<const Fan*> fansOf(const World& world) {
  std::vector<const Fan*> fans;
  for (FieldId id : world.fieldIds()) {
    if (const auto* fan = dynamic_cast<const Fan*>(world.field(id))) fans.push_back(fan);
  }
  return fans;
}

TEST(Preset17Fans, LightBallsHoverInTheCones_NoneIsBlownOut) {
  World world;
  ASSERT_TRUE(loadPreset(world, 17).has_value());
  const std::vector<const Fan*> fans = fansOf(world);
  ASSERT_EQ(fans.size(), 2u);
  const Real fanHeight = fans.front()->def().position.y();
  auto inAirflow = [&](const Vec2& p) {
    return std::ranges::any_of(fans, [&](const Fan* fan) { return fan->airVelocity(p) != Vec2::Zero(); });
  };
  // The first seconds are a scramble (balls knock each other about and
  // the shaded ones drop); after it the riders keep their place in the air.
  simulate(world, 6);
  constexpr int kSamples = 28;  // 14 s, twice a second
  double aloftSum = 0, heightSum = 0;
  int outsideTheScene = 0, aloftOutsideTheCones = 0, heldOutsideTheCones = 0;
  // A ball knocked out of a cone may be caught in mid-air on its way down
  // at one sample; one seen aloft outside the cones at two samples in a row
  // (0.5 s apart) would be held there by air that should not exist.
  std::set<std::uint32_t> outsideLastSample;
  for (int sample = 0; sample < kSamples; ++sample) {
    simulate(world, 0.5);
    std::set<std::uint32_t> outsideNow;
    for (BodyId id : dynamicBodies(world)) {
      const Vec2 p = stateOf(world, id).position;
      if (p.x() < 0 || p.x() > kSceneSize.x() || p.y() < 0 || p.y() > kSceneSize.y()) ++outsideTheScene;
      if (p.y() < 2) continue;
      ++aloftSum;
      heightSum += p.y() - fanHeight;
      if (inAirflow(p)) continue;
      ++aloftOutsideTheCones;
      outsideNow.insert(id.value);
      if (outsideLastSample.contains(id.value)) ++heldOutsideTheCones;
    }
    outsideLastSample = std::move(outsideNow);
  }
  // A ball alone on the axis hovers where 1/2 rho Cd (2r) u^2 = m g, u = S (1 - h / R).
  const double mass = kPi * kLightBallRadius * kLightBallRadius * materialProperties(Material::Ice).density;
  const double hoverSpeed = std::sqrt(mass * kG / (0.5 * 1.2 * 2 * kLightBallRadius));
  const double hover = kFanRange * (1 - hoverSpeed / kFanSpeed);
  const double meanHeight = heightSum / std::max(1.0, aloftSum);
  std::printf("fans: %.2f balls aloft on average at %.2f m above the fans (one ball alone on the axis: %.2f m); "
              "%d of %.0f aloft sightings outside the cones\n",
              aloftSum / kSamples, meanHeight, hover, aloftOutsideTheCones, aloftSum);
  EXPECT_EQ(outsideTheScene, 0);
  EXPECT_EQ(heldOutsideTheCones, 0) << "no air outside the cones: a ball there falls";
  EXPECT_LE(aloftOutsideTheCones, aloftSum / 20) << "balls knocked out of a cone are rare";
  EXPECT_GE(aloftSum / kSamples, 4);
  EXPECT_NEAR(meanHeight, hover, 1.5) << "riders hover about where drag equals weight";
}

}  // namespace
}  // namespace impulse::test
