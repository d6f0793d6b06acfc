// Chipmunk 7 (double precision). Stated settings: collision slop 5 mm (as
// Impulse's and Box2D's linear slop; Chipmunk's default is 0.1), the default
// collision bias (pow(0.9, 60): 10% of the overlap pushed out per 1/60 s), the
// default bounding-box tree, and when the scene allows sleep: a
// 0.5 s sleep time at 0.05 m/s idle speed (Impulse's values). Chipmunk has no
// continuous collision and no restitution threshold: it bounces at any
// approach speed, where Impulse and Box2D do not below 1 m/s.

#include <chipmunk/chipmunk.h>

#include <cmath>

#include "engine_adapter.h"

namespace bench {

namespace {

// Chipmunk multiplies the two shapes' coefficients. With one coefficient c in
// the whole scene, sqrt(c) per shape gives c; otherwise a pre-solve callback
// sets each arbiter to the mean of the shapes' own values.
cpBool meanMixing(cpArbiter* arbiter, cpSpace*, cpDataPointer) {
  cpShape* a = nullptr;
  cpShape* b = nullptr;
  cpArbiterGetShapes(arbiter, &a, &b);
  cpArbiterSetFriction(arbiter, 0.5 * (cpShapeGetFriction(a) + cpShapeGetFriction(b)));
  cpArbiterSetRestitution(arbiter, 0.5 * (cpShapeGetElasticity(a) + cpShapeGetElasticity(b)));
  return cpTrue;
}

class ChipmunkAdapter final : public EngineAdapter {
 public:
  ChipmunkAdapter(const SceneDescription& scene, int iterations) : space_(cpSpaceNew()) {
    cpSpaceSetGravity(space_, cpv(scene.gravity.x, scene.gravity.y));
    cpSpaceSetIterations(space_, iterations);
    cpSpaceSetCollisionSlop(space_, 0.005);
    if (scene.allowSleep) {
      cpSpaceSetSleepTimeThreshold(space_, 0.5);
      cpSpaceSetIdleSpeedThreshold(space_, 0.05);
    }
    const bool uniform = scene.uniformCoefficients();
    if (!uniform) cpSpaceAddDefaultCollisionHandler(space_)->preSolveFunc = meanMixing;
    bodies_.reserve(scene.bodies.size());
    for (const BodyDesc& body : scene.bodies) create(body, uniform);
  }

  ~ChipmunkAdapter() override {
    for (cpShape* shape : shapes_) {
      cpSpaceRemoveShape(space_, shape);
      cpShapeFree(shape);
    }
    for (cpBody* body : bodies_) {
      cpSpaceRemoveBody(space_, body);
      cpBodyFree(body);
    }
    cpSpaceFree(space_);
  }
  ChipmunkAdapter(const ChipmunkAdapter&) = delete;
  ChipmunkAdapter& operator=(const ChipmunkAdapter&) = delete;

  void step(double dt) override { cpSpaceStep(space_, dt); }

  Pose pose(int index) const override {
    cpBody* body = bodies_[static_cast<std::size_t>(index)];
    cpVect p = cpBodyGetPosition(body);
    cpVect v = cpBodyGetVelocity(body);
    return {{p.x, p.y}, cpBodyGetAngle(body), {v.x, v.y}, cpBodyGetAngularVelocity(body),
            !cpBodyIsSleeping(body)};
  }

 private:
  void create(const BodyDesc& desc, bool uniform) {
    std::vector<cpVect> vertices;
    for (const Vec2d& v : desc.shape.vertices) vertices.push_back(cpv(v.x, v.y));
    const bool isCircle = desc.shape.kind == ShapeKind::Circle;
    cpBody* body = nullptr;
    if (desc.isStatic) {
      body = cpBodyNewStatic();
    } else {
      double mass = desc.density * desc.shape.area();
      double moment = isCircle ? cpMomentForCircle(mass, 0, desc.shape.radius, cpvzero)
                               : cpMomentForPoly(mass, static_cast<int>(vertices.size()), vertices.data(),
                                                 cpvzero, 0);
      body = cpBodyNew(mass, moment);
    }
    cpSpaceAddBody(space_, body);
    cpBodySetPosition(body, cpv(desc.position.x, desc.position.y));
    cpBodySetAngle(body, desc.angle);
    if (!desc.isStatic) {
      cpBodySetVelocity(body, cpv(desc.velocity.x, desc.velocity.y));
      cpBodySetAngularVelocity(body, desc.angularVelocity);
    }
    cpShape* shape = isCircle ? cpCircleShapeNew(body, desc.shape.radius, cpvzero)
                              : cpPolyShapeNewRaw(body, static_cast<int>(vertices.size()), vertices.data(), 0);
    cpShapeSetFriction(shape, uniform ? std::sqrt(desc.friction) : desc.friction);
    cpShapeSetElasticity(shape, uniform ? std::sqrt(desc.restitution) : desc.restitution);
    cpSpaceAddShape(space_, shape);
    bodies_.push_back(body);
    shapes_.push_back(shape);
  }

  cpSpace* space_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
};

}  // namespace

std::unique_ptr<EngineAdapter> makeChipmunkAdapter(const SceneDescription& scene, int iterations) {
  return std::make_unique<ChipmunkAdapter>(scene, iterations);
}

}  // namespace bench
