#include "impulse/scenes/stress.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace impulse {

namespace {

// Stress scenes are larger than the preset canvas the default bounds fit.
void widenBounds(World& world, Real halfWidth, Real height) {
  WorldSettings settings = world.settings();
  settings.bounds = settings.bounds.unite({Vec2(-halfWidth, -halfWidth), Vec2(halfWidth, height)});
  world.setSettings(settings);
}

void addGround(World& world, Real halfWidth) {
  BodyDef ground;
  ground.shape = Shape::makePolygon(makeBox(halfWidth, 1));
  ground.position = Vec2(0, -1);
  ground.properties.isStatic = true;
  world.createBody(ground);
}

BodyId addBox(World& world, const Vec2& centre, Material material) {
  BodyDef def;
  def.shape = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  def.position = centre;
  def.material = material;
  return world.createBody(def).id;
}

}  // namespace

Pyramid buildPyramid(World& world, int rows, Material material) {
  widenBounds(world, Real(rows) + 10, Real(rows) + 10);
  addGround(world, Real(rows) + 10);
  Pyramid pyramid;
  pyramid.boxes.reserve(static_cast<std::size_t>(rows * (rows + 1) / 2));
  for (int row = 0; row < rows; ++row) {
    int count = rows - row;
    Real left = -Real(0.5) * Real(count - 1);
    for (int i = 0; i < count; ++i) {
      Vec2 centre(left + Real(i), Real(0.5) + Real(row));
      pyramid.boxes.push_back(addBox(world, centre, material));
    }
  }
  pyramid.top = pyramid.boxes.back();
  pyramid.topStart = Vec2(0, Real(rows) - Real(0.5));
  return pyramid;
}

std::vector<BodyId> buildTower(World& world, int count, Real offset) {
  widenBounds(world, 20, Real(count) + 10);
  addGround(world, 20);
  std::vector<BodyId> boxes;
  for (int i = 0; i < count; ++i) {
    Real shift = (i % 2 == 0) ? offset : -offset;
    boxes.push_back(addBox(world, Vec2(shift, Real(0.5) + Real(i)), Material::Solid));
  }
  return boxes;
}

std::vector<BodyId> buildRain(World& world, int count, Real radius) {
  // Container about square in the number of balls it must hold.
  const Real width = std::max(Real(10), std::sqrt(Real(count)) * radius * 3);
  const Real wallHeight = width;
  auto addWall = [&](Vec2 lower, Vec2 upper) {
    std::array<Vec2, 4> corners = {lower, Vec2(upper.x(), lower.y()), upper, Vec2(lower.x(), upper.y())};
    world.createPolygon(corners, {.properties = {.isStatic = true}});
  };
  widenBounds(world, width, 4 * width + Real(count) * radius);
  addWall(Vec2(-width / 2 - 1, -1), Vec2(width / 2 + 1, 0));
  addWall(Vec2(-width / 2 - 1, 0), Vec2(-width / 2, wallHeight));
  addWall(Vec2(width / 2, 0), Vec2(width / 2 + 1, wallHeight));

  std::vector<BodyId> balls;
  balls.reserve(static_cast<std::size_t>(count));
  const Real pitch = Real(2.2) * radius;
  const int perRow = std::max(1, static_cast<int>((width - 2 * radius) / pitch));
  for (int i = 0; i < count; ++i) {
    int row = i / perRow;
    int column = i % perRow;
    Real stagger = (row % 2) * Real(0.5) * pitch;
    Vec2 centre(-width / 2 + radius + stagger + pitch * Real(column), Real(2) + pitch * Real(row));
    balls.push_back(world.createCircle(centre, radius).id);
  }
  return balls;
}

}  // namespace impulse
