#include "scene_description.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bench {

ShapeDesc ShapeDesc::circle(double radius, Vec2d center) {
  ShapeDesc shape;
  shape.kind = ShapeKind::Circle;
  shape.radius = radius;
  shape.center = center;
  return shape;
}

ShapeDesc ShapeDesc::box(double halfWidth, double halfHeight, Vec2d center) {
  const double left = center.x - halfWidth, right = center.x + halfWidth;
  const double bottom = center.y - halfHeight, top = center.y + halfHeight;
  return polygon({{left, bottom}, {right, bottom}, {right, top}, {left, top}});
}

ShapeDesc ShapeDesc::polygon(std::vector<Vec2d> vertices, double rounding) {
  ShapeDesc shape;
  shape.kind = ShapeKind::Polygon;
  shape.vertices = std::move(vertices);
  shape.radius = rounding;
  return shape;
}

ShapeDesc ShapeDesc::capsule(Vec2d center1, Vec2d center2, double radius) {
  ShapeDesc shape;
  shape.kind = ShapeKind::Capsule;
  shape.vertices = {center1, center2};
  shape.radius = radius;
  return shape;
}

ShapeDesc ShapeDesc::segment(Vec2d point1, Vec2d point2) {
  ShapeDesc shape;
  shape.kind = ShapeKind::Segment;
  shape.vertices = {point1, point2};
  return shape;
}

ShapeDesc ShapeDesc::chain(std::vector<Vec2d> points, bool loop) {
  ShapeDesc shape;
  shape.kind = ShapeKind::Chain;
  shape.vertices = std::move(points);
  shape.loop = loop;
  return shape;
}

double ShapeDesc::area() const {
  switch (kind) {
    case ShapeKind::Circle: return std::numbers::pi * radius * radius;
    case ShapeKind::Capsule:
      return std::numbers::pi * radius * radius +
             2 * radius * std::hypot(vertices[1].x - vertices[0].x, vertices[1].y - vertices[0].y);
    case ShapeKind::Polygon: break;
    case ShapeKind::Segment:
    case ShapeKind::Chain: return 0;
  }
  double twiceArea = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2d& a = vertices[i];
    const Vec2d& b = vertices[(i + 1) % vertices.size()];
    twiceArea += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twiceArea;
}

double ShapeDesc::extent() const {
  if (kind == ShapeKind::Circle) return std::hypot(center.x, center.y) + radius;
  double extent = 0;
  for (const Vec2d& v : vertices) extent = std::max(extent, std::hypot(v.x, v.y));
  return extent + radius;
}

bool SceneDescription::uniformCoefficients() const {
  auto ownFriction = [](const ShapeDesc& shape) { return shape.friction.has_value(); };
  return std::all_of(bodies.begin(), bodies.end(), [&](const BodyDesc& body) {
    return body.friction == bodies.front().friction && body.restitution == bodies.front().restitution &&
           !ownFriction(body.shape) && std::none_of(body.extraShapes.begin(), body.extraShapes.end(), ownFriction);
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
