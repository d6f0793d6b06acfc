// Box2D v3 (C, built from a source tree given to CMake; see
// box2d_v3.cmake). This file is compiled once per v3 build (SSE2, AVX2), each
// time into the namespace BOX2D_V3_NAMESPACE, and v3's symbols are renamed
// apart per build, so no translation unit sees Box2D 2.4.1's headers and the
// two v3 builds link into one binary.
//
// Settings: sub-steps as given (v3's default is 4); everything else at
// b2DefaultWorldDef's values: contact hertz 30, damping ratio 10, push-out
// speed 3 m/s, restitution threshold 1 m/s (as Impulse's), continuous
// collision on (dynamic against static), speed capped at 400 m/s, sleep
// threshold 0.05 m/s for 0.5 s (as Impulse's). v3 polygons have no skin
// (radius 0), so the described shape collides as it is.

#include <box2d/box2d.h>

#include <stdexcept>

#include "engine_adapter.h"

#ifndef BOX2D_V3_NAMESPACE
#error "BOX2D_V3_NAMESPACE names the v3 build this adapter is compiled for"
#endif

namespace bench::BOX2D_V3_NAMESPACE {

namespace {

// v3 mixes friction as sqrt(a*b) and restitution as max(a, b); scenes with
// mixed coefficients get the mean, as in every engine here.
float meanOf(float a, uint64_t, float b, uint64_t) { return 0.5f * (a + b); }

b2Vec2 toVec(const Vec2d& v) { return b2Vec2{float(v.x), float(v.y)}; }

b2Polygon toPolygon(const std::vector<Vec2d>& vertices) {
  if (vertices.size() > B2_MAX_POLYGON_VERTICES) throw std::runtime_error("box2d v3: too many vertices");
  b2Vec2 points[B2_MAX_POLYGON_VERTICES];
  for (std::size_t i = 0; i < vertices.size(); ++i) points[i] = toVec(vertices[i]);
  b2Hull hull = b2ComputeHull(points, static_cast<int>(vertices.size()));
  if (hull.count == 0) throw std::runtime_error("box2d v3: polygon is not a convex hull");
  return b2MakePolygon(&hull, 0.0f);
}

class Box2DV3Adapter final : public EngineAdapter {
 public:
  Box2DV3Adapter(const SceneDescription& scene, int subSteps) : subSteps_(subSteps) {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = toVec(scene.gravity);
    def.enableSleep = scene.allowSleep;
    if (!scene.uniformCoefficients()) {
      def.frictionCallback = meanOf;
      def.restitutionCallback = meanOf;
    }
    world_ = b2CreateWorld(&def);
    bodies_.reserve(scene.bodies.size());
    for (const BodyDesc& body : scene.bodies) bodies_.push_back(create(body));
  }
  ~Box2DV3Adapter() override { b2DestroyWorld(world_); }
  Box2DV3Adapter(const Box2DV3Adapter&) = delete;
  Box2DV3Adapter& operator=(const Box2DV3Adapter&) = delete;

  void step(double dt) override { b2World_Step(world_, float(dt), subSteps_); }

  Pose pose(int index) const override {
    b2BodyId body = bodies_[static_cast<std::size_t>(index)];
    b2Vec2 p = b2Body_GetPosition(body);
    b2Vec2 v = b2Body_GetLinearVelocity(body);
    return {{p.x, p.y},
            b2Rot_GetAngle(b2Body_GetRotation(body)),
            {v.x, v.y},
            b2Body_GetAngularVelocity(body),
            b2Body_IsAwake(body)};
  }

 private:
  b2BodyId create(const BodyDesc& desc) {
    b2BodyDef def = b2DefaultBodyDef();
    def.type = desc.isStatic ? b2_staticBody : b2_dynamicBody;
    def.position = toVec(desc.position);
    def.rotation = b2MakeRot(float(desc.angle));
    def.linearVelocity = toVec(desc.velocity);
    def.angularVelocity = float(desc.angularVelocity);
    b2BodyId body = b2CreateBody(world_, &def);

    b2ShapeDef shape = b2DefaultShapeDef();
    shape.density = float(desc.density);
    shape.material.friction = float(desc.friction);
    shape.material.restitution = float(desc.restitution);
    if (desc.shape.kind == ShapeKind::Circle) {
      b2Circle circle{{0.0f, 0.0f}, float(desc.shape.radius)};
      b2CreateCircleShape(body, &shape, &circle);
    } else {
      b2Polygon polygon = toPolygon(desc.shape.vertices);
      b2CreatePolygonShape(body, &shape, &polygon);
    }
    return body;
  }

  b2WorldId world_{};
  int subSteps_;
  std::vector<b2BodyId> bodies_;
};

}  // namespace

std::unique_ptr<EngineAdapter> makeAdapter(const SceneDescription& scene, int subSteps) {
  return std::make_unique<Box2DV3Adapter>(scene, subSteps);
}

}  // namespace bench::BOX2D_V3_NAMESPACE
