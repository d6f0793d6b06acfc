// Box2D 2.4.1. Its polygons carry a skin of b2_polygonRadius (1 cm) that
// collides; the adapter shrinks every polygon by that skin so the colliding
// surface is the described one, and raises the density so the mass is the
// described mass. Restitution threshold 1 m/s as Impulse's. Sleeping uses
// Box2D's compile-time tolerances (0.01 m/s, 2 deg/s, 0.5 s). Continuous
// collision is Box2D's default (dynamic against static). Box2D clamps a body's
// motion to b2_maxTranslation (2 m) per step: 120 m/s at 60 Hz. Joints:
// pins are b2RevoluteJoints, rods b2DistanceJoints of stiffness 0 (rigid),
// springs b2DistanceJoints with the described stiffness (N/m) and damping
// (N*s/m) and no length limits; a joint to the world joins a static body
// without fixtures.
//
// Box2D v3's suite: several fixtures per body, offset circles, segments
// (b2EdgeShape), collision filters (2.4.1's own, with the same rules),
// kinematic bodies (a target becomes the velocity that reaches it over the
// step, as v3's b2Body_SetTargetTransform does), bodies created asleep,
// linear damping, revolute limits and motors. 2.4.1 has no capsules, rounded
// polygons, one-sided chains or revolute springs: scenes with them are
// skipped, and the adapter creates every body at the start.

#include <box2d/box2d.h>

#include <cfloat>
#include <cmath>

#include "engine_adapter.h"

namespace bench {

namespace {

// Box2D mixes friction as sqrt(a*b) and restitution as max(a, b); scenes
// with mixed coefficients need the mean, set once when a contact starts.
class MeanMixing final : public b2ContactListener {
 public:
  void BeginContact(b2Contact* contact) override {
    const b2Fixture* a = contact->GetFixtureA();
    const b2Fixture* b = contact->GetFixtureB();
    contact->SetFriction(0.5f * (a->GetFriction() + b->GetFriction()));
    contact->SetRestitution(0.5f * (a->GetRestitution() + b->GetRestitution()));
  }
};

// Vertex i moved inward so both its edges move inward by `skin`.
std::vector<b2Vec2> shrink(const std::vector<Vec2d>& vertices, double skin) {
  const std::size_t n = vertices.size();
  std::vector<b2Vec2> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2d& prev = vertices[(i + n - 1) % n];
    const Vec2d& v = vertices[i];
    const Vec2d& next = vertices[(i + 1) % n];
    auto normal = [](const Vec2d& a, const Vec2d& b) {
      double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
      return Vec2d{dy / len, -dx / len};
    };
    Vec2d n1 = normal(prev, v), n2 = normal(v, next);
    double scale = skin / (1 + n1.x * n2.x + n1.y * n2.y);
    out.push_back(b2Vec2(float(v.x - scale * (n1.x + n2.x)), float(v.y - scale * (n1.y + n2.y))));
  }
  return out;
}

double polygonArea(const std::vector<b2Vec2>& vertices) {
  double twiceArea = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const b2Vec2& a = vertices[i];
    const b2Vec2& b = vertices[(i + 1) % vertices.size()];
    twiceArea += double(a.x) * b.y - double(a.y) * b.x;
  }
  return 0.5 * twiceArea;
}

b2Vec2 toVec(const Vec2d& v) { return b2Vec2(float(v.x), float(v.y)); }

/// What v3's suite uses that 2.4.1 lacks; empty when nothing.
std::string missingFeature(const SceneDescription& scene) {
  auto missing = [](const ShapeDesc& shape) -> std::string {
    if (shape.kind == ShapeKind::Capsule) return "capsules";
    if (shape.kind == ShapeKind::Chain) return "one-sided chains";
    if (shape.kind == ShapeKind::Polygon && shape.radius > 0) return "rounded polygons";
    return {};
  };
  for (const BodyDesc& body : scene.bodies) {
    if (body.spawnStep > 0) return "bodies created during the run";
    std::string feature = missing(body.shape);
    for (const ShapeDesc& shape : body.extraShapes) {
      if (feature.empty()) feature = missing(shape);
    }
    if (!feature.empty()) return feature;
  }
  for (const JointDesc& joint : scene.joints) {
    if (joint.springHertz > 0) return "revolute springs";
  }
  return {};
}

b2Filter toFilter(const CollisionFilter& filter) {
  b2Filter f;
  f.categoryBits = static_cast<uint16>(filter.category);
  f.maskBits = static_cast<uint16>(filter.mask);
  f.groupIndex = static_cast<int16>(filter.group);
  return f;
}

b2BodyType typeOf(const BodyDesc& desc) {
  if (desc.isStatic) return b2_staticBody;
  return desc.isKinematic ? b2_kinematicBody : b2_dynamicBody;
}

class Box2DAdapter final : public EngineAdapter {
 public:
  Box2DAdapter(const SceneDescription& scene, int velocityIterations, int positionIterations)
      : scene_(scene),
        world_(b2Vec2(float(scene.gravity.x), float(scene.gravity.y))),
        velocityIterations_(velocityIterations),
        positionIterations_(positionIterations) {
    world_.SetAllowSleeping(scene.allowSleep);
    if (!scene.uniformCoefficients()) world_.SetContactListener(&mixing_);
    bodies_.reserve(scene.bodies.size());
    for (const BodyDesc& body : scene.bodies) bodies_.push_back(create(body));
    for (const JointDesc& joint : scene.joints) createJoint(joint);
  }

