#pragma once
// Narrow-phase dispatch over pairs of shape types, for the world's contacts.
// Shapes are stored by type (each at its own size), so a contact holds a
// pointer to each geometry and the function for their pair of types.

#include "impulse/manifold.h"
#include "impulse/shape.h"

namespace impulse {

/// One shape's geometry: `geometry` points at the struct its type names
/// (Circle, Capsule, Segment, Polygon or ChainSegment).
struct ShapeRef {
  ShapeType type = ShapeType::Circle;
  const void* geometry = nullptr;
};

/// The alternative held by the shape, as a ShapeRef (valid while it lives).
ShapeRef refOf(const Shape& shape);

using CollideFunction = Manifold (*)(const void* a, const Transform& xfA, const void* b,
                                     const Transform& xfB, Real speculativeDistance);

/// The table's function for the ordered pair of types, nullptr when the table
/// holds it the other way round (then swap the shapes: normals point from A
/// to B). Every unordered pair of types has exactly one order in the table,
/// which a static_assert checks when the table is built.
CollideFunction collideFunction(ShapeType a, ShapeType b);

/// False for pairs that never make contacts: two boundary shapes (segments
/// and chain segments have no inside to push out of).
bool shapesCanCollide(ShapeType a, ShapeType b);

/// Signed distance between two shapes: the gap when apart, minus the depth
/// along the axis of least penetration when they overlap. Continuous
/// collision uses it.
Real computeSeparation(ShapeRef a, const Transform& xfA, ShapeRef b, const Transform& xfB);

}  // namespace impulse
