// Body definitions: building one from user-facing options, the checks of
// a body's own properties, and the per-body material override.

#include "impulse/body.h"

#include "input_limits.h"

namespace impulse {

BodyDef makeBodyDef(const Shape& shape, const Vec2& position, const BodyOptions& options) {
  BodyDef def;
  def.shape = shape;
  def.position = position;
  def.linearVelocity = options.linearVelocity;
  def.angularVelocity = options.angularVelocity;
  def.material = options.material;
  def.materialOverride = options.materialOverride;
  def.interaction = options.interaction;
  def.properties = options.properties;
  def.isAwake = options.isAwake;
  return def;
}

std::string validateBodyProperties(const BodyProperties& properties) {
  const BodyProperties& p = properties;
  if (p.isStatic && p.isKinematic) return "a body is static or kinematic, not both";
  if (!isFinite(p.linearDrag) || !isFinite(p.angularDrag) || !isFinite(p.gravityScale)) {
    return "body has a non-finite drag or gravity scale (NaN or infinity)";
  }
  auto outside = [](Real value, Real lo, Real hi) { return value < lo || value > hi; };
  const std::string dragRange = " must be in [0, " + describeNumber(kMaxDrag) + "] 1/s";
  if (outside(p.linearDrag, 0, kMaxDrag)) return "linear damping " + describeNumber(p.linearDrag) + dragRange;
  if (outside(p.angularDrag, 0, kMaxDrag)) return "angular damping " + describeNumber(p.angularDrag) + dragRange;
  if (outside(p.gravityScale, -kMaxGravityScale, kMaxGravityScale)) {
    return "gravity scale " + describeNumber(p.gravityScale) + " must be in [-" + describeNumber(kMaxGravityScale) +
           ", " + describeNumber(kMaxGravityScale) + "]";
  }
  return {};
}

bool shouldCollide(const CollisionFilter& a, const CollisionFilter& b) {
  if (a.groupIndex == b.groupIndex && a.groupIndex != 0) return a.groupIndex > 0;
  return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

bool queryAccepts(const QueryFilter& query, const CollisionFilter& shape) {
  return (shape.categoryBits & query.maskBits) != 0 && (shape.maskBits & query.categoryBits) != 0;
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
