#pragma once
/// Force fields: forces that act on bodies through space rather than through
/// contact (orbits, fans, liquids). A field sees the awake dynamic bodies
/// once per step, before the solve, and returns a force and torque for each;
/// they act over that step like World::applyForce. A world without fields
/// pays nothing for the stage.

#include <cstdint>
#include <span>

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
  const Shape* shape = nullptr;  ///< local to the centre of mass
  Material material = Material::Solid;
};

/// What a field adds to one body for the coming step.
struct FieldLoad {
  Vec2 force = Vec2::Zero();
  Real torque = 0;
};

class ForceField {
 public:
  virtual ~ForceField() = default;
  /// Adds this field's force and torque on bodies[i] to loads[i]. The step
  /// drops a body's load if it is not finite, and the step guard holds
  /// speeds to the input limits whatever a field does.
  virtual void apply(std::span<const FieldBody> bodies, std::span<FieldLoad> loads) const = 0;
};

/// Handle of a field in a world; 0 is null.
struct FieldId {
  std::uint32_t value = 0;
  bool isNull() const { return value == 0; }
  friend bool operator==(FieldId, FieldId) = default;
};

}  // namespace impulse
