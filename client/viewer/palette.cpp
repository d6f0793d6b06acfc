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
    case Material::Solid: return {245, 245, 245};
    case Material::Ice: return {140, 205, 250};
    case Material::Wood: return {166, 108, 56};
    case Material::Metal: return {128, 132, 140};
    case Material::Rubber: return {255, 140, 0};
    case Material::Stone: return {112, 98, 86};
    case Material::Glass: return {150, 250, 200};
    case Material::Foam: return {255, 236, 160};
  }
  return {255, 0, 255};
}

Colour bodyFill(Material material, bool isStatic) {
  const Colour base = materialColour(material);
  if (!isStatic) return base;
  // Static bodies read as scenery: dark, pulled towards slate blue, well
  // apart from METAL's grey.
  const Colour dark = scaled(base, 0.2f);
  return {std::uint8_t(dark.r + 22), std::uint8_t(dark.g + 30), std::uint8_t(dark.b + 48)};
}

Colour bodyOutline(Material material, bool isStatic, bool asleep) {
  if (asleep && !isStatic) return palette::kSleep;
  const Colour fill = bodyFill(material, isStatic);
  if (isStatic) return scaled(materialColour(material), 0.55f);
  const int brightness = fill.r + fill.g + fill.b;
  return brightness > 400 ? scaled(fill, 0.3f) : Colour{240, 240, 240};
}

SurfaceLook surfaceLook(Material material, bool isStatic, bool asleep, bool isSensor) {
  if (!isSensor) return {bodyFill(material, isStatic), bodyOutline(material, isStatic, asleep), false};
  Colour fill = materialColour(material);
  Colour outline = fill;
  fill.a = kSensorFillAlpha;
  outline.a = kSensorOutlineAlpha;
  return {fill, outline, true};
}

}  // namespace impulse::viewer
