#pragma once
/// Materials of docs/product.md and how two materials combine at a contact.

#include <cstdint>
#include <optional>
#include <string_view>

#include "impulse/math.h"

namespace impulse {

enum class Material : std::uint8_t { Solid = 0, Ice, Wood, Metal, Rubber, Stone, Glass, Foam };
inline constexpr int kMaterialCount = 8;

struct MaterialProperties {
  std::string_view name;
  Real density;          ///< kg/m^2 (areal density: the world is 2D)
  Real restitution;      ///< bounce coefficient, 0..1
  Real staticFriction;   ///< holds a contact that is not sliding
  Real dynamicFriction;  ///< opposes a contact that slides
  /// Rolling resistance coefficient c_rr: a rolling circle feels a resisting
  /// torque c_rr * N * radius. Not in the seed's table (the seed faked rolling
  /// losses by scaling velocities); values chosen so SPEC's rolling presets
  /// behave like the seed's.
  Real rollingResistance;
};

const MaterialProperties& materialProperties(Material material);

/// Pair mixing as in the seed: the mean of the two coefficients.
inline Real mixCoefficient(Real a, Real b) { return Real(0.5) * (a + b); }

/// Material from its index 0..kMaterialCount-1, or nothing when out of range.
std::optional<Material> materialFromIndex(int index);

}  // namespace impulse
