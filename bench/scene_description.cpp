#include "scene_description.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bench {

ShapeDesc ShapeDesc::circle(double radius) {
  ShapeDesc shape;
  shape.kind = ShapeKind::Circle;
  shape.radius = radius;
  return shape;
}

ShapeDesc ShapeDesc::box(double halfWidth, double halfHeight) {
  ShapeDesc shape;
  shape.kind = ShapeKind::Polygon;
  shape.vertices = {{-halfWidth, -halfHeight}, {halfWidth, -halfHeight}, {halfWidth, halfHeight},
                    {-halfWidth, halfHeight}};
  return shape;
}

double ShapeDesc::area() const {
  if (kind == ShapeKind::Circle) return std::numbers::pi * radius * radius;
  double twiceArea = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2d& a = vertices[i];
    const Vec2d& b = vertices[(i + 1) % vertices.size()];
    twiceArea += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twiceArea;
}

double ShapeDesc::extent() const {
  if (kind == ShapeKind::Circle) return radius;
  double extent = 0;
  for (const Vec2d& v : vertices) extent = std::max(extent, std::hypot(v.x, v.y));
  return extent;
}

bool SceneDescription::uniformCoefficients() const {
  return std::all_of(bodies.begin(), bodies.end(), [&](const BodyDesc& body) {
    return body.friction == bodies.front().friction && body.restitution == bodies.front().restitution;
  });
}

BodyDesc makeBody(ShapeDesc shape, Vec2d position, impulse::Material material, bool isStatic) {
  const impulse::MaterialProperties& properties = impulse::materialProperties(material);
  BodyDesc body;
  body.shape = std::move(shape);
  body.position = position;
  body.isStatic = isStatic;
  body.material = material;
  body.density = properties.density;
  body.friction = properties.staticFriction;
  body.restitution = properties.restitution;
  return body;
}

BodyDesc makeStaticBox(Vec2d lower, Vec2d upper, impulse::Material material) {
  Vec2d centre{0.5 * (lower.x + upper.x), 0.5 * (lower.y + upper.y)};
  return makeBody(ShapeDesc::box(0.5 * (upper.x - lower.x), 0.5 * (upper.y - lower.y)), centre, material,
                  true);
}

int addBody(SceneDescription& scene, const BodyDesc& body) {
  scene.bodies.push_back(body);
  return static_cast<int>(scene.bodies.size()) - 1;
}

JointDesc makePin(int bodyA, int bodyB, Vec2d pin) {
  return {JointKind::Pin, bodyA, bodyB, pin, pin, 0, 0, 0};
}

JointDesc makeRod(int bodyA, int bodyB, Vec2d anchorA, Vec2d anchorB) {
  return {JointKind::Rod, bodyA, bodyB, anchorA, anchorB, 0, 0, 0};
}

JointDesc makeSpring(int bodyA, int bodyB, Vec2d anchorA, Vec2d anchorB, double restLength,
                     double stiffness, double damping) {
  return {JointKind::Spring, bodyA, bodyB, anchorA, anchorB, restLength, stiffness, damping};
}

void addJoint(SceneDescription& scene, const JointDesc& joint) { scene.joints.push_back(joint); }

}  // namespace bench
