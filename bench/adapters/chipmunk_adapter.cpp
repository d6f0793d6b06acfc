// Chipmunk 7 (double precision). Stated settings: collision slop 5 mm (as
// Impulse's and Box2D's linear slop; Chipmunk's default is 0.1), the default
// collision bias (pow(0.9, 60): 10% of the overlap pushed out per 1/60 s), the
// default bounding-box tree, and when the scene allows sleep: a
// 0.5 s sleep time at 0.05 m/s idle speed (Impulse's values). Chipmunk has no
// continuous collision and no restitution threshold: it bounces at any
// approach speed, where Impulse and Box2D do not below 1 m/s. Joints: pins
// are cpPivotJoints, rods cpPinJoints, springs cpDampedSprings, all at
// Chipmunk's default error bias (rigid joints corrected by 10% per 1/60 s, as
// its contacts); a joint to the world joins the space's static body. Joined
// bodies do not collide: Chipmunk's joints do not stop that, so a begin
// callback rejects their contacts.

#include <chipmunk/chipmunk.h>

#include <cmath>
#include <set>
#include <utility>

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

using BodyPair = std::pair<const cpBody*, const cpBody*>;

BodyPair ordered(const cpBody* a, const cpBody* b) {
  return a < b ? BodyPair{a, b} : BodyPair{b, a};
}

// The handler's data is the set of joined pairs.
cpBool collideUnlessJoined(cpArbiter* arbiter, cpSpace*, cpDataPointer joined) {
  cpBody* a = nullptr;
  cpBody* b = nullptr;
  cpArbiterGetBodies(arbiter, &a, &b);
  return static_cast<const std::set<BodyPair>*>(joined)->count(ordered(a, b)) == 0 ? cpTrue
                                                                                   : cpFalse;
}

cpVect toCp(const Vec2d& v) { return cpv(v.x, v.y); }

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
    cpCollisionHandler* handler = cpSpaceAddDefaultCollisionHandler(space_);
    if (!uniform) handler->preSolveFunc = meanMixing;
    bodies_.reserve(scene.bodies.size());
    for (const BodyDesc& body : scene.bodies) create(body, uniform);
    for (const JointDesc& joint : scene.joints) createJoint(joint);
    if (!joined_.empty()) {
      handler->beginFunc = collideUnlessJoined;
      handler->userData = &joined_;
    }
  }

  ~ChipmunkAdapter() override {
    for (cpConstraint* constraint : constraints_) {
      cpSpaceRemoveConstraint(space_, constraint);
      cpConstraintFree(constraint);
    }
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
    for (const Vec2d& v : desc.shape.vertices) vertices.push_back(toCp(v));
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
    cpBodySetPosition(body, toCp(desc.position));
    cpBodySetAngle(body, desc.angle);
    if (!desc.isStatic) {
      cpBodySetVelocity(body, toCp(desc.velocity));
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

  cpBody* bodyOf(int index) const {
    return index == kWorldBody ? cpSpaceGetStaticBody(space_)
                               : bodies_[static_cast<std::size_t>(index)];
  }

  void createJoint(const JointDesc& joint) {
    cpBody* a = bodyOf(joint.bodyA);
    cpBody* b = bodyOf(joint.bodyB);
    const cpVect localA = cpBodyWorldToLocal(a, toCp(joint.anchorA));
    const cpVect localB = cpBodyWorldToLocal(b, toCp(joint.anchorB));
    cpConstraint* constraint = nullptr;
    switch (joint.kind) {
      case JointKind::Pin:
        constraint = cpPivotJointNew(a, b, toCp(joint.anchorA));
        break;
      case JointKind::Rod:
        constraint = cpPinJointNew(a, b, localA, localB);
        break;
      case JointKind::Spring:
        constraint = cpDampedSpringNew(a, b, localA, localB, joint.restLength, joint.stiffness,
                                       joint.damping);
        break;
    }
    cpSpaceAddConstraint(space_, constraint);
    constraints_.push_back(constraint);
    joined_.insert(ordered(a, b));
  }

  cpSpace* space_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  std::vector<cpConstraint*> constraints_;
  std::set<BodyPair> joined_;
};

}  // namespace

std::unique_ptr<EngineAdapter> makeChipmunkAdapter(const SceneDescription& scene, int iterations) {
  // Only the first bench's scenes so far: the Box2D v3 suite's compound,
  // capsule, chain and kinematic bodies are not translated for this engine.
  requirePlainScene(scene, "chipmunk");
  return std::make_unique<ChipmunkAdapter>(scene, iterations);
}

}  // namespace bench
