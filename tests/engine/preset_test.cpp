// Every preset's outcome in docs/product.md, asserted from body states.

#include "impulse/scenes/presets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

// Layout figures of docs/product.md (the seed's canvas at 32 px/m).
constexpr double kBorder = 0.78125;  // wall and floor thickness
constexpr double kFloorTop = kBorder;
constexpr double kRightWallFace = 25 - kBorder;   // inner face of the right wall
constexpr double kCeilingFace = 18.75 - kBorder;  // inner face of preset 8's ceiling
constexpr double kSceneMiddle = 12.5;
// Longest any preset needs to come to rest (the slowest, the valley, takes 15 s).
constexpr double kSettleSeconds = 40;

struct LoadedPreset {
  World world;
  PresetInfo info;
  std::vector<BodyId> dynamic;  // creation order
};

LoadedPreset load(int id, Material selected = Material::Solid) {
  LoadedPreset preset;
  std::optional<PresetInfo> info = loadPreset(preset.world, id, selected);
  EXPECT_TRUE(info.has_value());
  if (info) preset.info = *info;
  preset.dynamic = dynamicBodies(preset.world);
  return preset;
}

double radiusOf(const World& world, BodyId id) {
  return world.bodyDescription(id)->shape.circle().radius;
}

// ---- Information ----

TEST(PresetLoading, EveryPresetHasTitleAndExplanation_AndDrawingOnlyInSandboxAndTutorials) {
  for (int id = 0; id < kPresetCount; ++id) {
    SCOPED_TRACE(id);
    World world;
    std::optional<PresetInfo> info = loadPreset(world, id);
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->id, id);
    EXPECT_FALSE(info->title.empty());
    ASSERT_FALSE(info->explanation.empty());
    for (const std::string& line : info->explanation) EXPECT_FALSE(line.empty());
    EXPECT_EQ(info->drawingAllowed, id == 0 || id == 3 || id == 4);
    EXPECT_GT(world.bodyCount(), 0) << "every scene has at least its boundary";
    EXPECT_EQ(world.gravity(), id == 15 ? Vec2(Vec2::Zero()) : kDefaultGravity) << "orbits are weightless";
  }
}

TEST(PresetLoading, OutOfRangeIdReturnsNothing_AndLeavesWorldUntouched) {
  World world;
  addCircle(world, {.center = Vec2(3, 3)});
  world.setGravity(Vec2(1, -2));
  world.step(kDt);
  const std::uint64_t hash = world.stateHash();
  const int bodies = world.bodyCount();
  for (int id : {kPresetCount, -1}) {
    EXPECT_FALSE(loadPreset(world, id).has_value());
    EXPECT_EQ(world.stateHash(), hash);
    EXPECT_EQ(world.bodyCount(), bodies);
    EXPECT_EQ(world.gravity(), Vec2(1, -2));
  }
  EXPECT_EQ(kPresetCount, 22);
}

TEST(PresetLoading, LoadingAPresetReplacesThePreviousScene_AndResetsGravity) {
  World world;
  loadPreset(world, 8);
  world.setGravity(Vec2(0, -2));
  simulate(world, 1);
  loadPreset(world, 0);
  EXPECT_EQ(world.bodyCount(), 3) << "sandbox: floor and two walls only";
  EXPECT_TRUE(dynamicBodies(world).empty());
  EXPECT_EQ(world.gravity(), kDefaultGravity);
}

// ---- Scenes ----

TEST(Preset1Ramp, BallRollsDownAndStopsWellShortOfTheRightWall) {
  LoadedPreset p = load(1);
  ASSERT_EQ(p.dynamic.size(), 1u);
  const BodyId ball = p.dynamic[0];
  const double r = radiusOf(p.world, ball);
  ASSERT_GT(simulateUntilAsleep(p.world, kSettleSeconds), 0) << "the ball comes to rest";
  BodyState s = stateOf(p.world, ball);
  // Rolled off the ramp (its foot is at x = 9.78) and rests on the floor.
  EXPECT_GT(s.position.x(), 9.78 + r);
  EXPECT_NEAR(s.position.y(), kFloorTop + r, 0.005);  // within the 5 mm slop
  // "Well short": at least 2 m of floor (1.6 ball diameters) left free.
  EXPECT_LT(s.position.x() + r, kRightWallFace - 2) << "rests at x = " << s.position.x();
}

