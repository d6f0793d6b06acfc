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
//
// Joints as v3's users make them, from b2DefaultRevoluteJointDef and
// b2DefaultDistanceJointDef: pins are revolute joints, rods distance joints
// without spring. v3 solves both as soft constraints (constraint hertz 60,
// capped at a quarter of the sub-step rate, damping ratio 2, the same soft
// step as its contacts): they are v3's rigid joints, soft by its design.
// Springs are distance joints with enableSpring; v3 takes a frequency and a
// damping ratio, not N/m and N*s/m, so the described stiffness k and damping
// c become hertz = sqrt(k / m) / (2 pi) and ratio = c / (2 sqrt(k m)) for the
// joint's effective mass m along its axis at creation (the mass v3 scales
// the spring by). A joint to the world joins a static body without shapes.

#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "engine_adapter.h"
#include "spawn_schedule.h"
#include "task_pool.h"

#ifndef BOX2D_V3_NAMESPACE
#error "BOX2D_V3_NAMESPACE names the v3 build this adapter is compiled for"
#endif

namespace bench::BOX2D_V3_NAMESPACE {

namespace {

// v3 mixes friction as sqrt(a*b) and restitution as max(a, b); scenes with
// mixed coefficients get the mean, as in every engine here.
float meanOf(float a, uint64_t, float b, uint64_t) { return 0.5f * (a + b); }

b2Vec2 toVec(const Vec2d& v) { return b2Vec2{float(v.x), float(v.y)}; }

b2Polygon toPolygon(const ShapeDesc& shape) {
  // Polygons v3 refuses: scenes it cannot express, reported as skipped.
  if (shape.vertices.size() > B2_MAX_POLYGON_VERTICES) throw Unsupported("box2d v3: too many vertices");
  b2Vec2 points[B2_MAX_POLYGON_VERTICES];
  for (std::size_t i = 0; i < shape.vertices.size(); ++i) points[i] = toVec(shape.vertices[i]);
  b2Hull hull = b2ComputeHull(points, static_cast<int>(shape.vertices.size()));
  if (hull.count == 0) throw Unsupported("box2d v3: polygon is not a convex hull");
  return b2MakePolygon(&hull, float(shape.radius));
}

b2Filter toFilter(const CollisionFilter& filter) {
  b2Filter f = b2DefaultFilter();
  f.categoryBits = filter.category;
  f.maskBits = filter.mask == ~0u ? B2_DEFAULT_MASK_BITS : filter.mask;
  f.groupIndex = filter.group;
  return f;
}

/// Every shape kind but chains, which b2CreateChain makes.
void createShape(b2BodyId body, b2ShapeDef def, const ShapeDesc& shape) {
  def.filter = toFilter(shape.filter);
  if (shape.friction) def.material.friction = float(*shape.friction);
  switch (shape.kind) {
    case ShapeKind::Circle: {
      const b2Circle circle{toVec(shape.center), float(shape.radius)};
      b2CreateCircleShape(body, &def, &circle);
      return;
    }
    case ShapeKind::Polygon: {
      const b2Polygon polygon = toPolygon(shape);
      b2CreatePolygonShape(body, &def, &polygon);
      return;
    }
    case ShapeKind::Capsule: {
      const b2Capsule capsule{toVec(shape.vertices[0]), toVec(shape.vertices[1]), float(shape.radius)};
      b2CreateCapsuleShape(body, &def, &capsule);
      return;
    }
    case ShapeKind::Segment: {
      const b2Segment segment{toVec(shape.vertices[0]), toVec(shape.vertices[1])};
      b2CreateSegmentShape(body, &def, &segment);
      return;
    }
    case ShapeKind::Chain: break;
  }
  throw std::logic_error("box2d v3: a chain is not a single shape");
}

void createChain(b2BodyId body, const b2ShapeDef& shapeDef, const ShapeDesc& shape) {
  std::vector<b2Vec2> points;
  for (const Vec2d& v : shape.vertices) points.push_back(toVec(v));
  b2ChainDef def = b2DefaultChainDef();
  def.points = points.data();
  def.count = static_cast<int>(points.size());
  def.isLoop = shape.loop;
  def.materials = &shapeDef.material;
  def.materialCount = 1;
  def.filter = toFilter(shape.filter);
  b2CreateChain(body, &def);
}

// A body's share 1/m + (r x u)^2 / I of a joint's inverse effective mass
// along u at its anchor (r from its centre of mass); static bodies add 0.
float inverseMassAlong(b2BodyId body, b2Vec2 anchor, b2Vec2 axis) {
  const float mass = b2Body_GetMass(body);
  if (mass == 0) return 0;
  const b2Vec2 centre = b2Body_GetWorldPoint(body, b2Body_GetLocalCenter(body));
  const float arm = b2Cross(b2Sub(anchor, centre), axis);
  return 1 / mass + arm * arm / b2Body_GetRotationalInertia(body);
}

// The shape's own bounding box where its body is (the query bench's
// shapes are circles and polygons).
b2AABB tightBox(b2ShapeId shape) {
  const b2WorldTransform transform = b2Body_GetTransform(b2Shape_GetBody(shape));
  if (b2Shape_GetType(shape) == b2_circleShape) {
    const b2Circle circle = b2Shape_GetCircle(shape);
    return b2ComputeCircleAABB(&circle, transform);
  }
  const b2Polygon polygon = b2Shape_GetPolygon(shape);
  return b2ComputePolygonAABB(&polygon, transform);
}

class Box2DV3Adapter final : public EngineAdapter {
 public:
  Box2DV3Adapter(const SceneDescription& scene, int subSteps, int workers)
      : scene_(scene), schedule_(scene), subSteps_(subSteps) {
    b2WorldDef def = b2DefaultWorldDef();
    if (workers > 1) {
      pool_ = std::make_unique<TaskPool>(workers);
      def.workerCount = workers;
      def.enqueueTask = enqueueOnPool;
      def.finishTask = finishOnPool;
      def.userTaskContext = pool_.get();
    }
    def.gravity = toVec(scene.gravity);
    def.enableSleep = scene.allowSleep;
    if (!scene.uniformCoefficients()) {
      def.frictionCallback = meanOf;
      def.restitutionCallback = meanOf;
    }
    world_ = b2CreateWorld(&def);
    bodies_.reserve(scene.bodies.size());
    spawnDue();
  }
  ~Box2DV3Adapter() override { b2DestroyWorld(world_); }

