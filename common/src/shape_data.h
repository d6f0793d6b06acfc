#pragma once
// A shape as the step sees it (the public face is ShapeDef, ShapeId and
// World's shape functions). Shapes live in one slot array; each body threads
// its shapes through `nextInBody`, in the order they were added.

#include <cstdint>

#include "edge_list.h"
#include "impulse/body.h"
#include "impulse/material.h"
#include "impulse/shape.h"
#include "shape_pair.h"

namespace impulse {

struct ShapeSlot {
  /// Geometry in the body's frame (origin at its centre of mass).
  Shape shape;
  /// The material's coefficients with any override applied.
  MaterialProperties coefficients{};
  /// Rolling resistance acts on round shapes only: their radius, else 0.
  Real rollingRadius = 0;
  ShapeInteraction interaction;
  std::int32_t body = kNullIndex;
  std::int32_t nextInBody = kNullIndex;
  std::int32_t proxyKey = kNullIndex;
  std::uint32_t generation = 0;
  Material material = Material::Solid;
  bool alive = false;

  ShapeType type() const { return shape.type(); }
  ShapeRef ref() const { return refOf(shape); }
};

}  // namespace impulse