TEST(Preset2Valley, BallOscillatesLowerEachTime_AndRestsInTheMiddle) {
  LoadedPreset p = load(2);
  ASSERT_EQ(p.dynamic.size(), 1u);
  const BodyId ball = p.dynamic[0];
  const BodyState start = stateOf(p.world, ball);
  ASSERT_LT(start.position.x(), kSceneMiddle);

  // Turning points: the furthest |x - middle| on each side between two
  // crossings of the middle.
  std::vector<double> amplitudes = {kSceneMiddle - start.position.x()};
  double highestOnRight = 0;
  int side = -1;  // -1 left of the middle, +1 right
  simulateUntil(p.world, kSettleSeconds, [&] {
    BodyState s = stateOf(p.world, ball);
    const double offset = s.position.x() - kSceneMiddle;
    if (offset * side < 0) {
      side = -side;
      amplitudes.push_back(0);
    }
    amplitudes.back() = std::max(amplitudes.back(), std::abs(offset));
    if (side > 0) highestOnRight = std::max(highestOnRight, double(s.position.y()));
    return p.world.awakeBodyCount() == 0;
  });
  // Fails to reach its starting height on the other side: 0.5 m (16 px)
  // lower at least, a visible loss.
  EXPECT_LT(highestOnRight, start.position.y() - 0.5);
  // Oscillates: crosses the middle at least three times, each swing smaller.
  EXPECT_GE(amplitudes.size(), 4u);
  for (std::size_t i = 1; i < amplitudes.size(); ++i) {
    EXPECT_LT(amplitudes[i], amplitudes[i - 1]) << "swing " << i;
  }
  // Rests on the valley's flat bottom, which spans x = 11.5 .. 13.5.
  EXPECT_EQ(p.world.awakeBodyCount(), 0);
  BodyState end = stateOf(p.world, ball);
  EXPECT_NEAR(end.position.x(), kSceneMiddle, 1.0);
  EXPECT_NEAR(end.position.y(), kFloorTop + radiusOf(p.world, ball), 0.005);
}

TEST(Preset3PolygonTutorial, ShowsThreeMarkers_AndAllowsDrawing) {
  LoadedPreset p = load(3);
  EXPECT_EQ(p.info.markers.size(), 3u);
  for (const Marker& m : p.info.markers) {
    EXPECT_GT(m.radius, 0);
    EXPECT_TRUE(m.center.x() > kBorder && m.center.x() < kRightWallFace &&
                m.center.y() > kFloorTop);
  }
  EXPECT_TRUE(p.info.drawingAllowed);
  EXPECT_TRUE(p.dynamic.empty()) << "the user draws the shapes";
}

TEST(Preset4CircleTutorial, ShowsConcentricCentreAndRadiusMarkers_AndAllowsDrawing) {
  LoadedPreset p = load(4);
  ASSERT_EQ(p.info.markers.size(), 2u);
  const Marker& a = p.info.markers[0];
  const Marker& b = p.info.markers[1];
  EXPECT_EQ(a.center, b.center);
  EXPECT_NE(a.radius, b.radius);
  EXPECT_TRUE(p.info.drawingAllowed);
  EXPECT_TRUE(p.dynamic.empty());
}

