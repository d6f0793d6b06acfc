#pragma once
/// The standard shapes the viewer spawns at the cursor (triangle, square,
/// pentagon, hexagon): regular polygons standing on a flat side.

#include <string_view>
#include <vector>

#include "impulse/math.h"

namespace impulse::viewer {

inline constexpr int kFewestStandardSides = 3;
inline constexpr int kMostStandardSides = 6;

/// Circumradius range of the standard shapes, m, and each size key's factor.
inline constexpr Real kMinShapeSize = Real(0.1);
inline constexpr Real kMaxShapeSize = 4;
inline constexpr Real kDefaultShapeSize = Real(0.5);
inline constexpr Real kShapeSizeFactor = Real(1.25);

/// Radius range of drawn capsules, m (the same keys change it in capsule mode).
inline constexpr Real kMinCapsuleRadius = Real(0.05);
inline constexpr Real kMaxCapsuleRadius = 2;
inline constexpr Real kDefaultCapsuleRadius = Real(0.25);

/// The `sides` vertices (anticlockwise) of the regular polygon with this
/// circumradius centred on `centre`, its bottom side horizontal.
std::vector<Vec2> regularPolygon(int sides, const Vec2& centre, Real circumradius);

/// "triangle", "square", "pentagon", "hexagon".
std::string_view standardShapeName(int sides);

}  // namespace impulse::viewer
