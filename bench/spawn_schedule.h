#pragma once
// The order in which an adapter creates a scene's bodies and joints: bodies
// in description order once their spawn step has come, each joint (in
// description order) as soon as its bodies exist. Engines differ only in how
// they create one body or joint.

#include <cstddef>

#include "engine_adapter.h"

namespace bench {

class SpawnSchedule {
 public:
  explicit SpawnSchedule(const SceneDescription& scene) : scene_(scene) {}

  /// Creates what is due before step `step` (0 at construction):
  /// createBody(const BodyDesc&) and createJoint(const JointDesc&).
  template <class CreateBody, class CreateJoint>
  void spawnDue(int step, CreateBody&& createBody, CreateJoint&& createJoint) {
    while (bodies_ < scene_.bodies.size() && scene_.bodies[bodies_].spawnStep <= step) {
      createBody(scene_.bodies[bodies_++]);
    }
    while (joints_ < scene_.joints.size() && exists(scene_.joints[joints_].bodyA) &&
           exists(scene_.joints[joints_].bodyB)) {
      createJoint(scene_.joints[joints_++]);
    }
  }

  /// Whether body `index` (or the world) has been created.
  bool exists(int index) const { return index == kWorldBody || static_cast<std::size_t>(index) < bodies_; }

 private:
  const SceneDescription& scene_;
  std::size_t bodies_ = 0;
  std::size_t joints_ = 0;
};

/// Where a body not created yet is: as described, awake.
inline Pose describedPose(const BodyDesc& body) {
  return {body.position, body.angle, body.velocity, body.angularVelocity, true};
}

}  // namespace bench
