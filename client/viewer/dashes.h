#pragma once
/// Dashed lines on screen (the outlines of sensors): ImGui draws only solid
/// lines, so a dashed one is drawn as its dashes.

#include <span>
#include <vector>

#include "view_transform.h"

namespace impulse::viewer {

/// The dashes along `path` (and back to its first point when `closed`):
/// `dash` pixels drawn, `gap` skipped, the pattern carried on round the
/// corners, so a dash across a corner comes out as two pieces. Replaces
/// `out` with the pieces, each as two points (from, to).
void dashesAlong(std::span<const PixelPoint> path, bool closed, float dash, float gap,
                 std::vector<PixelPoint>& out);

}  // namespace impulse::viewer