TEST(Preset5Collision, FirstBallSlowsAfterTheHit_AndTheSecondMovesOff) {
  LoadedPreset p = load(5);
  ASSERT_EQ(p.dynamic.size(), 2u);
  const BodyId striker = p.dynamic[0];
  const BodyId target = p.dynamic[1];
  const double targetStart = stateOf(p.world, target).position.x();
  // Speed of the striker on the step before the target starts to move.
  double strikerBefore = 0;
  int hitStep = simulateUntil(p.world, 10, [&] {
    if (stateOf(p.world, target).linearVelocity.norm() > 0.01) return true;
    strikerBefore = stateOf(p.world, striker).linearVelocity.norm();
    return false;
  });
  ASSERT_LT(hitStep, stepsFor(10)) << "the striker reaches the target";
  ASSERT_GT(strikerBefore, 1) << "the striker arrives rolling";
  // Half a second later, once friction has turned both into rolling:
  // equal masses, e = 0.7 leave the striker ~0.43 v and the target ~0.57 v.
  simulate(p.world, 0.5);
  const double strikerAfter = stateOf(p.world, striker).linearVelocity.norm();
  const double targetAfter = stateOf(p.world, target).linearVelocity.norm();
  EXPECT_LT(strikerAfter, 0.6 * strikerBefore);
  EXPECT_GT(targetAfter, strikerAfter);
  ASSERT_GT(simulateUntilAsleep(p.world, kSettleSeconds), 0);
  // The target moved off by at least a ball diameter (1.25 m) and stays ahead.
  EXPECT_GT(stateOf(p.world, target).position.x() - targetStart, 1.25);
  EXPECT_LT(stateOf(p.world, striker).position.x(), stateOf(p.world, target).position.x());
}

// The two targets of the two-level presets (6, 7): those starting right of
// the ramps, lower one first.
struct Targets {
  BodyId lower;
  BodyId upper;
  double lowerStart;
  double upperStart;
};

Targets findTargets(const LoadedPreset& p) {
  std::vector<BodyId> targets;
  for (BodyId id : p.dynamic) {
    if (stateOf(p.world, id).position.x() > 10) targets.push_back(id);
  }
  EXPECT_EQ(targets.size(), 2u);
  if (targets.size() != 2) return {};
  std::sort(targets.begin(), targets.end(), [&](BodyId a, BodyId b) {
    return stateOf(p.world, a).position.y() < stateOf(p.world, b).position.y();
  });
  return {targets[0], targets[1], stateOf(p.world, targets[0]).position.x(),
          stateOf(p.world, targets[1]).position.x()};
}

// Distance each target travelled once everything is at rest.
std::pair<double, double> targetTravel(LoadedPreset& p, const Targets& t) {
  EXPECT_GT(simulateUntilAsleep(p.world, kSettleSeconds), 0) << "everything comes to rest";
  return {std::abs(stateOf(p.world, t.lower).position.x() - t.lowerStart),
          std::abs(stateOf(p.world, t.upper).position.x() - t.upperStart)};
}

TEST(Preset6Mass, BiggerLowerTargetEndsNearerItsStart) {
  LoadedPreset p = load(6);
  Targets t = findTargets(p);
  EXPECT_NEAR(radiusOf(p.world, t.lower), 2 * radiusOf(p.world, t.upper), 1e-6);
  EXPECT_EQ(t.lowerStart, t.upperStart) << "targets at the same distance";
  auto [lower, upper] = targetTravel(p, t);
  // Both were hit (moved more than 10 cm); the heavier one less far.
  EXPECT_GT(lower, 0.1);
  EXPECT_GT(upper, 0.1);
  EXPECT_LT(lower, upper) << "lower " << lower << " m, upper " << upper << " m";
}

TEST(Preset7Speed, UpperTargetHitFromSteeperRampTravelsFurther) {
  LoadedPreset p = load(7);
  Targets t = findTargets(p);
  EXPECT_NEAR(radiusOf(p.world, t.lower), radiusOf(p.world, t.upper), 1e-6) << "equal targets";
  auto [lower, upper] = targetTravel(p, t);
  EXPECT_GT(lower, 0.1);
  EXPECT_GT(upper, lower) << "lower " << lower << " m, upper " << upper << " m";
}

