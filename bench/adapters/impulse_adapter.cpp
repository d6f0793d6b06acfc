// Impulse: one body per description body, materials as named (with a
// per-body override wherever a scene sets a coefficient the material does not
// have), the world's bounds widened to hold the scene. Everything else stays
// at WorldSettings' defaults except sub-steps and sleep. Joints: pins are
// revolute joints, rods distance joints of stiffness 0 (rigid), springs
// distance joints with the described stiffness and damping.

#include <algorithm>
#include <stdexcept>

#include "engine_adapter.h"
#include "impulse/world.h"

namespace bench {

namespace {

using impulse::Real;
using impulse::Vec2;

Vec2 toVec(const Vec2d& v) { return Vec2(Real(v.x), Real(v.y)); }

impulse::Shape toShape(const ShapeDesc& shape, const impulse::ShapeLimits& limits) {
  if (shape.kind == ShapeKind::Circle) return impulse::Shape::makeCircle(Real(shape.radius));
  std::vector<Vec2> points;
  for (const Vec2d& v : shape.vertices) points.push_back(toVec(v));
  impulse::PolygonBuild build = impulse::buildPolygon(points, limits);
  if (build.error != impulse::ShapeError::None) {
    throw std::runtime_error("impulse: " + std::string(impulse::describe(build.error)));
  }
  return impulse::Shape::makePolygon(build.polygon);
}

impulse::WorldSettings settingsFor(const SceneDescription& scene, int subSteps, bool sse2Only) {
  impulse::WorldSettings settings;
  if (sse2Only) settings.simdWidth = impulse::SimdWidth::Sse2;
  settings.gravity = toVec(scene.gravity);
  settings.subSteps = subSteps;
  settings.enableSleep = scene.allowSleep;
  // Bounds only gate creation (of bodies and joint anchors): fit them around
  // the scene.
  auto include = [&](const Vec2d& point) {
    Vec2 p = toVec(point);
    settings.bounds = settings.bounds.unite({p - Vec2(1, 1), p + Vec2(1, 1)});
  };
  for (const BodyDesc& body : scene.bodies) include(body.position);
  for (const JointDesc& joint : scene.joints) {
    include(joint.anchorA);
    include(joint.anchorB);
  }
  settings.shapeLimits.maxArea = Real(1e5);
  settings.shapeLimits.maxRadius = Real(1e3);
  settings.maxBodies = std::max<int>(settings.maxBodies, static_cast<int>(scene.bodies.size()));
  return settings;
}

// A scene's own density, friction or restitution, where it departs from the
// material's. A single friction coefficient (the peers' model) sets both of
// Impulse's coefficients, so every engine slides by the same closed form.
impulse::MaterialOverride overrideFor(const BodyDesc& body) {
  const impulse::MaterialProperties& material = impulse::materialProperties(body.material);
  impulse::MaterialOverride o;
  if (body.density != material.density) o.density = Real(body.density);
  if (body.restitution != material.restitution) o.restitution = Real(body.restitution);
  if (body.friction != material.staticFriction) {
    o.staticFriction = Real(body.friction);
    o.dynamicFriction = Real(body.friction);
  }
  return o;
}

impulse::JointSettings jointSettings(const JointDesc& joint) {
  switch (joint.kind) {
    case JointKind::Pin:
      return impulse::RevoluteJointSettings{};
    case JointKind::Rod:
      return impulse::DistanceJointSettings{};
    case JointKind::Spring:
      return impulse::DistanceJointSettings{Real(joint.restLength), Real(joint.stiffness),
                                            Real(joint.damping)};
  }
  throw std::logic_error("impulse: unknown joint kind");
}

class ImpulseAdapter final : public EngineAdapter {
 public:
  ImpulseAdapter(const SceneDescription& scene, int subSteps, bool sse2Only)
      : world_(settingsFor(scene, subSteps, sse2Only)) {
    ids_.reserve(scene.bodies.size());
    for (const BodyDesc& body : scene.bodies) {
      impulse::BodyDef def;
      def.shape = toShape(body.shape, world_.settings().shapeLimits);
      def.position = toVec(body.position);
      def.angle = Real(body.angle);
      def.linearVelocity = toVec(body.velocity);
      def.angularVelocity = Real(body.angularVelocity);
      def.material = body.material;
      def.materialOverride = overrideFor(body);
      def.isStatic = body.isStatic;
      impulse::CreateResult created = world_.createBody(def);
      if (!created.ok()) throw std::runtime_error("impulse: " + created.error);
      ids_.push_back(created.id);
    }
    for (const JointDesc& joint : scene.joints) createJoint(joint);
  }

  void step(double dt) override { world_.step(Real(dt)); }

  Pose pose(int index) const override {
    impulse::BodyState state = *world_.bodyState(ids_[static_cast<std::size_t>(index)]);
    return {{state.position.x(), state.position.y()},
            state.angle,
            {state.linearVelocity.x(), state.linearVelocity.y()},
            state.angularVelocity,
            state.awake};
  }

 private:
  void createJoint(const JointDesc& joint) {
    impulse::JointDef def;
    def.bodyA = ids_[static_cast<std::size_t>(joint.bodyA)];
    if (joint.bodyB != kWorldBody) def.bodyB = ids_[static_cast<std::size_t>(joint.bodyB)];
    def.anchorA = toVec(joint.anchorA);
    def.anchorB = toVec(joint.anchorB);
    def.settings = jointSettings(joint);
    impulse::JointResult created = world_.createJoint(def);
    if (!created.ok()) throw std::runtime_error("impulse: " + created.error);
  }

  impulse::World world_;
  std::vector<impulse::BodyId> ids_;
};

}  // namespace

std::unique_ptr<EngineAdapter> makeImpulseAdapter(const SceneDescription& scene, int subSteps,
                                                  bool sse2Only) {
  return std::make_unique<ImpulseAdapter>(scene, subSteps, sse2Only);
}

}  // namespace bench