  static void* enqueueOnPool(b2TaskCallback* task, void* taskContext, void* pool) {
    return static_cast<TaskPool*>(pool)->enqueue(task, taskContext);
  }
  static void finishOnPool(void* handle, void* pool) { static_cast<TaskPool*>(pool)->finish(handle); }
  Box2DV3Adapter(const Box2DV3Adapter&) = delete;
  Box2DV3Adapter& operator=(const Box2DV3Adapter&) = delete;

  void step(double dt) override {
    for (const KinematicTarget& target : scene_.targets) steer(target, dt);
    b2World_Step(world_, float(dt), subSteps_);
    // v3 times its bullets' continuous collision and its island sleeping
    // within its solve: told apart as Impulse's stages are (its other
    // bodies' continuous collision stays within the solve).
    const b2Profile profile = b2World_GetProfile(world_);
    stageTimes_.add({profile.pairs, profile.collide, profile.solve - profile.bullets - profile.sleepIslands,
                     profile.bullets, profile.sleepIslands});
    ++stepCount_;
    spawnDue();
  }

  // The constraints in v3's colours after each step: its touching contacts
  // of awake bodies and its joints (its counters tell them apart by colour
  // only), which its solver passes run over.
  void countStep() override {
    const b2Counters counters = b2World_GetCounters(world_);
    colouredConstraints_ += std::accumulate(std::begin(counters.colorCounts), std::end(counters.colorCounts), 0L);
    ++countedSteps_;
  }
  std::string passes() const override {
    if (countedSteps_ == 0) return {};
    char text[96];
    std::snprintf(text, sizeof text, "%.0f constraints a step in its colours (contacts and joints)",
                  double(colouredConstraints_) / countedSteps_);
    return text;
  }

