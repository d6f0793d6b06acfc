#include "joint_error.h"

#include <algorithm>
#include <cmath>

#include "spawn_schedule.h"

namespace bench {

Vec2d worldPoint(const Pose& pose, const Vec2d& local) {
  const double c = std::cos(pose.angle), s = std::sin(pose.angle);
  return {pose.position.x + c * local.x - s * local.y, pose.position.y + s * local.x + c * local.y};
}

Vec2d localPoint(const Pose& pose, const Vec2d& world) {
  const double c = std::cos(pose.angle), s = std::sin(pose.angle);
  const double dx = world.x - pose.position.x, dy = world.y - pose.position.y;
  return {c * dx + s * dy, -s * dx + c * dy};
}

Vec2d localPoint(const BodyDesc& body, const Vec2d& world) {
  return localPoint(describedPose(body), world);
}

JointProbe::JointProbe(const SceneDescription& scene) {
  for (const JointDesc& joint : scene.joints) {
    Anchors anchors;
    anchors.kind = joint.kind;
    anchors.body = {joint.bodyA, joint.bodyB};
    const std::array<Vec2d, 2> world{joint.anchorA, joint.anchorB};
    for (int side = 0; side < 2; ++side) {
      const int body = anchors.body[std::size_t(side)];
      anchors.local[std::size_t(side)] =
          body == kWorldBody
              ? world[std::size_t(side)]
              : localPoint(scene.bodies[std::size_t(body)], world[std::size_t(side)]);
    }
    anchors.length =
        std::hypot(joint.anchorB.x - joint.anchorA.x, joint.anchorB.y - joint.anchorA.y);
    joints_.push_back(anchors);
  }
}

Vec2d JointProbe::anchor(const EngineAdapter& engine, int joint, int side) const {
  const Anchors& anchors = joints_[std::size_t(joint)];
  const int body = anchors.body[std::size_t(side)];
  const Vec2d& local = anchors.local[std::size_t(side)];
  return body == kWorldBody ? local : worldPoint(engine.pose(body), local);
}

double JointProbe::worstPinGap(const EngineAdapter& engine) const {
  double worst = 0;
  for (int j = 0; j < static_cast<int>(joints_.size()); ++j) {
    if (joints_[std::size_t(j)].kind != JointKind::Pin) continue;
    Vec2d a = anchor(engine, j, 0), b = anchor(engine, j, 1);
    worst = std::max(worst, std::hypot(b.x - a.x, b.y - a.y));
  }
  return worst;
}

double JointProbe::worstRodError(const EngineAdapter& engine) const {
  double worst = 0;
  for (int j = 0; j < static_cast<int>(joints_.size()); ++j) {
    if (joints_[std::size_t(j)].kind != JointKind::Rod) continue;
    Vec2d a = anchor(engine, j, 0), b = anchor(engine, j, 1);
    worst = std::max(worst,
                     std::abs(std::hypot(b.x - a.x, b.y - a.y) - joints_[std::size_t(j)].length));
  }
  return worst;
}

}  // namespace bench
