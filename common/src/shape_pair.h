#pragma once
// Narrow-phase dispatch over pairs of shape types, for the world's contacts.
// A world stores shapes by type (each at its own size): a contact keeps the
// function for its pair of types and reads each geometry through a ShapeRef.

#include "impulse/manifold.h"
#include "impulse/shape.h"
#include "shape_ref.h"

namespace impulse {

using CollideFunction = Manifold (*)(const void* a, const Transform& xfA, const void* b,
                                     const Transform& xfB, Real speculativeDistance);

/// The table's function for the ordered pair of types, nullptr when the table
/// holds it the other way round (then swap the shapes: normals point from A
/// to B). Every unordered pair of types has exactly one order in the table,
/// which a static_assert checks when the table is built.
CollideFunction collideFunction(ShapeType a, ShapeType b);

/// The manifold of any two shapes, normal from a to b (impulse/manifold.h's
/// collide, on ShapeRefs).
Manifold collide(ShapeRef a, const Transform& xfA, ShapeRef b, const Transform& xfB,
                 Real speculativeDistance = kSpeculativeDistance);

/// False for pairs that never make contacts: two boundary shapes (segments
/// and chain segments have no inside to push out of).
bool shapesCanCollide(ShapeType a, ShapeType b);

/// Signed distance between two shapes: the gap when apart, minus the depth
/// along the axis of least penetration when they overlap. Continuous
/// collision uses it.
Real computeSeparation(ShapeRef a, const Transform& xfA, ShapeRef b, const Transform& xfB);

}  // namespace impulse
