#pragma once
/// Colours of the viewer: docs/product.md's material colours and how static and
/// sleeping bodies are shown. Tests use the same functions to find bodies in
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

/// docs/product.md: SOLID white, ICE light blue, WOOD brown, METAL grey, RUBBER orange;
/// issue 15: STONE dark taupe, GLASS pale aqua, FOAM cream.
Colour materialColour(Material material);

/// Fill of a body: its material colour, whether awake or asleep (sleep shows
/// in the outline, so a sleeping body never looks like another material);
/// static bodies darker and cooler, as scenery.
Colour bodyFill(Material material, bool isStatic);
/// Outline of a body: the sleep colour when asleep, else a contrast edge
/// (dark on light fills, light on dark ones).
Colour bodyOutline(Material material, bool isStatic, bool asleep);

/// How a body's shapes are filled and edged.
struct SurfaceLook {
  Colour fill;
  Colour outline;
  /// A thin dashed outline instead of a solid one.
  bool dashed = false;
  friend bool operator==(const SurfaceLook&, const SurfaceLook&) = default;
};
/// Solid bodies: bodyFill and bodyOutline. Sensors (triggers: they report
/// what passes through them and never collide) are see-through: their
/// material's colour, static or not, at kSensorFillAlpha, edged by a thin
/// dashed line, so nobody mistakes one for a wall or a platform.
SurfaceLook surfaceLook(Material material, bool isStatic, bool asleep, bool isSensor);
inline constexpr std::uint8_t kSensorFillAlpha = 56;
inline constexpr std::uint8_t kSensorOutlineAlpha = 210;

namespace palette {
inline constexpr Colour kBackground{22, 24, 30};
inline constexpr Colour kSceneBackground{30, 33, 41};
inline constexpr Colour kPanelBackground{16, 18, 24};
inline constexpr Colour kMarker{255, 221, 0};
inline constexpr Colour kText{230, 232, 238};
inline constexpr Colour kDimText{160, 166, 180};
inline constexpr Colour kValid{60, 220, 90};
inline constexpr Colour kInvalid{235, 60, 60};
inline constexpr Colour kPreview{120, 200, 255};
inline constexpr Colour kSelection{255, 221, 0};
/// Joints: light steel, readable over every material's fill.
inline constexpr Colour kJoint{205, 215, 230};
// Fields: translucent so the bodies inside stay readable.
inline constexpr Colour kLiquid{40, 110, 210, 90};
inline constexpr Colour kLiquidEdge{110, 180, 255, 200};
inline constexpr Colour kAir{200, 230, 255, 28};
inline constexpr Colour kAirEdge{200, 230, 255, 110};
inline constexpr Colour kGravitation{255, 200, 90};
inline constexpr Colour kGravity{255, 120, 200};
inline constexpr Colour kWarning{255, 180, 60};
/// Outline of sleeping bodies: a violet no material uses.
inline constexpr Colour kSleep{176, 112, 255};
// Debug overlays.
inline constexpr Colour kContact{255, 64, 64};
inline constexpr Colour kNormal{255, 160, 64};
inline constexpr Colour kBounds{80, 220, 120};
inline constexpr Colour kVelocity{80, 200, 255};
// The ray tool, and the flashes of the event stream.
inline constexpr Colour kRay{120, 255, 200};
inline constexpr Colour kRayHit{255, 80, 200};
inline constexpr Colour kHitFlash{255, 240, 150};
inline constexpr Colour kSensorFlash{120, 255, 160};
inline constexpr Colour kContactFlash{255, 255, 255};
}  // namespace palette

}  // namespace impulse::viewer
