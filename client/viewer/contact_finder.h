#pragma once
/// Contact points and normals of the world as the viewer shows it. Snapshots
/// carry no contacts, so the debug overlay runs the engine's own narrow
/// phase (common/'s pure collide functions) on the displayed bodies: the
/// points are those of the drawn state, not the solver's.

#include <span>
#include <vector>

#include "impulse/math.h"
#include "interpolated_world.h"

namespace impulse::viewer {

struct ShownContact {
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();  ///< unit, from the first body to the second
};

/// Touching or overlapping points (within `tolerance` metres of touching) of
/// every pair with at least one moving body. A sort-and-sweep on x keeps
/// this near linear for scenes that are not one heap.
void findContacts(std::span<const DrawnBody> bodies, std::vector<ShownContact>& out,
                  Real tolerance = Real(0.01));

}  // namespace impulse::viewer
