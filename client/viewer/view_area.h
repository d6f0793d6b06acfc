#pragma once
/// The viewer's area of interest (--area-margin, docs/networked-play.md):
/// what the view shows grown by a margin, sent again only once the view
/// has moved far enough that the area sent no longer serves it.

#include "impulse/math.h"
#include "view_transform.h"

namespace impulse::viewer {

/// The world rectangle the scene viewport shows, grown by `margin` metres
/// on every side (mirror frame).
AABB viewArea(const ViewTransform& view, float margin);

/// True when an edge of `wanted` lies more than `slack` metres from the
/// same edge of `sent`: a pan or zoom past it asks for a new area.
bool areaMoved(const AABB& sent, const AABB& wanted, float slack);

}  // namespace impulse::viewer
