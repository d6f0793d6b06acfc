#include "palette.h"

namespace impulse::viewer {

namespace {

Colour scaled(Colour c, float factor) {
  auto f = [factor](std::uint8_t v) { return std::uint8_t(float(v) * factor + 0.5f); };
  return {f(c.r), f(c.g), f(c.b), c.a};
}

}  // namespace

Colour materialColour(Material material) {
  switch (material) {
    case Material::Solid: return {255, 255, 255};
    case Material::Ice: return {173, 216, 230};
    case Material::Wood: return {139, 90, 43};
    case Material::Metal: return {150, 150, 150};
    case Material::Rubber: return {255, 140, 0};
  }
  return {255, 0, 255};
}

Colour bodyFill(Material material, bool isStatic, bool asleep) {
  const Colour base = materialColour(material);
  if (isStatic) {
    // Static bodies read as scenery: darker, pulled towards slate blue.
    const Colour dark = scaled(base, 0.35f);
    return {std::uint8_t(dark.r + 30), std::uint8_t(dark.g + 36), std::uint8_t(dark.b + 52)};
  }
  return asleep ? scaled(base, 0.72f) : base;
}

Colour bodyOutline(Material material, bool isStatic, bool asleep) {
  if (isStatic) return scaled(materialColour(material), 0.7f);
  const Colour fill = bodyFill(material, isStatic, asleep);
  // Light fills get a dark edge, dark fills a light one.
  const int brightness = fill.r + fill.g + fill.b;
  return brightness > 450 ? scaled(fill, 0.45f) : Colour{235, 235, 235};
}

}  // namespace impulse::viewer
