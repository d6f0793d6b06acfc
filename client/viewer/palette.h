#pragma once
/// Colours of the viewer: SPEC.md's material colours and how static and
/// sleeping bodies are shaded. Tests use the same functions to find bodies in
/// screenshots.

#include <cstdint>

#include "impulse/material.h"

namespace impulse::viewer {

struct Colour {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  std::uint8_t a = 255;
  friend bool operator==(const Colour&, const Colour&) = default;
};

/// SPEC.md: SOLID white, ICE light blue, WOOD brown, METAL grey, RUBBER orange.
Colour materialColour(Material material);

/// Fill of a body: its material colour; static bodies darker and cooler;
/// sleeping bodies dimmed a little.
Colour bodyFill(Material material, bool isStatic, bool asleep);
/// Outline of a body (brighter than its fill, so shapes stay readable).
Colour bodyOutline(Material material, bool isStatic, bool asleep);

namespace palette {
inline constexpr Colour kBackground{22, 24, 30};
inline constexpr Colour kSceneBackground{30, 33, 41};
inline constexpr Colour kMarker{255, 221, 0};
inline constexpr Colour kText{230, 232, 238};
inline constexpr Colour kDimText{160, 166, 180};
inline constexpr Colour kPanel{12, 14, 20, 200};
inline constexpr Colour kValid{60, 220, 90};
inline constexpr Colour kInvalid{235, 60, 60};
inline constexpr Colour kPreview{120, 200, 255};
inline constexpr Colour kSelection{255, 221, 0};
inline constexpr Colour kGravity{255, 120, 200};
inline constexpr Colour kWarning{255, 180, 60};
}  // namespace palette

}  // namespace impulse::viewer
