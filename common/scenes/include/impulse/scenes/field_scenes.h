#pragma once
/// The field presets' numbers (15 orbits, 16 floating, 17 fans), shared by
/// the scenes and the tests of their outcomes.

#include "impulse/math.h"

namespace impulse {

inline constexpr Real kSunRadius = Real(1.5);  ///< METAL, static
inline constexpr double kOrbitConstant = 0.001178;  ///< G: the inner planet's period is about 8 s
inline constexpr Real kPlanetRadius = Real(0.15);  ///< ICE: 0.05 % of the sun's mass
inline constexpr Real kPlanetOrbits[3] = {3, 5, Real(7.5)};
inline constexpr Real kWaterLevel = 8;
inline constexpr Real kWaterDensity = 1000;
inline constexpr Real kFanPositions[2] = {7, 18};
inline constexpr Real kFanSpeed = 45;
inline constexpr Real kFanRange = 14;
inline constexpr Real kFanSpread = Real(0.35);  ///< half-angle of each cone, rad
inline constexpr Real kLightBallRadius = Real(0.15);

}  // namespace impulse
