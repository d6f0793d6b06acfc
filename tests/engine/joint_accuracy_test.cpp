// Joint accuracy against closed forms (issue 14), each with its tolerance.
// Every test prints what it measured ("measured:"), so the figures in the
// issue's closing note come from these runs.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "joint_test_support.h"

namespace impulse::test {
namespace {

void report(const char* what, double value) { std::printf("measured: %s = %.5g\n", what, value); }

// ---- springs ----

struct SpringScene {
  World world;
  BodyId bob;
  double mass = 0;
  double stiffness = 0;
  // A bob on a horizontal spring of rest length 1 to the world origin,
  // pulled out by `amplitude`, weightless; the spring's period is `period`.
  SpringScene(double period, double dampingRatio, double amplitude) {
    bob = addCircle(
        world,
        {.center = Vec2(Real(1 + amplitude), 0), .radius = Real(0.25), .ignoreGravity = true});
    mass = massOf(world, bob);
    stiffness = mass * std::pow(2 * kPi / period, 2);
    double damping = 2 * dampingRatio * std::sqrt(stiffness * mass);
    addJoint(
        world, bob, BodyId{}, stateOf(world, bob).position, Vec2::Zero(),
        DistanceJointSettings{.length = 1, .stiffness = Real(stiffness), .damping = Real(damping)});
  }
  Samples run(double seconds) {
    return record(world, seconds, [&] { return double(stateOf(world, bob).position.x()) - 1; });
  }
};

/// The largest |value| between two times.
double peakBetween(const Samples& s, double from, double to) {
  double peak = 0;
  for (std::size_t i = 0; i < s.time.size(); ++i) {
    if (s.time[i] >= from && s.time[i] < to) peak = std::max(peak, std::abs(s.value[i]));
  }
  return peak;
}

TEST(JointAccuracy, SpringMassPeriod_Within1Percent_AmplitudeLossBelow3PercentOver10Periods) {
  SpringScene scene(1.0, 0, 0.5);
  Samples s = scene.run(10.5);
  double period = s.meanPeriod(0);
  double expected = 2 * kPi * std::sqrt(scene.mass / scene.stiffness);
  report("spring period relative error", period / expected - 1);
  EXPECT_NEAR(period / expected, 1, 0.01);
  double first = peakBetween(s, 0, 1);
  double tenth = peakBetween(s, 9.5, 10.5);
  report("spring amplitude loss over 10 periods", 1 - tenth / 0.5);
  EXPECT_GT(first / 0.5, 0.97);
  EXPECT_GT(tenth / 0.5, 0.97);
}

TEST(JointAccuracy, DampedSpringEnvelope_FollowsExpMinusZetaOmegaT_Within5Percent) {
  const double zeta = 0.1;
  const double amplitude = 0.5;
  SpringScene scene(1.0, zeta, amplitude);
  Samples s = scene.run(4);
  double omega = 2 * kPi;
  double omegaD = omega * std::sqrt(1 - zeta * zeta);
  // Extrema of x = A e^{-zeta w t}(cos wd t + ...) fall at t = n pi / wd,
  // where |x| = A e^{-zeta w t} exactly.
  double worst = 0;
  for (int n = 1; n * kPi / omegaD < 3.9; ++n) {
    double t = n * kPi / omegaD;
    double measured = peakBetween(s, t - 0.1, t + 0.1);
    double expected = amplitude * std::exp(-zeta * omega * t);
    worst = std::max(worst, std::abs(measured / expected - 1));
  }
  report("damped envelope worst relative error", worst);
  EXPECT_LT(worst, 0.05);
}

// ---- pendulums ----

/// Complete elliptic integral of the first kind K(k), by the AGM.
double ellipticK(double k) {
  double a = 1;
  double b = std::sqrt(1 - k * k);
  for (int i = 0; i < 20; ++i) {
    double next = (a + b) / 2;
    b = std::sqrt(a * b);
    a = next;
  }
  return kPi / (2 * a);
}

/// Period of a pendulum of equivalent length l released from theta0.
double pendulumPeriod(double l, double theta0) {
  return 4 * std::sqrt(l / kG) * ellipticK(std::sin(theta0 / 2));
}

/// A bob of radius 0.1 hanging 2 m below the origin, released at theta0;
/// `pinned`: a revolute joint at the origin (the bob turns with the rod, a
/// physical pendulum), else a distance rod (the bob turns freely).
double measuredPendulumRatio(double theta0, bool pinned) {
  const double length = 2;
  World world;
  Vec2 start(Real(length * std::sin(theta0)), Real(-length * std::cos(theta0)));
  BodyId bob = addCircle(world, {.center = start, .radius = Real(0.1)});
  double equivalent = length;
  if (pinned) {
    addJoint(world, bob, BodyId{}, Vec2::Zero(), Vec2::Zero(), RevoluteJointSettings{});
    double r = 0.1;
    equivalent = (r * r / 2 + length * length) / length;
  } else {
    addJoint(world, bob, BodyId{}, start, Vec2::Zero(), DistanceJointSettings{});
  }
  double expected = pendulumPeriod(equivalent, theta0);
  Samples s =
      record(world, 5.2 * expected, [&] { return double(stateOf(world, bob).position.x()); });
  return s.meanPeriod(0) / expected;
}

TEST(JointAccuracy, PendulumPeriod_SmallAnd90Degrees_Within1Percent) {
  for (bool pinned : {false, true}) {
    for (double theta0 : {0.05, kPi / 2}) {
      double ratio = measuredPendulumRatio(theta0, pinned);
      std::printf("measured: pendulum %s theta0 %.2f period relative error = %.5g\n",
                  pinned ? "revolute" : "rod", theta0, ratio - 1);
      EXPECT_NEAR(ratio, 1, 0.01) << (pinned ? "revolute" : "rod") << " theta0 " << theta0;
    }
  }
}

struct CradleOutcome {
  double last = 0;    ///< the last ball's peak speed over the released ball's impact speed
  double others = 0;  ///< the fastest other ball's speed afterwards, same scale
};

CradleOutcome cradle(int subSteps, Real gap) {
  WorldSettings settings;
  settings.subSteps = subSteps;
  World world(settings);
  const Real r = Real(0.25) + gap / 2;
  std::vector<BodyId> balls;
  for (int i = 0; i < 5; ++i) {
    Vec2 pivot(Real(2 * r * i), 0);
    Vec2 at = pivot + Vec2(0, -2);
    if (i == 0) at = pivot + Vec2(Real(-2 * std::sin(0.5)), Real(-2 * std::cos(0.5)));
    BodyDef def = makeBodyDef(Shape::makeCircle(Real(0.25)), at, {.material = Material::Metal});
    def.materialOverride.restitution = 1;
    def.materialOverride.staticFriction = 0;
    def.materialOverride.dynamicFriction = 0;
    CreateResult made = world.createBody(def);
    balls.push_back(made.id);
    addJoint(world, made.id, BodyId{}, at, pivot, DistanceJointSettings{}, true);
  }
  // The released ball's speed at the bottom, and the highest speed the last
  // ball reaches while the first and middle ones stay nearly still.
  double impact = std::sqrt(2 * kG * 2 * (1 - std::cos(0.5)));
  double lastPeak = 0;
  double othersAfter = 0;
  record(world, 1.2, [&] {
    lastPeak = std::max(lastPeak, double(stateOf(world, balls[4]).linearVelocity.norm()));
    return 0.0;
  });
  for (int i = 0; i < 4; ++i)
    othersAfter = std::max(othersAfter, double(stateOf(world, balls[i]).linearVelocity.norm()));
  std::printf(
      "measured: cradle %d sub-steps gap %.3f: last ball %.4g, fastest other %.4g of the impact "
      "speed\n",
      subSteps, gap, lastPeak / impact, othersAfter / impact);
  return {lastPeak / impact, othersAfter / impact};
}

// Balls 5 cm apart, elastic, no friction, at the default 4 sub-steps: each
// collision is one pair at a time. Touching balls (gap 0) pass only about
// 43 % (printed, not held): the contact solver's restitution targets come
// from the approach speeds at the step's start, which only the first pair
// has, so the chain behind it absorbs the blow inelastically.
TEST(JointAccuracy, NewtonsCradle_PassesMomentumThroughFiveBalls) {
  CradleOutcome spaced = cradle(4, Real(0.05));
  EXPECT_GT(spaced.last, 0.95);
  EXPECT_LT(spaced.others, 0.1);
  cradle(4, 0);
  cradle(16, Real(0.02));
}

// ---- chains and ropes ----

/// A chain of 20 light links on revolute pins, hanging from the world, with
/// a weight of `ratio` links' mass under it; the worst stretch over 5 s.
double heavyChainStretch(int subSteps, double ratio) {
  WorldSettings settings;
  settings.subSteps = subSteps;
  World world(settings);
  const int links = 20;
  const Real linkLength = Real(0.5);
  BodyId previous{};
  Vec2 top = Vec2(0, 20);
  double linkMass = 0;
  for (int i = 0; i < links; ++i) {
    Vec2 joint = top - Vec2(0, linkLength * Real(i));
    BodyId link = addBox(world, {.center = joint - Vec2(0, linkLength / 2),
                                 .halfWidth = Real(0.05),
                                 .halfHeight = linkLength / 2});
    linkMass = massOf(world, link);
    addJoint(world, link, previous, joint, joint, RevoluteJointSettings{});
    previous = link;
  }
  Vec2 end = top - Vec2(0, linkLength * links);
  BodyDef def =
      makeBodyDef(Shape::makePolygon(makeBox(Real(0.5), Real(0.5))), end - Vec2(0, Real(0.5)), {});
  def.materialOverride.density = Real(ratio * linkMass);
  BodyId weight = world.createBody(def).id;
  addJoint(world, weight, previous, end, end, RevoluteJointSettings{});
  // A push sideways, so the chain swings and the pins turn under the load.
  EXPECT_TRUE(world.applyImpulse(weight, Vec2(Real(2 * ratio * linkMass), 0)).ok());
  double nominal = linkLength * links + 0.5;
  double worst = 0;
  record(world, 5, [&] {
    double reach = (top - stateOf(world, weight).position).norm();
    worst = std::max(worst, reach / nominal - 1);
    return 0.0;
  });
  EXPECT_NEAR(massOf(world, weight) / linkMass, ratio, ratio / 100);
  return worst;
}

// The chain is a tree of rigid rows, solved exactly every sub-step
// (joint_tree_pass.h): the stretch is the linearisation's alone, far below
// the 1 % target at the default settings (the soft rows alone stretched it
// by 16 % at 4 sub-steps). At 1000:1 the links under the load swing about
// their pins at about sqrt(r T / I) = 480 rad/s, the most a 240 Hz
// sub-step can follow: that swinging chain needs 8 sub-steps.
TEST(JointAccuracy, HeavyChain_300To1And1000To1WeightOn20Links_StretchesBelow1Percent) {
  const int defaultSubSteps = WorldSettings{}.subSteps;
  for (auto [ratio, subSteps] : {std::pair{300.0, defaultSubSteps}, std::pair{1000.0, 8}}) {
    double stretch = heavyChainStretch(subSteps, ratio);
    std::printf("measured: heavy chain %g:1 worst stretch, %d sub-steps = %.5g\n", ratio, subSteps,
                stretch);
    EXPECT_LT(stretch, 0.0001) << ratio << ":1";
  }
}

/// `links` bars of 0.5 m pinned end to end in a row at height y, centred
/// on x = 0, not held by the world; returns the bars.
std::vector<BodyId> addFreeChain(World& world, int links, Real y) {
  std::vector<BodyId> bars;
  const Real left = -Real(0.25) * Real(links);
  for (int i = 0; i < links; ++i) {
    bars.push_back(addBox(world, {.center = Vec2(left + Real(0.5) * Real(i) + Real(0.25), y),
                                  .halfWidth = Real(0.25), .halfHeight = Real(0.05)}));
    if (i == 0) continue;
    const Vec2 pin(left + Real(0.5) * Real(i), y);
    addJoint(world, bars[i], bars[i - 1], pin, pin, RevoluteJointSettings{});
  }
  return bars;
}

// The exact pass runs where the soft rows would fall short
// (joint_tree_pass.h): on a group held by the world at every step, on a free
// group while its joints carry a load. A free chain falling carries none;
// slung over a peg, its two hanging halves load every joint.
TEST(JointTreePass, FreeChainSolvedExactlyWhileLoaded_HeldChainAlways) {
  World world(sleepless());
  addCircle(world, {.center = Vec2(0, 10), .radius = Real(0.5), .isStatic = true});
  const std::vector<BodyId> slung = addFreeChain(world, 12, Real(12));
  // A pendulum of two bars beside it, held by a world pin.
  const BodyId upper = addBox(world, {.center = Vec2(20, 9.75), .halfWidth = 0.05, .halfHeight = 0.25});
  const BodyId lower = addBox(world, {.center = Vec2(20, 9.25), .halfWidth = 0.05, .halfHeight = 0.25});
  addJoint(world, upper, BodyId{}, Vec2(20, 10), Vec2(20, 10), RevoluteJointSettings{});
  addJoint(world, lower, upper, Vec2(20, 9.5), Vec2(20, 9.5), RevoluteJointSettings{});
  const int heldJoints = 2;
  const int allJoints = heldJoints + static_cast<int>(slung.size()) - 1;

  int fallingSteps = 0;
  int fallingSoft = 0;
  while (stateOf(world, slung.front()).position.y() > Real(11)) {
    world.step(kDt);
    ++fallingSteps;
    if (world.profile().passes.treeJoints == heldJoints) ++fallingSoft;
  }
  EXPECT_GT(fallingSteps, 10);
  EXPECT_EQ(fallingSoft, fallingSteps) << "the falling chain carries no load: soft rows alone";
  simulate(world, 4);
  EXPECT_EQ(world.profile().passes.treeJoints, allJoints) << "slung over the peg, every joint is loaded";
}

/// A leg of three bars (hip, thigh, shin) on limited knees like a ragdoll's,
/// tipped over and thrown at the ground at 27 m/s (v3's rain lands its
/// ragdolls so). The fastest any knee's two ends move apart at the end of a
/// step in which the tree pass solved the leg, over the landing and the
/// second after it.
double landingLegWorstKneeSpeed() {
  World world(sleepless());
  // Dead (no bounce, as v3's rain): the restitution pass runs after the
  // sub-steps and gives the contacts the last word by design.
  const auto deadBox = [&](const BoxSpec& spec) {
    BodyDef def;
    def.shape = Shape::makePolygon(makeBox(spec.halfWidth, spec.halfHeight));
    def.position = spec.center;
    def.angle = spec.angle;
    def.properties.isStatic = spec.isStatic;
    def.linearVelocity = spec.velocity;
    def.materialOverride.restitution = 0;
    const CreateResult result = world.createBody(def);
    EXPECT_TRUE(result.ok()) << result.error;
    return result.id;
  };
  deadBox({.center = Vec2(0, -1), .halfWidth = 20, .halfHeight = 1, .isStatic = true});
  const Vec2 along = Vec2(Real(0.3), Real(-1)).normalized();
  const Real angle = std::atan2(along.y(), along.x());
  const Vec2 top(0, Real(2.5));
  std::vector<BodyId> bars;
  for (int i = 0; i < 3; ++i) {
    bars.push_back(deadBox({.center = top + (Real(0.5) * Real(i) + Real(0.25)) * along,
                                  .halfWidth = Real(0.25),
                                  .halfHeight = Real(0.06),
                                  .angle = angle,
                                  .velocity = Real(27) * along}));
  }
  RevoluteJointSettings knee;
  knee.enableLimit = true;
  knee.lowerAngle = Real(-0.25) * Real(kPi);
  knee.upperAngle = 0;
  // Each knee's point on each of its bars, in the bar's frame.
  std::vector<std::pair<Vec2, Vec2>> ends;
  for (int i = 1; i < 3; ++i) {
    const Vec2 point = top + Real(0.5) * Real(i) * along;
    addJoint(world, bars[i], bars[i - 1], point, point, knee);
    const BodyState below = stateOf(world, bars[i]);
    const BodyState above = stateOf(world, bars[i - 1]);
    ends.emplace_back(Rot::fromAngle(below.angle).applyInverse(point - below.position),
                      Rot::fromAngle(above.angle).applyInverse(point - above.position));
  }
  const auto pointVelocity = [&](BodyId bar, const Vec2& local) {
    const BodyState s = stateOf(world, bar);
    return Vec2(s.linearVelocity + cross(s.angularVelocity, Rot::fromAngle(s.angle).apply(local)));
  };
  double worst = 0;
  int solvedSteps = 0;
  record(world, 1.2, [&] {
    if (world.profile().passes.treeJoints == 0) return 0.0;
    ++solvedSteps;
    for (int i = 1; i < 3; ++i) {
      const Vec2 apart = pointVelocity(bars[i], ends[i - 1].first) - pointVelocity(bars[i - 1], ends[i - 1].second);
      worst = std::max(worst, double(apart.norm()));
    }
    return 0.0;
  });
  EXPECT_GE(solvedSteps, 10) << "the tree pass solves the leg from its landing on";
  return worst;
}

// The ground stops the shin within a step while the thigh goes on; the
// contacts' relax runs after the joints', and without the exact relax it had
// the last word: the knees ended steps opening at up to 9.4 m/s here (v3's
// rain: knees opened 0.29 m against v3's 0.20). Each step now ends with the
// knees' ends moving together to within the pass's compliance.
TEST(JointTreePass, LandingLeg_KneesEndEverySolvedStepTogether_Within1cmPerSecond) {
  const double speed = landingLegWorstKneeSpeed();
  report("leg landing at 27 m/s, fastest knee opening at a step's end (m/s)", speed);
  EXPECT_LT(speed, 0.01);
}

/// A chain of `links` bars pinned to the world at both ends (a bridge's
/// loop through the world), sagging from a V; the worst distance between
/// the two bodies' ends at any pin over `seconds`.
double pinnedBothEndsWorstGap(int links, double seconds) {
  World world;
  std::vector<BodyId> bars;
  std::vector<Vec2> pins;
  Vec2 pin(0, 10);
  for (int i = 0; i < links; ++i) {
    const Vec2 next = pin + Vec2(1, i < links / 2 ? Real(-0.4) : Real(0.4));
    bars.push_back(addBox(world, {.center = (pin + next) / 2, .halfWidth = Real(0.5),
                                  .halfHeight = Real(0.05),
                                  .angle = std::atan2((next - pin).y(), (next - pin).x())}));
    pins.push_back(pin);
    pin = next;
  }
  pins.push_back(pin);
  addJoint(world, bars.front(), BodyId{}, pins.front(), pins.front(), RevoluteJointSettings{});
  for (int i = 1; i < links; ++i) addJoint(world, bars[i], bars[i - 1], pins[i], pins[i], RevoluteJointSettings{});
  addJoint(world, bars.back(), BodyId{}, pins.back(), pins.back(), RevoluteJointSettings{});
  // Each bar's ends in its own frame, to find where the pins are now.
  std::vector<std::pair<Vec2, Vec2>> ends;
  for (int i = 0; i < links; ++i) {
    BodyState s = stateOf(world, bars[i]);
    Transform t{s.position, Rot::fromAngle(s.angle)};
    ends.emplace_back(t.applyInverse(pins[i]), t.applyInverse(pins[i + 1]));
  }
  auto endOf = [&](int bar, bool far) {
    BodyState s = stateOf(world, bars[bar]);
    Transform t{s.position, Rot::fromAngle(s.angle)};
    return t.apply(far ? ends[bar].second : ends[bar].first);
  };
  double worst = 0;
  record(world, seconds, [&] {
    worst = std::max(worst, double((endOf(0, false) - pins.front()).norm()));
    worst = std::max(worst, double((endOf(links - 1, true) - pins.back()).norm()));
    for (int i = 1; i < links; ++i) worst = std::max(worst, double((endOf(i, false) - endOf(i - 1, true)).norm()));
    return 0.0;
  });
  return worst;
}

// Two pins to the world close a loop through it: the exact pass keeps both
// (the second through its small compliance) while the chain swings down.
TEST(JointAccuracy, ChainPinnedAtBothEnds_SwingsWithEveryPinWithin1mm) {
  double gap = pinnedBothEndsWorstGap(10, 5);
  report("chain pinned at both ends, worst pin gap (m)", gap);
  EXPECT_LT(gap, 0.001);
}

// A loop of joints between bodies (a four-bar linkage) has no tree: it
// keeps the soft rows alone, and still holds together and stays finite.
TEST(JointAccuracy, FourBarLoop_KeepsTheSoftRows_HoldsWithin1cm) {
  World world;
  const BodyId crank = addBox(world, {.center = Vec2(0, Real(5.5)), .halfWidth = Real(0.05), .halfHeight = Real(0.5)});
  const BodyId coupler = addBox(world, {.center = Vec2(1, 6), .halfWidth = 1, .halfHeight = Real(0.05)});
  const BodyId rocker = addBox(world, {.center = Vec2(2, Real(5.5)), .halfWidth = Real(0.05), .halfHeight = Real(0.5)});
  const BodyId link = addBox(world, {.center = Vec2(1, 5), .halfWidth = 1, .halfHeight = Real(0.05)});
  const Vec2 corners[4] = {Vec2(0, 5), Vec2(0, 6), Vec2(2, 6), Vec2(2, 5)};
  addJoint(world, crank, BodyId{}, corners[0], corners[0], RevoluteJointSettings{});
  addJoint(world, crank, coupler, corners[1], corners[1], RevoluteJointSettings{});
  addJoint(world, coupler, rocker, corners[2], corners[2], RevoluteJointSettings{});
  addJoint(world, rocker, link, corners[3], corners[3], RevoluteJointSettings{});
  addJoint(world, link, crank, corners[0], corners[0], RevoluteJointSettings{});
  ASSERT_TRUE(world.applyImpulse(coupler, Vec2(2, 0)).ok());
  double worst = 0;
  record(world, 3, [&] {
    for (const JointId id : world.jointIds()) {
      const auto state = world.jointState(id);
      const auto description = world.jointDescription(id);
      if (!state || !description) continue;
      if (!description->bodyB.isNull()) worst = std::max(worst, double(state->length));
    }
    return 0.0;
  });
  report("four-bar loop worst pin gap (m)", worst);
  EXPECT_LT(worst, 0.01);
  for (const BodyId id : {crank, coupler, rocker, link}) {
    EXPECT_TRUE(stateOf(world, id).position.allFinite());
  }
}

TEST(JointAccuracy, Rope_NeverExceedsItsLengthByMoreThan1cm) {
  World world;
  BodyId bob = addCircle(world, {.center = Vec2(Real(0.5), 0), .radius = Real(0.2)});
  JointId rope = addJoint(world, bob, BodyId{}, Vec2(Real(0.5), 0), Vec2::Zero(),
                          RopeJointSettings{.maxLength = 3});
  bool wasSlack = false;
  double worst = highestOver(world, 6, [&] {
    double length = world.jointState(rope)->length;
    wasSlack = wasSlack || length < 2.5;
    return length - 3;
  });
  report("rope worst excess (m)", worst);
  EXPECT_TRUE(wasSlack);
  EXPECT_LT(worst, 0.01);
}

// ---- motors and limits ----

TEST(JointAccuracy, RevoluteMotor_ReachesAndHoldsItsSpeedUnderALoad_Within1Percent) {
  World world;
  // An unbalanced bar pinned at one end: gravity's torque changes sign as it
  // turns. The joint's speed is B's (the world's) relative to A: the bar
  // turns at -motorSpeed.
  BodyId bar = addBox(world, {.center = Vec2(1, 0), .halfWidth = 1, .halfHeight = Real(0.1)});
  double maxTorque = 10 * massOf(world, bar) * kG * 1;
  addJoint(world, bar, BodyId{}, Vec2::Zero(), Vec2::Zero(),
           RevoluteJointSettings{
               .enableMotor = true, .motorSpeed = 3, .maxMotorTorque = Real(maxTorque)});
  simulate(world, 0.5);
  double worst = highestOver(
      world, 4, [&] { return std::abs(-stateOf(world, bar).angularVelocity / 3.0 - 1); });
  report("revolute motor worst speed error", worst);
  EXPECT_LT(worst, 0.01);
}

TEST(JointAccuracy, RevoluteLimit_HoldsAHeavyBarWithin0p01Rad) {
  World world;
  BodyId bar = addBox(
      world,
      {.center = Vec2(1, 0), .halfWidth = 1, .halfHeight = Real(0.1), .material = Material::Metal});
  BodyId weight = addBox(world, {.center = Vec2(Real(2.2), 0),
                                 .halfWidth = Real(0.2),
                                 .halfHeight = Real(0.2),
                                 .material = Material::Metal});
  addJoint(world, weight, bar, Vec2(Real(2.2), 0), Vec2(Real(2.2), 0), WeldJointSettings{});
  JointId hinge =
      addJoint(world, bar, BodyId{}, Vec2::Zero(), Vec2::Zero(),
               RevoluteJointSettings{
                   .enableLimit = true, .lowerAngle = Real(-0.25), .upperAngle = Real(0.25)});
  // The bar falls clockwise: relative to it the world (B) turns the other
  // way, so the upper limit carries the load.
  double highest = highestOver(world, 3, [&] { return double(world.jointState(hinge)->angle); });
  report("revolute limit worst overshoot (rad)", highest - 0.25);
  EXPECT_GT(highest, 0.24);
  EXPECT_LT(highest, 0.25 + 0.01);
}

TEST(JointAccuracy, PrismaticLimit_HoldsAHangingLoadWithin1cm_UpdateSetsTheMotor) {
  World world;
  BodyId slider = addBox(world, {.center = Vec2(0, 5), .material = Material::Metal});
  JointId rail = addJoint(
      world, slider, BodyId{}, Vec2(0, 5), Vec2(0, 5),
      PrismaticJointSettings{.axis = Vec2(0, 1), .enableLimit = true, .lower = -1, .upper = 1});
  // Translation is B's (the world's) anchor relative to A's: the falling
  // slider drives it up to the upper limit.
  double highest =
      highestOver(world, 2, [&] { return double(world.jointState(rail)->translation); });
  report("prismatic limit worst overshoot (m)", highest - 1);
  EXPECT_GT(highest, 0.99);
  EXPECT_LT(highest, 1 + 0.01);
  EXPECT_NEAR(stateOf(world, slider).position.x(), 0, 0.001);
  // An update sets the motor's numbers; it does not switch the motor on.
  double force = 3 * massOf(world, slider) * kG;
  ASSERT_TRUE(
      world.updateJoint(rail, {.motorSpeed = Real(0.5), .maxMotorForce = Real(force)}).ok());
  auto settings = std::get<PrismaticJointSettings>(world.jointDescription(rail)->settings);
  EXPECT_EQ(settings.motorSpeed, Real(0.5));
  EXPECT_FALSE(settings.enableMotor);  // updating a motor does not enable it
}

TEST(JointAccuracy, PrismaticMotor_HoldsSpeedAgainstGravity_Within1Percent) {
  World world;
  BodyId slider = addBox(world, {.center = Vec2(0, 0), .material = Material::Metal});
  double force = 3 * massOf(world, slider) * kG;
  // The world's anchor moves down relative to the slider: the slider rises.
  addJoint(world, slider, BodyId{}, Vec2(0, 0), Vec2(0, 0),
           PrismaticJointSettings{.axis = Vec2(0, 1),
                                  .enableMotor = true,
                                  .motorSpeed = Real(-0.5),
                                  .maxMotorForce = Real(force)});
  simulate(world, 0.2);
  double worst = highestOver(
      world, 2, [&] { return std::abs(stateOf(world, slider).linearVelocity.y() / 0.5 - 1.0); });
  report("prismatic motor worst speed error", worst);
  EXPECT_LT(worst, 0.01);
}

// ---- weld, wheel, mouse ----

TEST(JointAccuracy, Weld_KeepsTwoBoxesRigidThroughADrop_Within1cmAnd0p01Rad) {
  World world;
  addGround(world);
  BodyId a = addBox(world, {.center = Vec2(0, 3), .angle = Real(0.3)});
  BodyId b = addBox(world, {.center = Vec2(1, Real(3.3))});
  addJoint(world, a, b, Vec2(Real(0.5), Real(3.15)), Vec2(Real(0.5), Real(3.15)),
           WeldJointSettings{});
  Transform ta0{stateOf(world, a).position, Rot::fromAngle(stateOf(world, a).angle)};
  Vec2 local0 = ta0.applyInverse(stateOf(world, b).position);
  double relative0 = stateOf(world, b).angle - stateOf(world, a).angle;
  double worstOffset = 0;
  double worstTurn = 0;
  record(world, 3, [&] {
    BodyState sa = stateOf(world, a);
    BodyState sb = stateOf(world, b);
    Transform ta{sa.position, Rot::fromAngle(sa.angle)};
    worstOffset = std::max(worstOffset, double((ta.applyInverse(sb.position) - local0).norm()));
    worstTurn = std::max(
        worstTurn, std::abs(std::remainder(double(sb.angle - sa.angle) - relative0, 2 * kPi)));
    return 0.0;
  });
  report("weld worst offset (m)", worstOffset);
  report("weld worst relative turn (rad)", worstTurn);
  EXPECT_LT(worstOffset, 0.01);
  EXPECT_LT(worstTurn, 0.01);
}

TEST(JointAccuracy, WheelSuspensionPeriod_Within1Percent_MotorSpeedWithin1Percent) {
  World world;
  BodyId chassis = addBox(world, {.center = Vec2(0, 5), .halfWidth = 2, .isStatic = true});
  BodyId wheel =
      addCircle(world, {.center = Vec2(0, 3), .radius = Real(0.4), .ignoreGravity = true});
  double mass = massOf(world, wheel);
  double stiffness = mass * std::pow(2 * kPi / 0.5, 2);
  // The spring rests where the joint was made; a kick starts the bounce.
  ASSERT_TRUE(world.setVelocity(wheel, Vec2(0, 1), 0).ok());
  addJoint(world, chassis, wheel, Vec2(0, 3), Vec2(0, 3),
           WheelJointSettings{.axis = Vec2(0, 1),
                              .stiffness = Real(stiffness),
                              .enableMotor = true,
                              .motorSpeed = 8,
                              .maxMotorTorque = 100});
  Samples s = record(world, 5.2, [&] { return double(stateOf(world, wheel).position.y()) - 3; });
  double ratio = s.meanPeriod(0) / 0.5;
  report("wheel suspension period relative error", ratio - 1);
  report("wheel motor speed relative error", stateOf(world, wheel).angularVelocity / 8 - 1);
  EXPECT_NEAR(ratio, 1, 0.01);
  EXPECT_NEAR(stateOf(world, wheel).angularVelocity / 8, 1, 0.01);
  EXPECT_NEAR(stateOf(world, wheel).position.x(), 0, 0.001);
}

TEST(JointAccuracy, MouseJoint_PullsToTheTargetWithAtMostMaxForce) {
  World world;
  BodyId box = addBox(world, {.center = Vec2(0, 0), .ignoreGravity = true});
  double mass = massOf(world, box);
  double maxForce = 2 * mass;  // at most 2 m/s^2
  JointId mouse = addJoint(
      world, box, BodyId{}, Vec2(0, 0), Vec2(0, 0),
      MouseJointSettings{
          .maxForce = Real(maxForce), .stiffness = Real(50 * mass), .damping = Real(14 * mass)});
  ASSERT_TRUE(world.updateJoint(mouse, {.target = Vec2(3, 0)}).ok());
  double fastestGain = 0;
  Real previous = 0;
  record(world, 6, [&] {
    Real v = stateOf(world, box).linearVelocity.norm();
    fastestGain = std::max(fastestGain, double(v - previous) / kDt);
    previous = v;
    return 0.0;
  });
  double miss = (stateOf(world, box).position - Vec2(3, 0)).norm();
  report("mouse final distance to target (m)", miss);
  report("mouse peak acceleration / (maxForce/m)", fastestGain / 2);
  EXPECT_LT(miss, 0.01);
  EXPECT_LT(fastestGain, 2 * 1.001);
  EXPECT_NEAR(world.jointState(mouse)->reactionForce.norm(), 0, maxForce * 0.05);
}

/// A rigid mouse joint (stiffness 0) pulling a box at rest towards a target
/// `pull` away, followed for `seconds`.
struct RigidPull {
  double arrival = -1;         ///< s until within 1 cm of the target; -1: never
  double slowestMoving = 1e9;  ///< m/s, lowest reported speed while over 10 cm away
  bool sleptAway = false;      ///< asleep at some step while over 1 cm away
  double overshoot = 0;        ///< m, furthest past the target along the pull
  double steepestGain = 0;     ///< m/s^2, largest speed gain in a step
};

RigidPull pullRigidly(World& world, BodyId box, Vec2 pull, double maxForce, double seconds) {
  const Vec2 start = stateOf(world, box).position;
  const Vec2 target = start + pull;
  const Vec2 along = pull.normalized();
  addJoint(world, box, BodyId{}, start, target, MouseJointSettings{.maxForce = Real(maxForce)});
  RigidPull out;
  Real previousSpeed = 0;
  record(world, seconds, [&] {
    const BodyState state = stateOf(world, box);
    const double away = (target - state.position).norm();
    const double speed = state.linearVelocity.norm();
    if (out.arrival < 0 && away < 0.01) out.arrival = world.simulatedTime();
    if (away > 0.1) out.slowestMoving = std::min(out.slowestMoving, speed);
    out.sleptAway = out.sleptAway || (!state.awake && away > 0.01);
    out.overshoot = std::max(out.overshoot, double(along.dot(state.position - target)));
    out.steepestGain = std::max(out.steepestGain, double(speed - previousSpeed) / kDt);
    previousSpeed = Real(speed);
    return 0.0;
  });
  return out;
}

// A rigid mouse joint drives its body with real velocity, as fast as its
// force allows and no faster than it can stop: a box pulled 5 m (at 1000
// times its weight) arrives within 1 s, moving and awake all the way.
TEST(JointAccuracy, RigidMouseJoint_Pulls5mWithin1s_MovingAwakeAndStoppingAtTheTarget) {
  World world;
  BodyId box = addBox(world, {.center = Vec2(0, 5)});
  const double weight = massOf(world, box) * kG;
  const RigidPull pull = pullRigidly(world, box, Vec2(5, 0), 1000 * weight, 2);
  report("rigid mouse 5 m pull: time to within 1 cm (s)", pull.arrival);
  report("rigid mouse 5 m pull: slowest reported speed while over 10 cm away (m/s)", pull.slowestMoving);
  report("rigid mouse 5 m pull: overshoot (m)", pull.overshoot);
  EXPECT_GT(pull.arrival, 0);
  EXPECT_LT(pull.arrival, 1);
  EXPECT_GT(pull.slowestMoving, 0.5) << "the reported velocity is the motion's";
  EXPECT_FALSE(pull.sleptAway);
  EXPECT_LT(pull.overshoot, 0.01);
  EXPECT_LT((stateOf(world, box).position - Vec2(5, 5)).norm(), 0.01) << "and it stays there";
}

// However far the target, the pull is limited by maxForce: a heavy box on
// a weak joint gains speed at no more than maxForce / mass.
TEST(JointAccuracy, RigidMouseJoint_WeakPull_AcceleratesAtMostMaxForceOverMass) {
  World world;
  BodyId box = addBox(world, {.center = Vec2(0, 0), .material = Material::Metal, .ignoreGravity = true});
  const double mass = massOf(world, box);
  const RigidPull pull = pullRigidly(world, box, Vec2(3, 0), 2 * mass, 5);  // at most 2 m/s^2
  report("rigid mouse weak pull: peak acceleration / (maxForce/m)", pull.steepestGain / 2);
  report("rigid mouse weak pull: time to within 1 cm of 3 m (s)", pull.arrival);
  report("rigid mouse weak pull: overshoot (m)", pull.overshoot);
  EXPECT_LT(pull.steepestGain, 2 * 1.001);
  EXPECT_GT(pull.arrival, 0);
  EXPECT_LT(pull.overshoot, 0.01);
  EXPECT_FALSE(pull.sleptAway);
}

}  // namespace
}  // namespace impulse::test
