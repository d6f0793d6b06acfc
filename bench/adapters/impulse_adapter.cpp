// Impulse: one body per description body, materials as named (with a
// per-body override wherever a scene sets a coefficient the material does not
// have), the world's bounds widened to hold the scene. Everything else stays
// at WorldSettings' defaults except sub-steps and sleep. Joints: pins are
// revolute joints, rods distance joints of stiffness 0 (rigid), springs
// distance joints with the described stiffness and damping. A pin's spring,
// given as Box2D v3 gives it (hertz, damping ratio), becomes the stiffness
// and damping of the same oscillator on the pair's relative rotational
// inertia. Chains are World::createChain bodies. The world's origin is the
// scene's (World::shiftOrigin), so positions go in and come out relative to it.
//
// Collision filters are Impulse's own (the same rule as Box2D v3's). Bodies
// described asleep are created asleep (BodyDef::isAwake). Box2D v3's linear damping
// is Impulse's linear drag (the same rate; exact where v3's is first order).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "engine_adapter.h"
#include "impulse/world.h"
#include "spawn_schedule.h"

namespace bench {

namespace {

using impulse::Real;
using impulse::Vec2;

Vec2 toVec(const Vec2d& v) { return Vec2(Real(v.x), Real(v.y)); }

/// A described point from (0, 0), relative to the scene's origin, for
/// settings made before the world (World::toLocal afterwards).
Vec2 toLocal(const SceneDescription& scene, const Vec2d& point) {
  return toVec({point.x - scene.origin.x, point.y - scene.origin.y});
}

Vec2 rotate(const Vec2& v, Real angle) {
  const Real c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

impulse::Shape toPolygon(const ShapeDesc& shape, const impulse::ShapeLimits& limits) {
  std::vector<Vec2> points;
  for (const Vec2d& v : shape.vertices) points.push_back(toVec(v));
  impulse::PolygonBuild build = impulse::buildPolygon(points, limits);
  // A polygon Impulse refuses (Solver2D's 2 mm cards): the scene is one it
  // cannot express, reported as skipped with the reason.
  if (build.error != impulse::ShapeError::None) {
    throw Unsupported("impulse: " + std::string(impulse::describe(build.error)));
  }
  build.polygon.radius = Real(shape.radius);
  // buildPolygon centres the polygon on its centroid: put it back where the
  // body's frame has it.
  return impulse::translated(impulse::Shape::makePolygon(build.polygon), build.centroid);
}

/// Every shape kind but chains, which are bodies of their own.
impulse::Shape toShape(const ShapeDesc& shape, const impulse::ShapeLimits& limits) {
  switch (shape.kind) {
    case ShapeKind::Circle: return impulse::Shape::makeCircle(Real(shape.radius), toVec(shape.center));
    case ShapeKind::Polygon: return toPolygon(shape, limits);
    case ShapeKind::Capsule:
      return impulse::Shape::makeCapsule(toVec(shape.vertices[0]), toVec(shape.vertices[1]), Real(shape.radius));
    case ShapeKind::Segment: return impulse::Shape::makeSegment(toVec(shape.vertices[0]), toVec(shape.vertices[1]));
    case ShapeKind::Chain: break;
  }
  throw std::logic_error("impulse: a chain is a body of its own");
}

impulse::WorldSettings settingsFor(const SceneDescription& scene, int subSteps, bool sse2Only, int threads) {
  impulse::WorldSettings settings;
  settings.tasks.workerCount = threads;
  if (sse2Only) settings.simdWidth = impulse::SimdWidth::Sse2;
  settings.gravity = toVec(scene.gravity);
  settings.subSteps = subSteps;
  settings.enableSleep = scene.allowSleep;
  // Bounds only gate creation (of bodies and joint anchors): fit them around
  // the scene.
  auto include = [&](const Vec2d& point, double margin) {
    Vec2 p = toLocal(scene, point);
    const Vec2 reach = Vec2::Constant(Real(margin));
    settings.bounds = settings.bounds.unite({p - reach, p + reach});
  };
  for (const BodyDesc& body : scene.bodies) {
    include(body.position, 1 + body.shape.extent());
    for (const ShapeDesc& shape : body.extraShapes) include(body.position, 1 + shape.extent());
  }
  for (const JointDesc& joint : scene.joints) {
    include(joint.anchorA, 1);
    include(joint.anchorB, 1);
  }
  settings.shapeLimits.maxArea = Real(1e5);
  // Solver2D's card house has cards of 8 cm^2.
  settings.shapeLimits.minArea = Real(1e-4);
  settings.shapeLimits.maxRadius = Real(1e3);
  settings.maxBodies = std::max<int>(settings.maxBodies, static_cast<int>(scene.bodies.size()));
  return settings;
}

// A scene's own density, friction or restitution, where it departs from the
// material's. A single friction coefficient (the peers' model) sets both of
// Impulse's coefficients, so every engine slides by the same closed form.
impulse::MaterialOverride overrideFor(const BodyDesc& body, std::optional<double> shapeFriction = std::nullopt) {
  const impulse::MaterialProperties& material = impulse::materialProperties(body.material);
  const double friction = shapeFriction.value_or(body.friction);
  impulse::MaterialOverride o;
  if (body.density != material.density) o.density = Real(body.density);
  if (body.restitution != material.restitution) o.restitution = Real(body.restitution);
  if (friction != material.staticFriction) {
    o.staticFriction = Real(friction);
    o.dynamicFriction = Real(friction);
  }
  return o;
}

// The description's filter; its all-categories mask is every bit of Impulse's wider one.
impulse::ShapeInteraction interactionOf(const ShapeDesc& shape) {
  impulse::ShapeInteraction interaction;
  interaction.filter.categoryBits = shape.filter.category;
  interaction.filter.maskBits = shape.filter.mask == ~0u ? ~std::uint64_t{0} : shape.filter.mask;
  interaction.filter.groupIndex = shape.filter.group;
  return interaction;
}

impulse::BodyOptions optionsFor(const BodyDesc& body) {
  impulse::BodyOptions options;
  options.interaction = interactionOf(body.shape);
  options.material = body.material;
  options.materialOverride = overrideFor(body);
  options.properties.isKinematic = body.isKinematic;
  options.isAwake = !body.startsAsleep;
  options.linearVelocity = toVec(body.velocity);
  options.angularVelocity = Real(body.angularVelocity);
  return options;
}

impulse::BodyDef bodyDefFor(const SceneDescription& scene, const BodyDesc& body,
                            const impulse::ShapeLimits& limits) {
  impulse::BodyDef def;
  def.shape = toShape(body.shape, limits);
  def.materialOverride = overrideFor(body, body.shape.friction);
  def.interaction = interactionOf(body.shape);
  for (const ShapeDesc& shape : body.extraShapes) {
    def.extraShapes.push_back(
        {toShape(shape, limits), body.material, overrideFor(body, shape.friction), interactionOf(shape)});
  }
  def.position = toLocal(scene, body.position);
  def.angle = Real(body.angle);
  def.linearVelocity = toVec(body.velocity);
  def.angularVelocity = Real(body.angularVelocity);
  def.material = body.material;
  def.properties.isStatic = body.isStatic;
  def.properties.isKinematic = body.isKinematic;
  def.properties.linearDrag = Real(body.linearDamping);
  def.isAwake = !body.startsAsleep;
  return def;
}

class ImpulseAdapter final : public EngineAdapter {
 public:
  ImpulseAdapter(const SceneDescription& scene, int subSteps, bool sse2Only, int threads)
      : scene_(scene), world_(settingsFor(scene, subSteps, sse2Only, threads)), schedule_(scene) {
    impulse::InputResult moved = world_.shiftOrigin({scene.origin.x, scene.origin.y});
    if (!moved.ok()) throw std::runtime_error("impulse: " + moved.error);
    bodies_.reserve(scene.bodies.size());
    spawnDue();
  }

  void step(double dt) override {
    for (const KinematicTarget& target : scene_.targets) steer(target, dt);
    world_.step(Real(dt));
    const impulse::StepProfile& profile = world_.profile();
    stageTimes_.add({profile.pairs, profile.collide, profile.solve, profile.continuous, profile.sleep});
    ++stepCount_;
    spawnDue();
  }

  Pose pose(int index) const override {
    const std::size_t i = static_cast<std::size_t>(index);
    if (i >= bodies_.size()) return describedPose(scene_.bodies[i]);
    impulse::BodyState state = *world_.bodyState(bodies_[i].id);
    const impulse::Vec2d origin =
        world_.toGlobal(state.position - rotate(bodies_[i].originToCentre, state.angle));
    return {{origin.x(), origin.y()},
            state.angle,
            {state.linearVelocity.x(), state.linearVelocity.y()},
            state.angularVelocity,
            state.awake};
  }

  bool hasQueries() const override { return true; }

  double castRayClosest(const Vec2d& origin, const Vec2d& translation) override {
    const impulse::CastResult result = world_.castRayClosest(local(origin), toVec(translation));
    return result.hit ? double(result.hit->fraction) : -1;
  }

  int castRayCount(const Vec2d& origin, const Vec2d& translation) override {
    return static_cast<int>(world_.castRay(local(origin), toVec(translation)).results.size());
  }

  int overlapBoxCount(const Vec2d& lower, const Vec2d& upper) override {
    return static_cast<int>(world_.overlapAABB({local(lower), local(upper)}).results.size());
  }

  void countStep() override { passTotals_.add(world_.profile().passes); }
  std::string passes() const override { return passTotals_.describe(); }
  std::string stages() const override { return stageTimes_.describe(); }

 private:
  /// The solver's pass counts summed over the steps.
  struct PassTotals {
    long contacts = 0, supportRows = 0, joints = 0, treeJoints = 0, pushedContacts = 0, quietContacts = 0;
    int steps = 0, pushSteps = 0;

    void add(const impulse::SolverPasses& step) {
      ++steps;
      contacts += step.contacts;
      quietContacts += step.quietContacts;
      supportRows += step.supportRows;
      joints += step.joints;
      treeJoints += step.treeJoints;
      pushedContacts += step.pushedContacts;
      pushSteps += step.pushedContacts > 0 ? 1 : 0;
    }

    std::string describe() const {
      if (steps == 0) return {};
      char text[256];
      if (contacts == 0) {
        std::snprintf(text, sizeof text, "no contacts");
      } else {
        std::snprintf(text, sizeof text,
                      "%.0f contacts a step (%.1f%% quiet: speculative, holding nothing), support %.1f%% of contacts, "
                      "push %.2f%% of contacts in %.1f%% of steps",
                      double(contacts) / steps, percent(quietContacts, contacts), percent(supportRows, contacts),
                      percent(pushedContacts, contacts), percent(pushSteps, steps));
      }
      std::string line = text;
      if (joints == 0) return line + ", no joints";
      std::snprintf(text, sizeof text, ", exact tree %.1f%% of joints", percent(treeJoints, joints));
      return line + text;
    }

    static double percent(long part, long whole) { return 100.0 * double(part) / double(whole); }
  };

  struct Created {
    impulse::BodyId id;
    Vec2 originToCentre;  ///< from the described origin to Impulse's centre of mass, in the body's frame
  };

  void spawnDue() {
    schedule_.spawnDue(
        stepCount_, [this](const BodyDesc& body) { create(body); },
        [this](const JointDesc& joint) { createJoint(joint); });
  }

  void create(const BodyDesc& body) {
    impulse::CreateResult created = body.shape.kind == ShapeKind::Chain ? createChain(body)
                                                                         : world_.createBody(bodyDefFor(scene_, body, world_.settings().shapeLimits));
    if (!created.ok()) throw std::runtime_error("impulse: " + created.error);
    const Vec2 centre = world_.bodyState(created.id)->position;
    bodies_.push_back({created.id, rotate(centre - local(body.position), -Real(body.angle))});
  }

  impulse::CreateResult createChain(const BodyDesc& body) {
    std::vector<Vec2> points;
    for (const Vec2d& v : body.shape.vertices) points.push_back(local(body.position) + rotate(toVec(v), Real(body.angle)));
    return world_.createChain(points, body.shape.loop, optionsFor(body));
  }

  void steer(const KinematicTarget& target, double dt) {
    const Created& body = bodies_[static_cast<std::size_t>(target.body)];
    const Real angle = world_.bodyState(body.id)->angle;
    const Vec2 centre = local(target.position(stepCount_ * dt)) + rotate(body.originToCentre, angle);
    impulse::InputResult steered = world_.setTargetTransform(body.id, centre, angle, Real(dt));
    if (!steered.ok()) throw std::runtime_error("impulse: " + steered.error);
  }

  Vec2 local(const Vec2d& point) const { return world_.toLocal({point.x, point.y}); }

  impulse::BodyId idOf(int index) const {
    return index == kWorldBody ? impulse::BodyId{} : bodies_[static_cast<std::size_t>(index)].id;
  }

  Real inertiaOf(int index) const {
    if (index == kWorldBody) return 0;
    const impulse::BodyDescription body = *world_.bodyDescription(idOf(index));
    return body.properties.isDynamic() ? body.mass.inertia : 0;
  }

  impulse::RevoluteJointSettings pinSettings(const JointDesc& joint) const {
    impulse::RevoluteJointSettings s;
    s.enableLimit = joint.enableLimit;
    s.lowerAngle = Real(joint.lowerAngle);
    s.upperAngle = Real(joint.upperAngle);
    s.enableMotor = joint.enableMotor;
    s.motorSpeed = Real(joint.motorSpeed);
    s.maxMotorTorque = Real(joint.maxMotorTorque);
    if (joint.springHertz > 0) {
      // The pair's relative rotational inertia (a static side counts as infinite).
      const Real iA = inertiaOf(joint.bodyA), iB = inertiaOf(joint.bodyB);
      const Real inertia = iA == 0 ? iB : iB == 0 ? iA : iA * iB / (iA + iB);
      const Real omega = Real(2 * std::numbers::pi * joint.springHertz);
      s.stiffness = inertia * omega * omega;
      s.damping = Real(2 * joint.springDampingRatio) * inertia * omega;
    }
    return s;
  }

  impulse::JointSettings jointSettings(const JointDesc& joint) const {
    switch (joint.kind) {
      case JointKind::Pin: return pinSettings(joint);
      case JointKind::Rod: return impulse::DistanceJointSettings{};
      case JointKind::Spring:
        return impulse::DistanceJointSettings{Real(joint.restLength), Real(joint.stiffness), Real(joint.damping)};
    }
    throw std::logic_error("impulse: unknown joint kind");
  }

  void createJoint(const JointDesc& joint) {
    impulse::JointDef def;
    def.bodyA = idOf(joint.bodyA);
    def.bodyB = idOf(joint.bodyB);
    def.anchorA = local(joint.anchorA);
    def.anchorB = local(joint.anchorB);
    def.settings = jointSettings(joint);
    impulse::JointResult created = world_.createJoint(def);
    if (!created.ok()) throw std::runtime_error("impulse: " + created.error);
  }

  const SceneDescription& scene_;
  impulse::World world_;
  SpawnSchedule schedule_;
  std::vector<Created> bodies_;
  int stepCount_ = 0;
  PassTotals passTotals_;
  StageTimes stageTimes_{{"pairs", "collide", "solve", "continuous", "sleep"}};
};

}  // namespace

std::unique_ptr<EngineAdapter> makeImpulseAdapter(const SceneDescription& scene, int subSteps,
                                                  bool sse2Only, int threads) {
  return std::make_unique<ImpulseAdapter>(scene, subSteps, sse2Only, threads);
}

}  // namespace bench
