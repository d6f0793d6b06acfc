#pragma once
/// The scenes of docs/product.md (presets 0-10) and the joint scenes (11-14), built
/// into a world. Server, tests and benchmark share them.

#include <functional>
#include <string>
#include <vector>

#include "impulse/material.h"
#include "impulse/math.h"
#include "impulse/world.h"

namespace impulse {

/// A yellow guide circle drawn by viewers (tutorial presets).
struct Marker {
  Vec2 center = Vec2::Zero();
  Real radius = 0;
};

struct PresetInfo {
  int id = 0;
  std::string title;
  std::vector<std::string> explanation;
  std::vector<Marker> markers;
  /// Whether users may draw shapes in this scene (sandbox and tutorials).
  bool drawingAllowed = false;
  /// The scene's script, for scenes with moving parts (a kinematic
  /// elevator): run before every step with the simulated time at the step's
  /// start and the step's length. Unset for most scenes; a world replaced by
  /// a clear or a scene load drops it.
  std::function<void(World& world, double time, Real dt)> drive;
};

/// 0-10 are docs/product.md's; 11-14 show joints (spring, pendulum and
/// cradle, chain bridge, car); 15-17 fields (orbits, floating, fans); 18-21
/// shapes (a car on chain terrain, a kinematic elevator, a tumbler, capsule
/// ragdolls on stairs).
inline constexpr int kPresetCount = 22;
/// Width and height of the scene in metres (the seed's 800x600 px at 32 px/m).
inline const Vec2 kSceneSize = Vec2(25, Real(18.75));
/// The rectangle every preset is drawn in, around the world's origin.
inline const AABB kPresetScene{Vec2::Zero(), kSceneSize};

/// Where a preset loaded into a room with these bounds lies (the server's
/// rule, and the viewer's frame for it): the preset scene where it was
/// drawn when the bounds hold it, else that scene centred on the bounds.
AABB presetLanding(const AABB& roomBounds);

/// Clears the world, resets gravity and builds preset `id` (0..21).
/// `selected` is the viewer's current material (preset 9 uses it).
/// Returns nothing for an id out of range, leaving the world untouched.
std::optional<PresetInfo> loadPreset(World& world, int id, Material selected = Material::Solid);

}  // namespace impulse
