// Continuous collision: small fast bodies never tunnel through thin static
// walls.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

enum class Projectile { Disc, Box };

struct TunnelCase {
  Projectile shape;
  Real speed;
};

class NoTunnelling : public ::testing::TestWithParam<TunnelCase> {};

// A 0.2 m thick static wall with its left face at x = 0, and a projectile of
// radius (or half-width) 0.1 m fired at it from 5 m to its left. At 200 m/s
// it moves 3.3 m per step, 16 times the wall's thickness.
TEST_P(NoTunnelling, FastSmallBodyNeverEndsBeyondThinStaticWall) {
  const TunnelCase c = GetParam();
  World world;
  const Real thickness = Real(0.2);
  addBox(world, {.center = Vec2(thickness / 2, 5),
                 .halfWidth = thickness / 2,
                 .halfHeight = 5,
                 .isStatic = true});
  const Real size = Real(0.1);
  const Vec2 start(-5, 5);
  const Vec2 velocity(c.speed, 0);
  BodyId projectile =
      c.shape == Projectile::Disc
          ? addCircle(world, {.center = start, .radius = size, .velocity = velocity})
          : addBox(world, {.center = start,
                           .halfWidth = size,
                           .halfHeight = size,
                           .velocity = velocity,
                           .angularVelocity = 3});
  double furthest = start.x();
  bool reboundSeen = false;
  simulateUntil(world, 0.5, [&] {
    BodyState s = stateOf(world, projectile);
    furthest = std::max(furthest, double(s.position.x()));
    reboundSeen = reboundSeen || s.linearVelocity.x() < 0;
    return false;
  });
  // Its centre stays left of the wall's face by its half-size, less the
  // 5 mm slop the contact may sink (1 cm allowed for the box's corner).
  EXPECT_LT(furthest, -size + 0.01) << "reached x = " << furthest;
  EXPECT_TRUE(reboundSeen) << "the wall stopped it";
  EXPECT_LT(stateOf(world, projectile).position.x(), 0);
  EXPECT_TRUE(allStatesFinite(world));
}

INSTANTIATE_TEST_SUITE_P(
    Speeds, NoTunnelling,
    ::testing::Values(TunnelCase{Projectile::Disc, 200}, TunnelCase{Projectile::Disc, 400},
                      TunnelCase{Projectile::Box, 200}, TunnelCase{Projectile::Box, 400}),
    [](const ::testing::TestParamInfo<TunnelCase>& param) {
      return std::string(param.param.shape == Projectile::Disc ? "Disc" : "Box") + "_" +
             std::to_string(static_cast<int>(param.param.speed)) + "mps";
    });

}  // namespace
}  // namespace impulse
