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
//
// Box2D v3's suite: bodies of several shapes (Chipmunk sums their mass from
// each shape's density), offset circles, segments, collision filters (a
// negative v3 group is a Chipmunk group: the same never-collide rule),
// kinematic bodies (a target becomes the velocity that reaches it over the
// step), bodies put to sleep at creation, and pin motors (cpSimpleMotor, its
// torque capped). Chipmunk has no one-sided chains; revolute limits, springs
// and linear damping, and bodies created during the run, are not translated
// (rain, spinner): scenes with them are skipped.

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

/// What v3's suite uses that this adapter does not translate; empty when nothing.
std::string missingFeature(const SceneDescription& scene) {
  auto missing = [](const ShapeDesc& shape) -> std::string {
    if (shape.kind == ShapeKind::Chain) return "one-sided chains";
    if (shape.filter.group > 0) return "positive collision groups";
    return {};
  };
  for (const BodyDesc& body : scene.bodies) {
    if (body.spawnStep > 0) return "bodies created during the run";
    if (body.linearDamping > 0) return "linear damping";
    std::string feature = missing(body.shape);
    for (const ShapeDesc& shape : body.extraShapes) {
      if (feature.empty()) feature = missing(shape);
    }
    if (!feature.empty()) return feature;
  }
  for (const JointDesc& joint : scene.joints) {
    if (joint.enableLimit || joint.springHertz > 0) return "revolute limits or springs";
  }
  return {};
}

cpShapeFilter toFilter(const CollisionFilter& filter) {
  return cpShapeFilterNew(static_cast<cpGroup>(-filter.group), filter.category, filter.mask);
}

cpShape* newShape(cpBody* body, const ShapeDesc& shape) {
  std::vector<cpVect> vertices;
  for (const Vec2d& v : shape.vertices) vertices.push_back(toCp(v));
  switch (shape.kind) {
    case ShapeKind::Circle: return cpCircleShapeNew(body, shape.radius, toCp(shape.center));
    case ShapeKind::Polygon:
      return cpPolyShapeNewRaw(body, static_cast<int>(vertices.size()), vertices.data(), shape.radius);
    case ShapeKind::Capsule:
    case ShapeKind::Segment: return cpSegmentShapeNew(body, vertices[0], vertices[1], shape.radius);
    case ShapeKind::Chain: break;
  }
  throw Unsupported("chipmunk adapter: no one-sided chains");
}

class ChipmunkAdapter final : public EngineAdapter {
 public:
  ChipmunkAdapter(const SceneDescription& scene, int iterations) : scene_(scene), space_(cpSpaceNew()) {
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

  void step(double dt) override {
    for (const KinematicTarget& target : scene_.targets) steer(target, dt);
    cpSpaceStep(space_, dt);
    ++stepCount_;
  }

  Pose pose(int index) const override {
    cpBody* body = bodies_[static_cast<std::size_t>(index)];
    cpVect p = cpBodyGetPosition(body);
    cpVect v = cpBodyGetVelocity(body);
    return {{p.x, p.y}, cpBodyGetAngle(body), {v.x, v.y}, cpBodyGetAngularVelocity(body),
            !cpBodyIsSleeping(body)};
  }

 private:
  // The velocity that takes the body to the target over the step.
  void steer(const KinematicTarget& target, double dt) {
    cpBody* body = bodies_[static_cast<std::size_t>(target.body)];
    cpBodySetVelocity(body, cpvmult(cpvsub(toCp(target.position(stepCount_ * dt)), cpBodyGetPosition(body)), 1 / dt));
  }

  static cpBody* newBody(const BodyDesc& desc) {
    if (desc.isStatic) return cpBodyNewStatic();
    // Mass, centre of gravity and moment come from the shapes' densities.
    return desc.isKinematic ? cpBodyNewKinematic() : cpBodyNew(0, 0);
  }

  void create(const BodyDesc& desc, bool uniform) {
    cpBody* body = newBody(desc);
    cpSpaceAddBody(space_, body);
    cpBodySetPosition(body, toCp(desc.position));
    cpBodySetAngle(body, desc.angle);
    if (!desc.isStatic) {
      cpBodySetVelocity(body, toCp(desc.velocity));
      cpBodySetAngularVelocity(body, desc.angularVelocity);
    }
    addShape(body, desc, desc.shape, uniform);
    for (const ShapeDesc& shape : desc.extraShapes) addShape(body, desc, shape, uniform);
    if (desc.startsAsleep) cpBodySleep(body);
    bodies_.push_back(body);
  }

  void addShape(cpBody* body, const BodyDesc& desc, const ShapeDesc& described, bool uniform) {
    cpShape* shape = newShape(body, described);
    const double friction = described.friction.value_or(desc.friction);
    cpShapeSetFriction(shape, uniform ? std::sqrt(friction) : friction);
    cpShapeSetElasticity(shape, uniform ? std::sqrt(desc.restitution) : desc.restitution);
    cpShapeSetFilter(shape, toFilter(described.filter));
    if (desc.isDynamic()) cpShapeSetDensity(shape, desc.density);
    cpSpaceAddShape(space_, shape);
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
        if (joint.enableMotor) addMotor(a, b, joint);
        // Local anchors: a pin may be built open (Solver2D's stretched chain).
        constraint = cpPivotJointNew2(a, b, localA, localB);
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

  // A pin's motor holds B's spin relative to A at the speed, its torque
  // capped. Chipmunk's rate is A's spin relative to B: the sign turns.
  void addMotor(cpBody* a, cpBody* b, const JointDesc& joint) {
    cpConstraint* motor = cpSimpleMotorNew(a, b, -joint.motorSpeed);
    cpConstraintSetMaxForce(motor, joint.maxMotorTorque);
    cpSpaceAddConstraint(space_, motor);
    constraints_.push_back(motor);
  }

  const SceneDescription& scene_;
  int stepCount_ = 0;
  cpSpace* space_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  std::vector<cpConstraint*> constraints_;
  std::set<BodyPair> joined_;
};

}  // namespace

std::unique_ptr<EngineAdapter> makeChipmunkAdapter(const SceneDescription& scene, int iterations) {
  if (const std::string feature = missingFeature(scene); !feature.empty()) {
    throw Unsupported("chipmunk adapter: no " + feature);
  }
  return std::make_unique<ChipmunkAdapter>(scene, iterations);
}

}  // namespace bench
