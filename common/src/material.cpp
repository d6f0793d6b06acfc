#include "impulse/material.h"

#include <array>

namespace impulse {

namespace {

// Index order follows the Material enum.
constexpr std::array<MaterialProperties, kMaterialCount> kMaterials = {{
    {"SOLID", 500, Real(0.7), Real(0.40), Real(0.30), Real(0.02)},
    {"ICE", 100, Real(0.3), Real(0.03), Real(0.01), Real(0.005)},
    {"WOOD", 700, Real(0.2), Real(0.50), Real(0.40), Real(0.03)},
    {"METAL", 2000, Real(0.1), Real(0.40), Real(0.30), Real(0.01)},
    {"RUBBER", 200, Real(0.8), Real(0.90), Real(0.80), Real(0.04)},
    // Issue 15's three (not in the seed): dense and dead STONE, hard and
    // slippery GLASS that still rings, light FOAM that swallows impacts and
    // rolls poorly.
    {"STONE", 2400, Real(0.15), Real(0.65), Real(0.50), Real(0.02)},
    {"GLASS", 2500, Real(0.55), Real(0.25), Real(0.20), Real(0.005)},
    {"FOAM", 30, Real(0.05), Real(0.80), Real(0.70), Real(0.08)},
}};

}  // namespace

const MaterialProperties& materialProperties(Material material) {
  return kMaterials[static_cast<std::size_t>(material)];
}

std::optional<Material> materialFromIndex(int index) {
  if (index < 0 || index >= kMaterialCount) return std::nullopt;
  return static_cast<Material>(index);
}

}  // namespace impulse
