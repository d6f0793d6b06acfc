#pragma once
// Presets 18-21 (shape_presets.cpp) and the pieces of presets.cpp they build
// on. Internal to the scenes library.

#include "impulse/scenes/presets.h"

namespace impulse {

/// Visible wall and floor thickness; the floor's top is at this height.
inline constexpr Real kSceneBorder = Real(0.78125);

void addStaticBox(World& world, Vec2 lower, Vec2 upper);
/// Floor and two side walls, centred on the canvas edges as in the seed.
void addBoundary(World& world);
/// The car of preset 14 with its chassis' left end at `left`, wheels on
/// `ground`; returns the chassis.
BodyId addCar(World& world, Real left, Real ground);

PresetInfo terrainCarPreset(World& world);
PresetInfo elevatorPreset(World& world);
PresetInfo tumblerPreset(World& world);
PresetInfo ragdollStairsPreset(World& world);

}  // namespace impulse
