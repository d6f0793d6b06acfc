#pragma once
/// The chain tool's geometry: the points a person clicks become the points
/// of a SpawnChain. Every clicked segment is part of the chain (an open
/// chain's first and last wire points only guide its ends, so short guides
/// are added beyond the clicked ends), and the chain is turned so its
/// colliding side is the one a person means: an open chain is solid from
/// above, a closed one from outside.

#include <span>
#include <vector>

#include "impulse/math.h"
#include "impulse/shape.h"

namespace impulse::viewer {

/// How far the guide points lie beyond an open chain's clicked ends, m.
inline constexpr Real kChainGuideLength = Real(0.05);

/// The wire points of an open chain through `clicked` (2 or more): solid
/// from above (a chain collides on the right of the way its points run, so
/// the points run right to left), with a guide point beyond each end.
std::vector<Vec2> openChainPoints(std::span<const Vec2> clicked);

/// The wire points of a loop through `clicked`, anticlockwise: solid from
/// outside.
std::vector<Vec2> closedChainPoints(std::span<const Vec2> clicked);

/// For interactive drawing: ShapeError::None while the points clicked so far
/// still make an open chain the engine accepts (no crossing or folding back,
/// neighbours at least 5 mm apart); the engine's own check (buildChain)
/// decides, so the refusal carries its message.
ShapeError checkChainInProgress(std::span<const Vec2> clicked);

}  // namespace impulse::viewer
