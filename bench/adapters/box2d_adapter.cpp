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

class Box2DAdapter final : public EngineAdapter {
 public:
  Box2DAdapter(const SceneDescription& scene, int velocityIterations, int positionIterations)
      : world_(b2Vec2(float(scene.gravity.x), float(scene.gravity.y))),
        velocityIterations_(velocityIterations),
        positionIterations_(positionIterations) {
    world_.SetAllowSleeping(scene.allowSleep);
    if (!scene.uniformCoefficients()) world_.SetContactListener(&mixing_);
    bodies_.reserve(scene.bodies.size());
    for (const BodyDesc& body : scene.bodies) bodies_.push_back(create(body));
    for (const JointDesc& joint : scene.joints) createJoint(joint);
  }

  void step(double dt) override { world_.Step(float(dt), velocityIterations_, positionIterations_); }

  Pose pose(int index) const override {
    const b2Body* body = bodies_[static_cast<std::size_t>(index)];
    b2Vec2 p = body->GetPosition();
    b2Vec2 v = body->GetLinearVelocity();
    return {{p.x, p.y}, body->GetAngle(), {v.x, v.y}, body->GetAngularVelocity(), body->IsAwake()};
  }

 private:
  b2Body* create(const BodyDesc& desc) {
    b2BodyDef def;
    def.type = desc.isStatic ? b2_staticBody : b2_dynamicBody;
    def.position.Set(float(desc.position.x), float(desc.position.y));
    def.angle = float(desc.angle);
    def.linearVelocity.Set(float(desc.velocity.x), float(desc.velocity.y));
    def.angularVelocity = float(desc.angularVelocity);
    b2Body* body = world_.CreateBody(&def);

    b2FixtureDef fixture;
    fixture.friction = float(desc.friction);
    fixture.restitution = float(desc.restitution);
    fixture.restitutionThreshold = 1.0f;
    b2CircleShape circle;
    b2PolygonShape polygon;
    if (desc.shape.kind == ShapeKind::Circle) {
      circle.m_radius = float(desc.shape.radius);
      fixture.shape = &circle;
      fixture.density = float(desc.density);
    } else {
      std::vector<b2Vec2> core = shrink(desc.shape.vertices, b2_polygonRadius);
      polygon.Set(core.data(), static_cast<int>(core.size()));
      fixture.shape = &polygon;
      fixture.density = float(desc.density * desc.shape.area() / polygonArea(core));
    }
    body->CreateFixture(&fixture);
    return body;
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
  // Only the first bench's scenes so far: the Box2D v3 suite's compound,
  // capsule, chain and kinematic bodies are not translated for this engine.
  requirePlainScene(scene, "box2d 2.4.1");
  return std::make_unique<Box2DAdapter>(scene, velocityIterations, positionIterations);
}

}  // namespace bench
