// Body definitions: building one from user-facing options, and the
// per-body material override.

#include "impulse/body.h"

namespace impulse {

BodyDef makeBodyDef(const Shape& shape, const Vec2& position, const BodyOptions& options) {
  BodyDef def;
  def.shape = shape;
  def.position = position;
  def.linearVelocity = options.linearVelocity;
  def.angularVelocity = options.angularVelocity;
  def.material = options.material;
  def.isStatic = options.isStatic;
  def.isKinematic = options.isKinematic;
  def.isAwake = options.isAwake;
  def.ignoreGravity = options.ignoreGravity;
  def.linearDrag = options.linearDrag;
  def.angularDrag = options.angularDrag;
  def.materialOverride = options.materialOverride;
  def.gravityScale = options.gravityScale;
  return def;
}

std::string validateMaterialOverride(const MaterialOverride& materialOverride) {
  auto outside = [](const std::optional<Real>& value, Real lo, Real hi) {
    return value && !(isFinite(*value) && *value >= lo && *value <= hi);
  };
  const MaterialOverride& o = materialOverride;
  if (outside(o.density, Real(1e-3), Real(1e6))) return "density must be in (0.001, 1e6] kg/m^2";
  if (outside(o.restitution, 0, 1)) return "restitution must be in [0, 1]";
  if (outside(o.staticFriction, 0, 10) || outside(o.dynamicFriction, 0, 10)) {
    return "friction coefficients must be in [0, 10]";
  }
  if (outside(o.rollingResistance, 0, 1)) return "rolling resistance must be in [0, 1]";
  return {};
}

MaterialProperties resolveCoefficients(Material material, const MaterialOverride& materialOverride) {
  const MaterialOverride& o = materialOverride;
  MaterialProperties resolved = materialProperties(material);
  resolved.density = o.density.value_or(resolved.density);
  resolved.restitution = o.restitution.value_or(resolved.restitution);
  resolved.staticFriction = o.staticFriction.value_or(resolved.staticFriction);
  resolved.dynamicFriction = o.dynamicFriction.value_or(resolved.dynamicFriction);
  resolved.rollingResistance = o.rollingResistance.value_or(resolved.rollingResistance);
  return resolved;
}

}  // namespace impulse