  void step(double dt) override {
    for (const KinematicTarget& target : scene_.targets) steer(target, dt);
    world_.Step(float(dt), velocityIterations_, positionIterations_);
    ++stepCount_;
  }

  Pose pose(int index) const override {
    const b2Body* body = bodies_[static_cast<std::size_t>(index)];
    b2Vec2 p = body->GetPosition();
    b2Vec2 v = body->GetLinearVelocity();
    return {{p.x, p.y}, body->GetAngle(), {v.x, v.y}, body->GetAngularVelocity(), body->IsAwake()};
  }

 private:
  // The velocity that takes the body to the target over the step; 2.4.1's
  // kinematic bodies move by their velocity alone.
  void steer(const KinematicTarget& target, double dt) {
    b2Body* body = bodies_[static_cast<std::size_t>(target.body)];
    const b2Vec2 to = toVec(target.position(stepCount_ * dt));
    body->SetLinearVelocity((1.0f / float(dt)) * (to - body->GetPosition()));
  }

  b2Body* create(const BodyDesc& desc) {
    b2BodyDef def;
    def.type = typeOf(desc);
    def.position = toVec(desc.position);
    def.angle = float(desc.angle);
    def.linearVelocity = toVec(desc.velocity);
    def.angularVelocity = float(desc.angularVelocity);
    def.linearDamping = float(desc.linearDamping);
    def.awake = !desc.startsAsleep;
    b2Body* body = world_.CreateBody(&def);
    addFixture(body, desc, desc.shape);
    for (const ShapeDesc& shape : desc.extraShapes) addFixture(body, desc, shape);
    return body;
  }

  static void addFixture(b2Body* body, const BodyDesc& desc, const ShapeDesc& shape) {
    b2FixtureDef fixture;
    fixture.friction = float(shape.friction.value_or(desc.friction));
    fixture.restitution = float(desc.restitution);
    fixture.restitutionThreshold = 1.0f;
    fixture.density = float(desc.density);
    fixture.filter = toFilter(shape.filter);
    b2CircleShape circle;
    b2PolygonShape polygon;
    b2EdgeShape edge;
    switch (shape.kind) {
      case ShapeKind::Circle:
        circle.m_radius = float(shape.radius);
        circle.m_p = toVec(shape.center);
        fixture.shape = &circle;
        break;
      case ShapeKind::Polygon: {
        std::vector<b2Vec2> core = shrink(shape.vertices, b2_polygonRadius);
        polygon.Set(core.data(), static_cast<int>(core.size()));
        fixture.shape = &polygon;
        fixture.density = float(desc.density * shape.area() / polygonArea(core));
        break;
      }
      case ShapeKind::Segment:
        edge.SetTwoSided(toVec(shape.vertices[0]), toVec(shape.vertices[1]));
        fixture.shape = &edge;
        break;
      case ShapeKind::Capsule:
      case ShapeKind::Chain: throw Unsupported("box2d 2.4.1 adapter: no capsules or one-sided chains");
    }
    body->CreateFixture(&fixture);
  }

  b2Body* bodyOf(int index) {
    if (index != kWorldBody) return bodies_[static_cast<std::size_t>(index)];
    if (!ground_) {
      b2BodyDef def;
      ground_ = world_.CreateBody(&def);
    }
    return ground_;
  }

  void createJoint(const JointDesc& joint) {
    b2Body* a = bodyOf(joint.bodyA);
    b2Body* b = bodyOf(joint.bodyB);
    const b2Vec2 anchorA(float(joint.anchorA.x), float(joint.anchorA.y));
    const b2Vec2 anchorB(float(joint.anchorB.x), float(joint.anchorB.y));
    if (joint.kind == JointKind::Pin) {
      b2RevoluteJointDef def;
      def.Initialize(a, b, anchorA);
      // A pin may be built open (Solver2D's stretched chain).
      def.localAnchorB = b->GetLocalPoint(anchorB);
      def.enableLimit = joint.enableLimit;
      def.lowerAngle = float(joint.lowerAngle);
      def.upperAngle = float(joint.upperAngle);
      def.enableMotor = joint.enableMotor;
      def.motorSpeed = float(joint.motorSpeed);
      def.maxMotorTorque = float(joint.maxMotorTorque);
      world_.CreateJoint(&def);
      return;
    }
    b2DistanceJointDef def;
    def.Initialize(a, b, anchorA, anchorB);
    if (joint.kind == JointKind::Spring) {
      // Initialize pins min and max length to the rest length, which would
      // hold the spring rigid: free them.
      def.length = float(joint.restLength);
      def.minLength = 0;
      def.maxLength = FLT_MAX;
      def.stiffness = float(joint.stiffness);
      def.damping = float(joint.damping);
    }
    world_.CreateJoint(&def);
  }

  const SceneDescription& scene_;
  int stepCount_ = 0;
  b2World world_;
  b2Body* ground_ = nullptr;
  MeanMixing mixing_;
  int velocityIterations_;
  int positionIterations_;
  std::vector<b2Body*> bodies_;
};

}  // namespace

std::unique_ptr<EngineAdapter> makeBox2DAdapter(const SceneDescription& scene, int velocityIterations,
                                                int positionIterations) {
  if (const std::string feature = missingFeature(scene); !feature.empty()) {
    throw Unsupported("box2d 2.4.1 adapter: no " + feature);
  }
  return std::make_unique<Box2DAdapter>(scene, velocityIterations, positionIterations);
}

}  // namespace bench