TEST(Preset8WeightlessCrowd, NothingLeavesTheBox_AndEverythingSettles) {
  LoadedPreset p = load(8);
  ASSERT_EQ(p.dynamic.size(), 21u);
  int weightless = 0;
  for (BodyId id : p.dynamic) weightless += p.world.bodyDescription(id)->properties.ignoreGravity ? 1 : 0;
  EXPECT_EQ(weightless, 20);
  // How far each ball reaches past the walls, floor or ceiling (negative
  // while clear of them).
  auto depthOutside = [&](BodyId id) {
    BodyState s = stateOf(p.world, id);
    const double r = radiusOf(p.world, id);
    return std::max({kBorder - (s.position.x() - r), s.position.x() + r - kRightWallFace,
                     kFloorTop - (s.position.y() - r), s.position.y() + r - kCeilingFace});
  };
  double deepest = 0;
  int centresOutside = 0;
  simulateUntil(p.world, kSettleSeconds, [&] {
    for (BodyId id : p.dynamic) {
      const double depth = depthOutside(id);
      deepest = std::max(deepest, depth / radiusOf(p.world, id));
      centresOutside += depth < radiusOf(p.world, id) && allStatesFinite(p.world) ? 0 : 1;
    }
    return p.world.awakeBodyCount() == 0;
  });
  EXPECT_EQ(centresOutside, 0) << "body-steps with a centre outside the box";
  // The large ball lands with 39 times a small ball's mass and may squeeze
  // one into the floor for a few steps; it must never sink half its radius
  // (half-way to tunnelling).
  EXPECT_LT(deepest, 0.5) << "deepest overlap with the box, in radii";
  EXPECT_EQ(p.world.awakeBodyCount(), 0) << "everything settles";
  for (BodyId id : p.dynamic) {
    // At rest every ball is inside, touching the box at most by the 5 mm slop.
    EXPECT_LT(depthOutside(id), 0.005) << "body " << id.value;
  }
}

// Distance each ramp ball of preset 9 rolls, keyed by material.
std::map<Material, double> frictionPresetTravel(Material selected) {
  LoadedPreset p = load(9, selected);
  EXPECT_EQ(p.dynamic.size(), 2u);
  std::map<BodyId, double> starts;
  for (BodyId id : p.dynamic) starts[id] = stateOf(p.world, id).position.x();
  EXPECT_GT(simulateUntilAsleep(p.world, kSettleSeconds), 0);
  std::map<Material, double> travel;
  for (BodyId id : p.dynamic) {
    // The lower ball is always SOLID; with SOLID selected both share a key.
    travel[p.world.bodyDescription(id)->material] = stateOf(p.world, id).position.x() - starts[id];
  }
  return travel;
}

TEST(Preset9Friction, IceBallTravelsFurtherThanSolidBall) {
  std::map<Material, double> travel = frictionPresetTravel(Material::Ice);
  ASSERT_EQ(travel.size(), 2u);
  // 0.5 m (16 px): a difference a viewer sees.
  EXPECT_GT(travel[Material::Ice], travel[Material::Solid] + 0.5)
      << "ICE " << travel[Material::Ice] << " m, SOLID " << travel[Material::Solid] << " m";
}

TEST(Preset9Friction, IdenticalRampsGiveIdenticalTravel_WhenSolidIsSelected) {
  LoadedPreset p = load(9, Material::Solid);
  ASSERT_EQ(p.dynamic.size(), 2u);
  const double start0 = stateOf(p.world, p.dynamic[0]).position.x();
  const double start1 = stateOf(p.world, p.dynamic[1]).position.x();
  ASSERT_GT(simulateUntilAsleep(p.world, kSettleSeconds), 0);
  // The two levels differ only in height: 1 cm covers float round-off of
  // positions at different heights over 10 s of rolling.
  EXPECT_NEAR(stateOf(p.world, p.dynamic[0]).position.x() - start0,
              stateOf(p.world, p.dynamic[1]).position.x() - start1, 0.01);
}

