#pragma once
/// What the viewer can tell about a body from its descriptor alone: mass
/// properties from the shape and the material's density (per-body density
/// overrides are not on the wire, so such bodies count with their
/// material's), the world's kinetic energy, and a shape's size in words.

#include <span>
#include <string>

#include "impulse/shape.h"
#include "interpolated_world.h"

namespace impulse::viewer {

/// Area, mass and inertia of a body as its look describes it (zero mass for
/// static bodies).
MassProperties massOf(const BodyLook& look);

/// Translational plus rotational kinetic energy of the dynamic bodies, J.
double kineticEnergy(std::span<const DrawnBody> bodies);

/// "circle, radius 0.5 m" or "polygon, 4 vertices, 2 x 1 m".
std::string describeShape(const Shape& shape);

}  // namespace impulse::viewer
