#pragma once
// One shape's geometry wherever it is stored: a Shape's alternative (a
// definition) or a world's pool of its type (shape_data.h). The functions
// of impulse/shape.h that the step needs read it through a ShapeRef, so the
// world never builds a Shape to ask a shape's box, size or mass.

#include <optional>

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

/// A definition holding a copy of the geometry.
Shape shapeOf(ShapeRef shape);

/// Calls visit with the geometry as the struct its type names.
template <class Visit>
decltype(auto) visitGeometry(ShapeRef shape, Visit&& visit) {
  switch (shape.type) {
    case ShapeType::Circle: return visit(*static_cast<const Circle*>(shape.geometry));
    case ShapeType::Capsule: return visit(*static_cast<const Capsule*>(shape.geometry));
    case ShapeType::Segment: return visit(*static_cast<const Segment*>(shape.geometry));
    case ShapeType::Polygon: return visit(*static_cast<const Polygon*>(shape.geometry));
    case ShapeType::ChainSegment: break;
  }
  return visit(*static_cast<const ChainSegment*>(shape.geometry));
}

// The functions of impulse/shape.h of the same names, on a ShapeRef.
MassProperties computeMassProperties(ShapeRef shape, Real density);
AABB computeAABB(ShapeRef shape, const Transform& transform);
Real computeExtent(ShapeRef shape);
Real computeInnerRadius(ShapeRef shape);
bool containsPoint(ShapeRef shape, const Transform& transform, const Vec2& point);

}  // namespace impulse