  bool hasQueries() const override { return true; }
  std::string stages() const override { return stageTimes_.describe(); }

  double castRayClosest(const Vec2d& origin, const Vec2d& translation) override {
    const b2RayResult result = b2World_CastRayClosest(world_, toVec(origin), toVec(translation), b2DefaultQueryFilter());
    return result.hit ? double(result.fraction) : -1;
  }

  // v3 reports a shape the ray starts inside as a hit at fraction 0 (its
  // closest-hit search skips those); Impulse never reports them, so they
  // are not counted here.
  int castRayCount(const Vec2d& origin, const Vec2d& translation) override {
    int count = 0;
    auto countHit = [](b2ShapeId, b2Pos, b2Vec2, float fraction, void* context) {
      if (fraction > 0) ++*static_cast<int*>(context);
      // 1 keeps the ray whole: every hit is reported.
      return 1.0f;
    };
    b2World_CastRay(world_, toVec(origin), toVec(translation), b2DefaultQueryFilter(), countHit, &count);
    return count;
  }

  // v3 reports the shapes whose fat (margin-grown) box overlaps, and the box
  // it keeps per shape is grown by its speculative distance; the tight box
  // computed here makes its answer the one Impulse gives.
  int overlapBoxCount(const Vec2d& lower, const Vec2d& upper) override {
    struct Count {
      b2AABB box;
      int count;
    } count{{toVec(lower), toVec(upper)}, 0};
    auto countTight = [](b2ShapeId shape, void* context) {
      Count& c = *static_cast<Count*>(context);
      if (b2AABB_Overlaps(tightBox(shape), c.box)) ++c.count;
      return true;
    };
    b2World_OverlapAABB(world_, b2Pos_zero, count.box, b2DefaultQueryFilter(), countTight, &count);
    return count.count;
  }

  Pose pose(int index) const override {
    const std::size_t i = static_cast<std::size_t>(index);
    if (i >= bodies_.size()) return describedPose(scene_.bodies[i]);
    b2BodyId body = bodies_[i];
    b2Vec2 p = b2Body_GetPosition(body);
    b2Vec2 v = b2Body_GetLinearVelocity(body);
    return {{p.x, p.y},
            b2Rot_GetAngle(b2Body_GetRotation(body)),
            {v.x, v.y},
            b2Body_GetAngularVelocity(body),
            b2Body_IsAwake(body)};
  }

 private:
  void spawnDue() {
    schedule_.spawnDue(
        stepCount_, [this](const BodyDesc& body) { bodies_.push_back(create(body)); },
        [this](const JointDesc& joint) { createJoint(joint); });
  }

  void steer(const KinematicTarget& target, double dt) {
    const b2BodyId body = bodies_[static_cast<std::size_t>(target.body)];
    const b2Transform to{toVec(target.position(stepCount_ * dt)), b2Body_GetRotation(body)};
    b2Body_SetTargetTransform(body, to, float(dt), true);
  }

  static b2BodyType typeOf(const BodyDesc& desc) {
    if (desc.isStatic) return b2_staticBody;
    return desc.isKinematic ? b2_kinematicBody : b2_dynamicBody;
  }

