#pragma once
/// Tolerances shared by collision and solver, in metres and seconds.

#include "impulse/math.h"

namespace impulse {

/// Penetration the solver tolerates before pushing apart; keeps resting
/// contacts persistent instead of flickering between touching and not.
inline constexpr Real kLinearSlop = Real(0.005);
/// Contacts are generated this far before shapes touch, so the solver can stop
/// an approaching body exactly at the surface (speculative contact).
inline constexpr Real kSpeculativeDistance = 4 * kLinearSlop;
/// Largest fat AABB margin: a moving proxy is re-inserted in the tree only
/// after it leaves its enlarged box. A small shape's margin is smaller
/// (BroadPhase::fatBox), so a crowd of them does not pair every body with
/// its neighbours' neighbours.
inline constexpr Real kAabbMargin = Real(0.1);
/// Polygon vertex limits of docs/product.md.
inline constexpr int kMinPolygonVertices = 3;
inline constexpr int kMaxPolygonVertices = 16;

}  // namespace impulse
