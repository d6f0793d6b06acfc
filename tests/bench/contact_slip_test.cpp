// ContactSlipProbe (bench/contact_slip.h): how far pieces slide along each
// other where they touch, from poses alone, on poses scripted step by step.

#include "contact_slip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "spawn_schedule.h"

namespace bench {
namespace {

// An engine whose poses the test sets between observations.
class ScriptedPoses final : public EngineAdapter {
 public:
  explicit ScriptedPoses(const SceneDescription& scene) {
    for (const BodyDesc& body : scene.bodies) poses.push_back(describedPose(body));
  }
  void step(double) override {}
  Pose pose(int index) const override { return poses[std::size_t(index)]; }

  std::vector<Pose> poses;
};

// A 1 m box resting on the top face of a static slab (y = 0), and a 1 m
// box resting on that one.
SceneDescription twoBoxesOnASlab() {
  SceneDescription scene;
  addBody(scene, makeBody(ShapeDesc::box(5, 0.5), {0, -0.5}, impulse::Material::Solid, true));
  addBody(scene, makeBody(ShapeDesc::box(0.5, 0.5), {0, 0.5}, impulse::Material::Solid));
  addBody(scene, makeBody(ShapeDesc::box(0.5, 0.5), {0, 1.5}, impulse::Material::Solid));
  return scene;
}

// The probe's largest slip over `steps` observations of the two boxes on
// the slab, `move(poses, step)` setting the poses before each.
template <class Move>
double largestSlipWhile(int steps, Move move) {
  const SceneDescription scene = twoBoxesOnASlab();
  ScriptedPoses engine(scene);
  ContactSlipProbe probe(scene);
  for (int step = 0; step < steps; ++step) {
    move(engine.poses, step);
    probe.observe(engine);
  }
  return probe.largestSlip();
}

TEST(ContactSlip, BoxesSlidingAsOneSlipOnTheSlabOnly) {
  const double slip = largestSlipWhile(30, [](std::vector<Pose>& poses, int) {
    poses[1].position.x += 0.001;
    poses[2].position.x += 0.001;
  });
  EXPECT_NEAR(slip, 0.03, 1e-9);
}

TEST(ContactSlip, ABoxSlidingBackCountsHowFarItGot_NotItsPath) {
  const double slip = largestSlipWhile(40, [](std::vector<Pose>& poses, int step) {
    poses[2].position.x += step < 20 ? 0.001 : -0.001;
  });
  EXPECT_NEAR(slip, 0.02, 1e-9);
}

// Tipped about its lower right corner, the upper box turns on the lower
// one without sliding: what the probe finds is second order in the angle
// (its contact is the middle of the points within reach, not the corner),
// under a hundredth of the corner's 1 cm rise.
TEST(ContactSlip, ABoxTippingOverItsCornerDoesNotSlip) {
  const double slip = largestSlipWhile(40, [](std::vector<Pose>& poses, int step) {
    // Clockwise: the left side rises.
    const double angle = -0.001 * (step + 1), c = std::cos(angle), s = std::sin(angle);
    const Vec2d corner{0.5, 1};
    // The centre, half a box left of and above the corner, turned about it.
    poses[2].position = {corner.x - 0.5 * c - 0.5 * s, corner.y - 0.5 * s + 0.5 * c};
    poses[2].angle = angle;
  });
  EXPECT_LT(slip, 1e-4);
}

}  // namespace
}  // namespace bench