  b2BodyId create(const BodyDesc& desc) {
    b2BodyDef def = b2DefaultBodyDef();
    def.type = typeOf(desc);
    def.position = toVec(desc.position);
    def.rotation = b2MakeRot(float(desc.angle));
    def.linearVelocity = toVec(desc.velocity);
    def.angularVelocity = float(desc.angularVelocity);
    def.linearDamping = float(desc.linearDamping);
    def.isAwake = !desc.startsAsleep;
    b2BodyId body = b2CreateBody(world_, &def);

    b2ShapeDef shape = b2DefaultShapeDef();
    shape.density = float(desc.density);
    shape.material.friction = float(desc.friction);
    shape.material.restitution = float(desc.restitution);
    if (desc.shape.kind == ShapeKind::Chain) {
      createChain(body, shape, desc.shape);
    } else {
      createShape(body, shape, desc.shape);
    }
    for (const ShapeDesc& extra : desc.extraShapes) createShape(body, shape, extra);
    return body;
  }

  b2BodyId bodyOf(int index) {
    if (index != kWorldBody) return bodies_[static_cast<std::size_t>(index)];
    if (B2_IS_NULL(ground_)) {
      b2BodyDef def = b2DefaultBodyDef();
      ground_ = b2CreateBody(world_, &def);
    }
    return ground_;
  }

  // The bodies and anchors of a joint definition whose other fields keep
  // their defaults.
  void join(b2JointDef& base, const JointDesc& joint) {
    base.bodyIdA = bodyOf(joint.bodyA);
    base.bodyIdB = bodyOf(joint.bodyB);
    base.localFrameA.p = b2Body_GetLocalPoint(base.bodyIdA, toVec(joint.anchorA));
    base.localFrameB.p = b2Body_GetLocalPoint(base.bodyIdB, toVec(joint.anchorB));
  }

  void createJoint(const JointDesc& joint) {
    if (joint.kind == JointKind::Pin) {
      b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
      join(def.base, joint);
      def.enableLimit = joint.enableLimit;
      def.lowerAngle = float(joint.lowerAngle);
      def.upperAngle = float(joint.upperAngle);
      def.enableMotor = joint.enableMotor;
      def.motorSpeed = float(joint.motorSpeed);
      def.maxMotorTorque = float(joint.maxMotorTorque);
      def.enableSpring = joint.springHertz > 0;
      def.hertz = float(joint.springHertz);
      def.dampingRatio = float(joint.springDampingRatio);
      b2CreateRevoluteJoint(world_, &def);
      return;
    }
    b2DistanceJointDef def = b2DefaultDistanceJointDef();
    join(def.base, joint);
    def.length = b2Distance(toVec(joint.anchorA), toVec(joint.anchorB));
    if (joint.kind == JointKind::Spring) springFor(joint, def);
    b2CreateDistanceJoint(world_, &def);
  }

  void springFor(const JointDesc& joint, b2DistanceJointDef& def) {
    const b2Vec2 anchorA = toVec(joint.anchorA), anchorB = toVec(joint.anchorB);
    const b2Vec2 axis = b2Normalize(b2Sub(anchorB, anchorA));
    const double mass = 1.0 / (inverseMassAlong(def.base.bodyIdA, anchorA, axis) +
                               inverseMassAlong(def.base.bodyIdB, anchorB, axis));
    def.length = float(joint.restLength);
    def.enableSpring = true;
    def.hertz = float(std::sqrt(joint.stiffness / mass) / (2 * std::numbers::pi));
    def.dampingRatio = float(joint.damping / (2 * std::sqrt(joint.stiffness * mass)));
  }

  const SceneDescription& scene_;
  SpawnSchedule schedule_;
  int stepCount_ = 0;
  long colouredConstraints_ = 0;
  int countedSteps_ = 0;
  StageTimes stageTimes_{{"pairs", "collide", "solve", "continuous", "sleep"}};
  b2WorldId world_{};
  b2BodyId ground_ = b2_nullBodyId;
  int subSteps_;
  std::vector<b2BodyId> bodies_;
  std::unique_ptr<TaskPool> pool_;  // outlives nothing of the world: destroyed after it
};

}  // namespace

std::unique_ptr<EngineAdapter> makeAdapter(const SceneDescription& scene, int subSteps, int workers) {
  return std::make_unique<Box2DV3Adapter>(scene, subSteps, workers);
}

}  // namespace bench::BOX2D_V3_NAMESPACE
