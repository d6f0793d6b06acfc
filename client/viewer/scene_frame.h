#pragma once
/// Where a room opens in the viewer (docs/viewer.md, "Where a room opens"):
/// the world rectangle its view is fitted to, in the mirror's frame
/// (metres from the room's origin).

#include <span>

#include "impulse/math.h"

namespace impulse::viewer {

/// Rooms with no side longer than this open on their bounds: a 1 m body is
/// still about 3 px across in a 720 px tall window.
inline constexpr Real kLargestFramedRoom = 250;
/// The bodies' area is grown by this on every side, so none sits on an edge.
inline constexpr Real kBodiesAreaMargin = 5;

/// True when `roomBounds` are too large to open on, so the room opens on
/// its bodies and the frame waits for the first snapshot.
bool opensOnBodies(const AABB& roomBounds);

/// The frame a room with `roomBounds` opens on:
/// - the preset scene, when the bounds hold it (every preset is built there);
/// - else the bounds, when no side is longer than kLargestFramedRoom;
/// - else the area of `bodies` (their centres) grown by kBodiesAreaMargin and
///   to at least the preset scene's size; with no bodies, that size at the
///   bounds' centre.
AABB openingFrame(const AABB& roomBounds, std::span<const Vec2> bodies);

}  // namespace impulse::viewer
