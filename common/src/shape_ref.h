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

/// The geometry as `Geometry`, which must be the struct its type names.
template <class Geometry>
const Geometry& geometryAs(ShapeRef shape) {
  return *static_cast<const Geometry*>(shape.geometry);
}

/// Calls visit with the geometry as the struct its type names.
template <class Visit>
decltype(auto) visitGeometry(ShapeRef shape, Visit&& visit) {
  switch (shape.type) {
    case ShapeType::Circle: return visit(geometryAs<Circle>(shape));
    case ShapeType::Capsule: return visit(geometryAs<Capsule>(shape));
    case ShapeType::Segment: return visit(geometryAs<Segment>(shape));
    case ShapeType::Polygon: return visit(geometryAs<Polygon>(shape));
    case ShapeType::ChainSegment: break;
  }
  return visit(geometryAs<ChainSegment>(shape));
}

// The functions of impulse/shape.h of the same names, on a ShapeRef.
MassProperties computeMassProperties(ShapeRef shape, Real density);
AABB computeAABB(ShapeRef shape, const Transform& transform);
Real computeExtent(ShapeRef shape);
Real computeInnerRadius(ShapeRef shape);
bool containsPoint(ShapeRef shape, const Transform& transform, const Vec2& point);

}  // namespace impulse
