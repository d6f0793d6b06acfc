#include "joint_figure.h"

#include <variant>

namespace impulse::viewer {

namespace {

Vec2 worldPoint(const BodySample& body, const Vec2& local) {
  return body.position + Rot::fromAngle(body.angle).apply(local);
}

}  // namespace

JointLook jointLook(const JointSettings& settings) {
  if (const auto* distance = std::get_if<DistanceJointSettings>(&settings)) {
    return distance->stiffness > 0 ? JointLook::Spring : JointLook::Rod;
  }
  if (std::holds_alternative<RopeJointSettings>(settings)) return JointLook::Rope;
  if (std::holds_alternative<PrismaticJointSettings>(settings)) return JointLook::Slider;
  if (std::holds_alternative<MouseJointSettings>(settings)) return JointLook::Pull;
  // Revolute, weld and wheel: a pin at the shared point.
  return JointLook::Pin;
}

std::optional<JointFigure> jointFigure(const JointDescription& joint, const BodySample* a,
                                       const BodySample* b) {
  if (a == nullptr || (!joint.bodyB.isNull() && b == nullptr)) return std::nullopt;
  JointFigure figure;
  figure.look = jointLook(joint.settings);
  figure.a = worldPoint(*a, joint.localAnchorA);
  // A joint to the world keeps a world point (a mouse joint's target).
  figure.b = b != nullptr ? worldPoint(*b, joint.localAnchorB) : joint.localAnchorB;
  return figure;
}

void zigzag(const Vec2& from, const Vec2& to, int teeth, Real width, std::vector<Vec2>& points) {
  points.clear();
  points.push_back(from);
  const Vec2 along = to - from;
  const Real length = along.norm();
  if (length > 0 && teeth > 0) {
    const Vec2 side = leftPerp(along) / length * width;
    // A tenth of the length straight at each end, where the spring is hooked.
    const Vec2 start = from + along * Real(0.1);
    const Vec2 step = along * Real(0.8) / Real(2 * teeth);
    points.push_back(start);
    for (int i = 0; i < 2 * teeth; ++i) {
      const Real sign = i % 2 == 0 ? Real(1) : Real(-1);
      points.push_back(start + step * (Real(i) + Real(0.5)) + side * sign);
    }
    points.push_back(to - along * Real(0.1));
  }
  points.push_back(to);
}

}  // namespace impulse::viewer