TEST(Preset10Restitution, BounceHeightsAreOrderedByRestitution) {
  LoadedPreset p = load(10);
  ASSERT_EQ(p.dynamic.size(), 5u);
  struct Ball {
    BodyId id;
    double restitution;
    bool bounced = false;
    bool pastApex = false;
    double apex = 0;  // highest centre after the first bounce
  };
  std::vector<Ball> balls;
  for (BodyId id : p.dynamic) balls.push_back({id, p.world.bodyDescription(id)->restitution});
  simulateUntil(p.world, 5, [&] {
    for (Ball& b : balls) {
      BodyState s = stateOf(p.world, b.id);
      if (!b.bounced) {
        b.bounced = s.linearVelocity.y() > 0;
      } else if (!b.pastApex) {
        b.apex = std::max(b.apex, double(s.position.y()));
        b.pastApex = s.linearVelocity.y() < 0;
      }
    }
    return std::all_of(balls.begin(), balls.end(), [](const Ball& b) { return b.pastApex; });
  });
  std::sort(balls.begin(), balls.end(),
            [](const Ball& a, const Ball& b) { return a.restitution > b.restitution; });
  EXPECT_EQ(p.world.bodyDescription(balls.front().id)->material, Material::Rubber);
  EXPECT_EQ(p.world.bodyDescription(balls.back().id)->material, Material::Metal);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    SCOPED_TRACE(materialProperties(p.world.bodyDescription(balls[i].id)->material).name);
    EXPECT_TRUE(balls[i].bounced);
    EXPECT_TRUE(balls[i].pastApex);
    if (i > 0) {
      EXPECT_LT(balls[i].apex, balls[i - 1].apex);
    }
  }
}

// ---- Joint presets (11-14): each against its closed form ----

// Times at which `value` crosses zero going up, found by linear
// interpolation between steps, over `seconds`.
std::vector<double> upwardCrossings(World& world, double seconds,
                                    const std::function<double()>& value) {
  std::vector<double> crossings;
  double previous = value();
  int step = 0;
  simulateUntil(world, seconds, [&] {
    ++step;
    const double now = value();
    if (previous < 0 && now >= 0) {
      crossings.push_back((step - now / (now - previous)) * double(kDt));
    }
    previous = now;
    return false;
  });
  return crossings;
}

