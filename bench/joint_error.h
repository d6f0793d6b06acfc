#pragma once
// Joint errors measured from poses alone, the same way for every engine: each
// anchor is fixed in its body where the description put it at creation and
// carried by the body's current pose, whatever each engine reports
// internally.

#include <array>
#include <vector>

#include "engine_adapter.h"

namespace bench {

/// `local` (in the body's frame, about its centroid) at the pose.
Vec2d worldPoint(const Pose& pose, const Vec2d& local);
/// The world point `world` in the frame of a body at `pose`.
Vec2d localPoint(const Pose& pose, const Vec2d& world);
/// The world point `world` in the frame of `body` as described.
Vec2d localPoint(const BodyDesc& body, const Vec2d& world);

class JointProbe {
 public:
  explicit JointProbe(const SceneDescription& scene);
  /// Where anchor `side` (0: A, 1: B) of joint `joint` is now; a world anchor
  /// stays where it was described.
  Vec2d anchor(const EngineAdapter& engine, int joint, int side) const;
  /// Largest distance (m) between the two anchors of any pin.
  double worstPinGap(const EngineAdapter& engine) const;
  /// Largest change (m) of any rod's length since creation.
  double worstRodError(const EngineAdapter& engine) const;

 private:
  struct Anchors {
    JointKind kind = JointKind::Pin;
    std::array<int, 2> body{};
    std::array<Vec2d, 2> local{};  ///< in the body's frame, or world for kWorldBody
    double length = 0;             ///< at creation
  };
  std::vector<Anchors> joints_;
};

}  // namespace bench
