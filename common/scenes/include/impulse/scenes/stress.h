#pragma once
/// Stress scenes shared by tests and the benchmark (the docs/product.md presets are in
/// presets.h).

#include <vector>

#include "impulse/body.h"
#include "impulse/world.h"

namespace impulse {

/// A pyramid of unit boxes on a static ground whose top is at y = 0.
struct Pyramid {
  std::vector<BodyId> boxes;  ///< row by row, bottom first
  BodyId top;
  Vec2 topStart = Vec2::Zero();
};

/// rows rows of 1 m boxes (rows*(rows+1)/2 boxes), touching, no overlap.
Pyramid buildPyramid(World& world, int rows, Material material = Material::Solid);

/// A column of `count` 1 m boxes on a static ground at y = 0; each box is
/// shifted sideways by `offset`, alternating left and right.
std::vector<BodyId> buildTower(World& world, int count, Real offset = 0);

/// An open box (floor and two walls) and `count` circles of `radius` in a
/// staggered grid above it, falling in.
std::vector<BodyId> buildRain(World& world, int count, Real radius = Real(0.25));

}  // namespace impulse