// Mean period between the first and last upward crossings.
double meanPeriod(const std::vector<double>& crossings) {
  if (crossings.size() < 2) return 0;
  return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

TEST(Preset11Spring, PeriodIsTwoPiRootMOverK_AndTheAmplitudeIsKept) {
  LoadedPreset p = load(11);
  ASSERT_EQ(p.dynamic.size(), 1u);
  const BodyId ball = p.dynamic[0];
  const double startY = stateOf(p.world, ball).position.y();
  double highest = startY;
  double lowest = startY;
  const auto crossings = upwardCrossings(p.world, 20.5, [&] {
    const double y = stateOf(p.world, ball).position.y();
    highest = std::max(highest, y);
    lowest = std::min(lowest, y);
    return double(stateOf(p.world, ball).linearVelocity.y());
  });
  ASSERT_GE(crossings.size(), 10u);
  // T = 2*pi*sqrt(m/k) = 2 s by construction; stated tolerance 1 %.
  EXPECT_NEAR(meanPeriod(crossings), 2.0, 0.02);
  // Undamped: after 10 periods the swing still spans 2 m (loss < 3 %).
  EXPECT_NEAR(highest - lowest, 2.0, 0.06);
}

TEST(Preset12Pendulum, SmallSwingPeriodIsTwoPiRootLOverG) {
  LoadedPreset p = load(12);
  ASSERT_EQ(p.dynamic.size(), 6u);  // the pendulum, then the cradle's five
  const BodyId bob = p.dynamic[0];
  const double pivotX = 5;
  const auto crossings = upwardCrossings(p.world, 12.5, [&] {
    return double(stateOf(p.world, bob).position.x()) - pivotX;
  });
  ASSERT_GE(crossings.size(), 3u);
  // 2*pi*sqrt(L/g) with the 10-degree correction (1 + theta^2/16); 1 %.
  const double theta = 10 * kPi / 180;
  const double expected = 2 * kPi * std::sqrt(4.0 / kG) * (1 + theta * theta / 16);
  EXPECT_NEAR(meanPeriod(crossings), expected, 0.01 * expected);
}

TEST(Preset12NewtonsCradle, MomentumPassesThroughToTheLastBall) {
  LoadedPreset p = load(12);
  const std::vector<BodyId> cradle(p.dynamic.begin() + 1, p.dynamic.end());
  ASSERT_EQ(cradle.size(), 5u);
  const double restX = stateOf(p.world, cradle[4]).position.x();
  double lastOut = 0;
  double middleOut = 0;
  // The first ball falls 60 degrees (a quarter of a period and more), hits,
  // and the last swings out within the next half period.
  simulateUntil(p.world, 3, [&] {
    lastOut = std::max(lastOut, double(stateOf(p.world, cradle[4]).position.x()) - restX);
    for (int i = 1; i < 4; ++i) {
      const double at = stateOf(p.world, cradle[std::size_t(i)]).position.x();
      middleOut = std::max(middleOut, std::abs(at - (restX - (4 - i) * 1.05)));
    }
    return false;
  });
  // Released 60 degrees out on 4 m (3.46 m to the side). RUBBER keeps 0.8
  // of the speed per contact, so the last ball swings well out (2.5 m
  // measured) while the middle ones barely move (0.4 m).
  EXPECT_GT(lastOut, 1.0);
  EXPECT_LT(middleOut, 0.5 * lastOut);
}

TEST(Preset13ChainBridge, EndPinsCarryTheWholeWeight) {
  LoadedPreset p = load(13);
  // Long enough for the dropped balls and the swinging V to come to rest.
  simulate(p.world, 20);
  double weight = 0;
  for (BodyId id : p.dynamic) weight += p.world.bodyDescription(id)->mass.mass * kG;
  // The two end pins: the first and last joints made.
  const auto joints = p.world.jointIds();
  ASSERT_EQ(joints.size(), 15u);
  double lift = 0;
  for (const JointId end : {joints.front(), joints.back()}) {
    const auto description = p.world.jointDescription(end);
    const auto state = p.world.jointState(end);
    ASSERT_TRUE(description && state);
    // Both end pins join a plank (A) to the world (B); the reaction is
    // stated on B, so the plank is held up by its opposite.
    const double sign = description->bodyB.isNull() ? -1 : 1;
    lift += sign * double(state->reactionForce.y());
  }
  // Balls and planks rest on the bridge alone: the pins carry all of it (1 %).
  EXPECT_NEAR(lift, weight, 0.01 * weight);
}

TEST(Preset14Car, MotorsHoldTheirSpeed_AndTheCarRollsAtOmegaR) {
  LoadedPreset p = load(14);
  ASSERT_EQ(p.dynamic.size(), 3u);  // chassis, two wheels
  const BodyId chassis = p.dynamic[0];
  simulate(p.world, 1);
  const double x0 = stateOf(p.world, chassis).position.x();
  double spinSum = 0;
  int samples = 0;
  // One second on the flat stretch before the bumps (they start at x = 8).
  simulateUntil(p.world, 1, [&] {
    spinSum += double(stateOf(p.world, p.dynamic[1]).angularVelocity);
    ++samples;
    return false;
  });
  const double travelled = stateOf(p.world, chassis).position.x() - x0;
  // The motor's speed (-6 rad/s) within 2 %, bumps included.
  EXPECT_NEAR(spinSum / samples, -6.0, 0.12);
  // Rolling without slipping: v = omega * r = 3 m/s, within 5 % over 1 s.
  EXPECT_NEAR(travelled, 3.0, 0.15);
  // Then over the bumps without getting stuck or flipping.
  simulate(p.world, 3);
  EXPECT_GT(stateOf(p.world, chassis).position.x(), 16);
  EXPECT_LT(std::abs(stateOf(p.world, chassis).angle), 0.5);
}

}  // namespace
}  // namespace impulse
