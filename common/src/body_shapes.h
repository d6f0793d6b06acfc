#pragma once
// A body's shapes (body_shapes.cpp): checked, attached, detached, and the
// body's mass and sizes recomputed from their union.

#include <cstdint>
#include <string>

#include "world_data.h"

namespace impulse {

/// Only round shapes roll (a polygon's resistance to tipping is geometric):
/// their radius, else 0.
Real rollingRadiusOf(const Shape& shape);

/// Empty when the shape, its material and its override are valid.
std::string checkShapeDef(const WorldData& world, const ShapeDef& def);

/// Takes a shape slot for the body and appends it to the body's shapes
/// (no proxy yet: the body's centre of mass may still move).
std::int32_t attachShape(WorldData& world, std::int32_t body, const ShapeDef& def);

/// Gives an attached shape its broad-phase proxy, where its body is now.
void createShapeProxy(WorldData& world, std::int32_t shape);

/// Unlinks the shape from its body, removes its proxy and frees its slot
/// (its contacts must be gone already).
void detachShape(WorldData& world, std::int32_t shape);

/// Empty when the body's shapes suit a body of `type`: a dynamic body needs
/// a shape with area, and a moving body's shapes stay within kMaxBodyExtent
/// of its centre of mass (its extent must be up to date).
std::string checkShapesSuitType(const WorldData& world, std::int32_t body, BodyType type);

/// After a shape came or went or changed density: new mass and sizes, with
/// the velocity carried to the new centre of mass; the body wakes. Returns
/// checkShapesSuitType's verdict on the result.
std::string reshapeBody(WorldData& world, std::int32_t body);

/// Wakes the bodies whose proxies overlap the box: a static body that
/// appears or moves there is never looked for by sleeping ones (only moving
/// proxies search for pairs).
void wakeBodiesUnder(WorldData& world, const AABB& box);

/// Mass, inertia, extent and inner radius from the body's shapes. When the
/// union's centroid is off the body's origin, the shapes are moved so it is
/// the origin again and the body's position follows, leaving every shape
/// where it was in the world. Returns that shift (body frame).
Vec2 updateBodyMass(WorldData& world, std::int32_t body);

/// Mass, inertia, extent and inner radius from the body's shapes as they
/// are, for a body whose shapes are already centred (a saved one). Returns
/// the union's centroid, which is the origin to within round-off.
Vec2 setMassFromShapes(WorldData& world, std::int32_t body);

}  // namespace impulse
