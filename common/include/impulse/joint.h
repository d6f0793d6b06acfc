#pragma once
/// Joints: constraints between two bodies, or a body and the world. They are
/// solved with the contacts (constraint_kind.h), warm started, coloured with
/// them and asleep with their islands; a world without joints pays nothing.

#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "impulse/body.h"
#include "impulse/math.h"

namespace impulse {

/// Stable joint handle, 0 is null; built like BodyId (slot + generation).
struct JointId {
  std::uint32_t value = 0;

  static JointId make(std::int32_t slot, std::uint32_t generation) {
    return {BodyId::make(slot, generation).value};
  }
  bool isNull() const { return value == 0; }
  std::int32_t slot() const { return BodyId{value}.slot(); }
  std::uint32_t generation() const { return BodyId{value}.generation(); }
  friend bool operator==(JointId, JointId) = default;
  friend auto operator<=>(JointId, JointId) = default;
};

/// A rod (stiffness 0) or a spring of `stiffness` N/m and `damping` N*s/m
/// between the anchors. Length 0: the anchors' distance at creation.
struct DistanceJointSettings {
  Real length = 0;
  Real stiffness = 0;
  Real damping = 0;
};

/// Slack below maxLength, never longer. 0: the anchors' distance at creation.
struct RopeJointSettings {
  Real maxLength = 0;
};

/// A pin at anchorA; angles are body B's rotation relative to A since creation.
struct RevoluteJointSettings {
  bool enableLimit = false;
  Real lowerAngle = 0;
  Real upperAngle = 0;
  bool enableMotor = false;
  Real motorSpeed = 0;      ///< rad/s
  Real maxMotorTorque = 0;  ///< N*m
  Real stiffness = 0;       ///< N*m/rad, 0: no spring
  Real damping = 0;         ///< N*m*s/rad
};

/// B slides along `axis` (fixed in A, given in world at creation), no turn.
/// Translation, limits and the spring's rest are measured from the
/// position at creation.
struct PrismaticJointSettings {
  Vec2 axis = Vec2(1, 0);
  bool enableLimit = false;
  Real lower = 0;
  Real upper = 0;
  bool enableMotor = false;
  Real motorSpeed = 0;     ///< m/s
  Real maxMotorForce = 0;  ///< N
  Real stiffness = 0;      ///< N/m, 0: no spring
  Real damping = 0;        ///< N*s/m
};

/// Glues B to A; stiffness 0 is rigid, > 0 soft (N/m, N*m/rad).
struct WeldJointSettings {
  Real linearStiffness = 0;
  Real angularStiffness = 0;
};

/// A wheel (B) on a suspension spring along `axis` (fixed in A), free to
/// turn, with an optional motor. The spring rests at the creation position.
struct WheelJointSettings {
  Vec2 axis = Vec2(0, 1);
  Real stiffness = 0;  ///< N/m along the axis, 0: rigid
  Real damping = 0;    ///< N*s/m
  bool enableMotor = false;
  Real motorSpeed = 0;      ///< rad/s
  Real maxMotorTorque = 0;  ///< N*m
};

/// Pulls anchorA of body A towards a target (anchorB at creation; then
/// World::updateJoint) with at most maxForce, as a spring. Stiffness 0 is a
/// rigid drive: the body moves with real velocity, the fastest from which
/// half of maxForce still stops it at the target, and stays awake while its
/// anchor is more than 1 cm away. Motor speeds of every kind are B's
/// relative to A: with B the world, A turns or slides the other way.
struct MouseJointSettings {
  Real maxForce = 0;   ///< N
  Real stiffness = 0;  ///< N/m
  Real damping = 0;    ///< N*s/m
};

using JointSettings = std::variant<DistanceJointSettings, RopeJointSettings, RevoluteJointSettings,
                                   PrismaticJointSettings, WeldJointSettings, WheelJointSettings,
                                   MouseJointSettings>;

/// Everything needed to create a joint. Anchors are world points at
/// creation; a null bodyB fixes the joint to the world at anchorB.
struct JointDef {
  BodyId bodyA;
  BodyId bodyB;
  Vec2 anchorA = Vec2::Zero();
  Vec2 anchorB = Vec2::Zero();
  /// Whether the two bodies still collide with each other.
  bool collideConnected = false;
  JointSettings settings;
};

/// Outcome of a joint creation: an id, or what was wrong.
struct JointResult {
  JointId id;
  std::string error;
  bool ok() const { return error.empty(); }
};

/// What changes on a live joint (unset: unchanged).
struct JointUpdate {
  std::optional<Vec2> target{};        ///< mouse joints
  std::optional<Real> motorSpeed{};    ///< revolute, prismatic, wheel
  std::optional<Real> maxMotorForce{}; ///< N (prismatic) or N*m (revolute, wheel)
};

/// What does not change over a joint's life (and its settings as in force).
struct JointDescription {
  JointId id;
  BodyId bodyA;
  BodyId bodyB;  ///< null: the world
  Vec2 localAnchorA = Vec2::Zero();  ///< in A's frame (centre of mass)
  Vec2 localAnchorB = Vec2::Zero();  ///< in B's frame, or world when bodyB is null
  bool collideConnected = false;
  JointSettings settings;
};

/// Impulses per sub-step, kept across steps for warm starting (the spring's
/// only for the reaction: springs are solved afresh every sub-step).
struct JointImpulses {
  Vec2 point = Vec2::Zero();        ///< pin of revolute, weld, rigid mouse
  Vec2 pointSpring = Vec2::Zero();  ///< soft weld, mouse
  Real perpendicular = 0;           ///< across the axis (prismatic, wheel)
  Real angular = 0;                 ///< rigid angle (weld, prismatic)
  Real axial = 0;                   ///< rod length, rigid wheel axis
  Real spring = 0;
  Real motor = 0;
  Real lower = 0;
  Real upper = 0;
};

/// A joint's state after the last step.
struct JointState {
  Vec2 reactionForce = Vec2::Zero();  ///< N, on body B
  Real reactionTorque = 0;            ///< N*m, on body B
  Real length = 0;       ///< distance between the anchors
  Real angle = 0;        ///< B's rotation relative to A since creation
  Real translation = 0;  ///< along the axis (prismatic, wheel)
};

}  // namespace impulse
