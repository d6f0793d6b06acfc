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

/// Gives the shape a new filter, sensor flag and events: its contacts and
/// the sensor list follow, its proxy looks for the pairs now allowed, and
/// its body wakes.
void changeShapeInteraction(WorldData& world, std::int32_t shape, const ShapeInteraction& interaction);

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
