#pragma once
/// Force fields: forces that act on bodies through space rather than through
/// contact (orbits, fans, liquids). A field sees the awake dynamic bodies
/// once per step, before the solve, and returns a force and torque for each;
/// they act over that step like World::applyForce. A field whose pull
/// depends on where bodies are (gravitation, buoyancy) may return an impulse instead:
/// it is added to the velocity at the start of the step, before the
/// sub-steps move the body, which makes the step symplectic Euler for that
/// pull (orbits neither spiral in nor out).
///
/// Symplectic Euler at the step swings a body about its true path by about
/// w dt / 2 of its distance, w^2 being how fast its acceleration changes per
/// metre (FieldLoad::gradient). A body whose loads add up to w dt > 0.01 is
/// therefore given no load for the step: every field is asked again at
/// every sub-step, with the body where the sub-step has it and dt the
/// sub-step, and its load (impulse plus force times dt) is added to its
/// velocity then. A field that can tell how fast its force changes
/// (FieldLoad::forceChange: gravitation) reports no gradient instead: the
/// force it gives for the step is carried forward to each sub-step along
/// that rate, as if asked there, for one call per step. A world without
/// fields pays nothing for the stage, and one whose fields are uniform or
/// slow (gradient 0 or small) pays one call per field and step.

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "impulse/body.h"
#include "impulse/math.h"
#include "impulse/shape.h"

namespace impulse {

/// A body as a field sees it.
struct FieldBody {
  BodyId id;
  Transform transform;  ///< centre of mass and rotation
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  Real mass = 0;
  Real inertia = 0;  ///< about the centre of mass
  /// The body's shapes, local to the centre of mass (valid for the step).
  std::span<const Shape* const> shapes;
  Real area = 0;
  Real extent = 0;  ///< largest distance from the centre of mass to a shape
};

/// What a field adds to one body for the coming step.
struct FieldLoad {
  Vec2 force = Vec2::Zero();  ///< spread over the step's sub-steps
  /// N/s: how fast `force` changes over the step; sub-step k of length h
  /// feels force + forceChange * k h (0 for a steady force).
  Vec2 forceChange = Vec2::Zero();
  Real torque = 0;
  Vec2 impulse = Vec2::Zero();  ///< N*s, added to the velocity before the sub-steps
  Real angularImpulse = 0;      ///< N*m*s, added to the spin before the sub-steps
  /// 1/s^2: how fast this field's acceleration of the body changes per
  /// metre the body moves (an upper bound will do; 0 for a uniform field).
  /// Fields add theirs; a large sum has the body's loads taken per sub-step.
  Real gradient = 0;
};

/// What a field sees of the world for one step (or one sub-step: see above).
struct FieldStep {
  /// The awake dynamic bodies: the ones the field pushes (loads[i] is bodies[i]'s).
  std::span<const FieldBody> bodies;
  /// Static and sleeping bodies, only for a field that asks (needsStillBodies):
  /// they are sources of the field but are not pushed. A static body's mass
  /// is its area times its density. Asked per sub-step, `bodies` are the
  /// ones taken per sub-step and the other awake bodies are here too, where
  /// the sub-step has them.
  std::span<const FieldBody> stillBodies;
  Vec2 gravity = Vec2::Zero();
  Real dt = 0;  ///< the step's, or the sub-step's when asked per sub-step
};

class ForceField {
 public:
  virtual ~ForceField() = default;
  /// Adds this field's force and torque on step.bodies[i] to loads[i]. The
  /// step drops a body's load if it is not finite, and the step guard holds
  /// speeds to the input limits whatever a field does.
  virtual void apply(const FieldStep& step, std::span<FieldLoad> loads) const = 0;
  /// True for a field that comes from the bodies themselves and so needs
  /// FieldStep::stillBodies; the others do not pay for gathering them.
  virtual bool needsStillBodies() const { return false; }
};

/// A field made from user numbers, or the reason they were refused (the
/// number's name and its range).
struct FieldBuild {
  std::shared_ptr<const ForceField> field;
  std::string error;
  bool ok() const { return error.empty(); }
};

/// Handle of a field in a world; 0 is null.
struct FieldId {
  std::uint32_t value = 0;
  bool isNull() const { return value == 0; }
  friend bool operator==(FieldId, FieldId) = default;
};

}  // namespace impulse
