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

/// True when world `point` is inside one of the body's solid shapes placed
/// at `xf`, or within `lineReach` (m) of one of its segments or chain
/// segments, which have no inside to click.
bool bodyTouches(const BodyLook& look, const Transform& xf, const Vec2& point, Real lineReach);

/// Translational plus rotational kinetic energy of the dynamic bodies, J.
double kineticEnergy(std::span<const DrawnBody> bodies);

/// "circle, radius 0.5 m" or "polygon, 4 vertices, 2 x 1 m".
std::string describeShape(const Shape& shape);

/// A body's shapes in a few words: "chain of 49 segments, 24.5 m" for a
/// chain, "3 shapes: 2 polygons, 1 circle" for a compound body, the shape
/// itself (describeShape) for one.
std::string describeShapes(std::span<const Shape> shapes);

}  // namespace impulse::viewer
