// World::importState: a saved state (impulse/world_state.h) checked piece by
// piece and built into fresh private data, which replaces the world's only
// when every check passed. A state may come from anyone over the network, so
// nothing in it is trusted: numbers, shapes, slot indices, free lists, edge
// lists and both broad-phase trees are all checked before they are used.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "body_shapes.h"
#include "input_limits.h"
#include "world_data.h"

namespace impulse {

namespace {

// Ranges of the solver settings a scene may carry (docs/scenes.md).
constexpr int kMaxSubSteps = 64;
constexpr int kMaxRelaxIterations = 64;
constexpr double kMaxRate = 1e4;         // Hz, damping ratios, speeds in m/s
constexpr double kMaxSleepTime = 1e9;    // s
constexpr double kMaxLocalLength = 1e4;  // m, anchors and joint references
constexpr double kMaxImpulse = 1e15;     // N*s, impulses carried for warm starting
constexpr double kMaxCoefficient = 1e3;  // mixed friction, restitution, rolling length
constexpr Real kUnitTolerance = Real(1e-4);

std::string at(const char* kind, std::size_t slot) {
  return std::string(kind) + " " + std::to_string(slot) + ": ";
}

std::string checkVector(const std::string& field, const Vec2& v, double bound) {
  std::string error = checkRange(field + ".x", v.x(), -bound, bound);
  return error.empty() ? checkRange(field + ".y", v.y(), -bound, bound) : error;
}

std::string checkRotation(const std::string& field, const Rot& q) {
  if (isFinite(q.c) && isFinite(q.s) && std::abs(q.c * q.c + q.s * q.s - 1) <= kUnitTolerance)
    return {};
  return field + " must be a unit rotation (cos, sin)";
}

template <class... Errors>
std::string firstOf(const Errors&... errors) {
  std::string result;
  ((result.empty() ? void(result = errors) : void()), ...);
  return result;
}

std::string applySolverSettings(const SolverSettingsState& s, WorldSettings& settings) {
  std::string error =
      firstOf(checkGravity(settings.inputLimits, s.gravity),
              checkRange("subSteps", s.subSteps, 1, kMaxSubSteps),
              checkRange("relaxIterations", s.relaxIterations, 0, kMaxRelaxIterations),
              checkRange("contactHertz", s.contactHertz, 0, kMaxRate),
              checkRange("contactDampingRatio", s.contactDampingRatio, 0, kMaxRate),
              checkRange("maxContactPushSpeed", s.maxContactPushSpeed, 0, kMaxRate),
              checkRange("restitutionThreshold", s.restitutionThreshold, 0, kMaxRate),
              checkRange("stickSpeed", s.stickSpeed, 0, kMaxRate),
              checkRange("linearSleepTolerance", s.linearSleepTolerance, 0, kMaxRate),
              checkRange("timeToSleep", s.timeToSleep, 0, kMaxSleepTime),
              checkRange("hitEventThreshold", s.hitEventThreshold, 0, kMaxRate));
  if (!error.empty()) return "settings: " + error;
  settings.gravity = s.gravity;
  settings.subSteps = s.subSteps;
  settings.relaxIterations = s.relaxIterations;
  settings.contactHertz = s.contactHertz;
  settings.contactDampingRatio = s.contactDampingRatio;
  settings.maxContactPushSpeed = s.maxContactPushSpeed;
  settings.restitutionThreshold = s.restitutionThreshold;
  settings.stickSpeed = s.stickSpeed;
  settings.enableWarmStarting = s.enableWarmStarting;
  settings.enableSleep = s.enableSleep;
  settings.linearSleepTolerance = s.linearSleepTolerance;
  settings.timeToSleep = s.timeToSleep;
  settings.enableContinuous = s.enableContinuous;
  settings.hitEventThreshold = s.hitEventThreshold;
  return {};
}

// A saved polygon is kept as it is (rebuilding it would move its bits), so
// it is checked instead: convex and in range (buildPolygon), anticlockwise
// with each normal the unit outward normal of its edge, its stored centroid
// its centroid.
std::string checkPolygon(const Polygon& polygon, const ShapeLimits& limits) {
  if (polygon.count < 3 || polygon.count > kMaxPolygonVertices) {
    return "polygon must have 3 to " + std::to_string(kMaxPolygonVertices) + " vertices";
  }
  const std::span<const Vec2> vertices(polygon.vertices.data(), std::size_t(polygon.count));
  const PolygonBuild build = buildPolygon(vertices, limits);
  if (build.error != ShapeError::None) return "polygon: " + std::string(describe(build.error));
  const Real extent = computeExtent(Shape::makePolygon(polygon));
  if ((build.centroid - polygon.centroid).norm() > kUnitTolerance * (1 + extent)) {
    return "polygon's stored centroid must be the centroid of its vertices";
  }
  if (ShapeError error = validateShape(Shape::makePolygon(polygon), limits); error != ShapeError::None) {
    return "polygon: " + std::string(describe(error));
  }
  for (int i = 0; i < polygon.count; ++i) {
    const Vec2 edge =
        polygon.vertices[std::size_t((i + 1) % polygon.count)] - polygon.vertices[std::size_t(i)];
    const Vec2 outward = Vec2(edge.y(), -edge.x()).normalized();
    const Vec2& normal = polygon.normals[std::size_t(i)];
    if (!isFinite(normal) || (normal - outward).norm() > kUnitTolerance ||
        normal.dot(polygon.vertices[std::size_t(i)] - polygon.centroid) <= 0) {
      return "polygon normal " + std::to_string(i) +
             " must be the unit outward normal of its edge (vertices anticlockwise)";
    }
  }
  return {};
}

std::string checkShape(const Shape& shape, const ShapeLimits& limits) {
  if (shape.type() == ShapeType::Polygon) return checkPolygon(shape.polygon(), limits);
  const ShapeError error = validateShape(shape, limits);
  return error == ShapeError::None ? std::string() : std::string(describe(error));
}

MaterialOverride coefficientsOf(const ShapeSlotState& s) {
  return {s.density, s.restitution, s.staticFriction, s.dynamicFriction, s.rollingResistance};
}

std::string checkShapeSlot(const WorldSettings& settings, const ShapeSlotState& s) {
  if (static_cast<int>(s.material) >= kMaterialCount) return "unknown material";
  return firstOf(checkShape(s.shape, settings.shapeLimits), validateMaterialOverride(coefficientsOf(s)));
}

// Its geometry goes into the world's pools.
ShapeSlot buildShape(const ShapeSlotState& s, ShapeGeometries& geometries) {
  ShapeSlot shape;
  shape.alive = true;
  shape.generation = s.generation;
  shape.body = s.body;
  geometries.store(shape, s.shape);
  shape.material = s.material;
  shape.coefficients = resolveCoefficients(s.material, coefficientsOf(s));
  shape.rollingRadius = rollingRadiusOf(s.shape);
  shape.interaction = s.interaction;
  shape.proxyKey = s.proxyKey;
  return shape;
}

std::string checkBody(const WorldSettings& settings, const Vec2d& origin, const BodySlotState& b) {
  const InputLimits& limits = settings.inputLimits;
  std::string error =
      firstOf(checkApplicationPoint(limits, settings.bounds, origin, b.transform.p, "position"),
              checkRotation("rotation", b.transform.q),
              checkBodyMotion(limits, b.linearVelocity, b.angularVelocity),
              validateBodyProperties(b.properties),
              checkRange("sleepTime", b.sleepTime, 0, kMaxSleepTime),
              checkApplicationPoint(limits, settings.bounds, origin, b.center0, "center0"),
              checkRotation("rotation0", b.rotation0));
  if (!error.empty()) return error;
  if (b.properties.isStatic && b.awake) return "a static body cannot be awake";
  return {};
}

// Pending forces within the accelerations InputLimits allow for the mass.
std::string checkForces(const InputLimits& limits, const BodySlotState& b,
                        const MassProperties& mass) {
  const double maxForce = b.properties.isStatic ? 0 : double(limits.maxForceAcceleration) * mass.mass;
  const double maxTorque = b.properties.isStatic ? 0 : double(limits.maxTorqueAcceleration) * mass.inertia;
  return firstOf(checkVector("force", b.force, maxForce),
                 checkRange("torque", b.torque, -maxTorque, maxTorque));
}

// The body as createBody would have made it, with the saved motion and
// solver state; its mass comes with its shapes (StateImport::shapes).
Body buildBody(const BodySlotState& b) {
  Body body;
  body.alive = true;
  body.generation = b.generation;
  body.properties() = b.properties;
  body.transform = b.transform;
  body.linearVelocity = b.linearVelocity;
  body.angularVelocity = b.angularVelocity;
  body.force = b.force;
  body.torque = b.torque;
  body.sleepTime = b.sleepTime;
  body.center0 = b.center0;
  body.rotation0 = b.rotation0;
  body.creationOrder = b.creationOrder;
  body.awake = b.awake;
  return body;
}

// A free list must name each free slot once and nothing else.
std::string checkFreeList(const char* kind, const std::vector<std::int32_t>& freeSlots,
                          const std::vector<bool>& alive) {
  std::vector<bool> listed(alive.size(), false);
  std::size_t deadCount = 0;
  for (bool live : alive) deadCount += live ? 0 : 1;
  for (std::int32_t slot : freeSlots) {
    if (slot < 0 || std::size_t(slot) >= alive.size() || alive[std::size_t(slot)] ||
        listed[std::size_t(slot)]) {
      return std::string(kind) + " free list must name each free slot once (bad entry " +
             std::to_string(slot) + ")";
    }
    listed[std::size_t(slot)] = true;
  }
  if (freeSlots.size() != deadCount)
    return std::string(kind) + " free list must name every free slot";
  return {};
}

class StateImport {
 public:
  StateImport(const WorldSettings& limits, const WorldState& state) : state_(state) {
    next_->settings = limits;
  }

  // The stages in order: each relies on the ones before it.
  std::string run() {
    for (auto stage : {&StateImport::settings, &StateImport::bodies, &StateImport::shapes, &StateImport::broadPhase,
                       &StateImport::contacts, &StateImport::joints, &StateImport::fields, &StateImport::edges,
                       &StateImport::awakeList, &StateImport::clock, &StateImport::sensors}) {
      if (std::string error = (this->*stage)(); !error.empty()) return error;
    }
    return {};
  }
  std::unique_ptr<WorldData> take() { return std::move(next_); }

 private:
  std::string settings() {
    if (std::string error = checkOrigin(state_.origin); !error.empty()) return error;
    next_->origin = state_.origin;
    return applySolverSettings(state_.settings, next_->settings);
  }

  // Each field made again from its numbers (so checked as AddField checks
  // them), under its own id.
  std::string fields() {
    WorldData& w = *next_;
    if (state_.nextFieldId == 0) return "nextFieldId must be at least 1";
    std::vector<std::uint32_t> seen;
    for (std::size_t i = 0; i < state_.fields.size(); ++i) {
      const FieldSlotState& f = state_.fields[i];
      if (f.id.value == 0 || f.id.value >= state_.nextFieldId) {
        return at("field", i) + "id must lie within 1..nextFieldId - 1";
      }
      if (std::find(seen.begin(), seen.end(), f.id.value) != seen.end()) return at("field", i) + "id used twice";
      seen.push_back(f.id.value);
      FieldBuild built = makeField(f.def);
      if (!built.ok()) return at("field", i) + built.error;
      w.fields.push_back({f.id, std::move(built.field)});
    }
    w.nextFieldId = state_.nextFieldId;
    return {};
  }

  std::string bodies() {
    WorldData& w = *next_;
    if (state_.bodies.size() > BodyId::kIndexMask) return "too many body slots";
    std::vector<bool> alive;
    for (std::size_t slot = 0; slot < state_.bodies.size(); ++slot) {
      const BodySlotState& b = state_.bodies[slot];
      alive.push_back(b.alive);
      Body body;
      body.generation = b.generation;
      if (b.alive) {
        if (std::string error = checkBody(w.settings, w.origin, b); !error.empty())
          return at("body slot", slot) + error;
        if (b.creationOrder >= state_.nextCreationOrder) {
          return at("body slot", slot) + "creationOrder must be below nextCreationOrder";
        }
        body = buildBody(b);
        ++w.liveBodies;
      }
      w.bodies.push_back(body);
    }
    if (w.liveBodies > w.settings.maxBodies) {
      return "body limit reached (" + std::to_string(w.settings.maxBodies) + " bodies)";
    }
    if (std::string error = checkFreeList("body", state_.freeBodies, alive); !error.empty())
      return error;
    w.freeBodies.assign(state_.freeBodies);
    w.nextCreationOrder = state_.nextCreationOrder;
    return {};
  }

  // Every live shape belongs to a live body, which lists it once; the
  // bodies' masses follow from their shapes.
  std::string shapes() {
    WorldData& w = *next_;
    if (state_.shapes.size() > BodyId::kIndexMask) return "too many shape slots";
    const std::size_t limit = std::size_t(kShapesPerBodyOfLimit) * std::size_t(std::max(w.settings.maxBodies, 0));
    std::vector<bool> alive;
    for (std::size_t slot = 0; slot < state_.shapes.size(); ++slot) {
      const ShapeSlotState& s = state_.shapes[slot];
      alive.push_back(s.alive);
      ShapeSlot shape;
      shape.generation = s.generation;
      if (s.alive) {
        if (!liveBody(s.body)) return at("shape slot", slot) + "body must be a live body";
        if (std::string error = checkShapeSlot(w.settings, s); !error.empty()) return at("shape slot", slot) + error;
        shape = buildShape(s, w.shapeGeometries);
        ++w.liveShapes;
      }
      w.shapes.push_back(shape);
    }
    if (std::size_t(w.liveShapes) > limit) {
      return "shape limit reached (" + std::to_string(limit) + " shapes: " + std::to_string(kShapesPerBodyOfLimit) +
             " per body of the body limit)";
    }
    if (std::string error = checkFreeList("shape", state_.freeShapes, alive); !error.empty()) return error;
    w.freeShapes.assign(state_.freeShapes);
    return linkBodyShapes();
  }

  std::string linkBodyShapes() {
    WorldData& w = *next_;
    std::vector<bool> listed(w.shapes.size(), false);
    for (std::size_t slot = 0; slot < w.bodies.size(); ++slot) {
      if (!w.bodies[slot].alive) continue;
      const BodySlotState& b = state_.bodies[slot];
      if (b.shapes.empty() || b.shapes.size() > std::size_t(kMaxShapesPerBody)) {
        return at("body slot", slot) + "a body has 1 to " + std::to_string(kMaxShapesPerBody) + " shapes";
      }
      std::int32_t* link = &w.bodies[slot].shapeHead;
      for (std::int32_t s : b.shapes) {
        if (s < 0 || std::size_t(s) >= w.shapes.size() || !w.shapes[std::size_t(s)].alive ||
            w.shapes[std::size_t(s)].body != std::int32_t(slot) || listed[std::size_t(s)]) {
          return at("body slot", slot) + "shapes must name its own live shapes, each once";
        }
        listed[std::size_t(s)] = true;
        *link = s;
        link = &w.shapes[std::size_t(s)].nextInBody;
      }
      w.bodies[slot].shapeCount = std::int32_t(b.shapes.size());
      if (std::string error = massFromShapes(std::int32_t(slot)); !error.empty()) return at("body slot", slot) + error;
    }
    return {};
  }

  std::string massFromShapes(std::int32_t slot) {
    WorldData& w = *next_;
    Body& body = w.bodies[std::size_t(slot)];
    const Vec2 center = setMassFromShapes(w, slot);
    if (center.norm() > kUnitTolerance * (1 + body.extent)) {
      return "the shapes' centroid must be the body's origin (shapes are local to the centre of mass)";
    }
    if (!body.isStatic && body.extent > kMaxBodyExtent) {
      return "a moving body's shapes must lie within " + std::to_string(int(kMaxBodyExtent)) + " m of its centre";
    }
    return checkForces(w.settings.inputLimits, state_.bodies[std::size_t(slot)], body.mass);
  }

  // Every live shape owns exactly one leaf, in the tree of its body's kind,
  // whose user value is its slot; no other leaf exists.
  std::string broadPhase() {
    WorldData& w = *next_;
    if (!w.broadPhase.restore(state_.broadPhase)) {
      return "broad phase: a tree is not a valid tree, or the queue names a node that is no leaf";
    }
    if (w.broadPhase.proxyCount() != w.liveShapes) return "broad phase: one leaf per live shape is needed";
    for (std::size_t slot = 0; slot < w.shapes.size(); ++slot) {
      const ShapeSlot& shape = w.shapes[slot];
      if (!shape.alive) continue;
      const bool staticKey = (shape.proxyKey & 1) == static_cast<int>(BroadPhase::ProxyKind::Static);
      if (w.broadPhase.leafUserValue(shape.proxyKey) != std::int32_t(slot) ||
          staticKey != w.bodies[std::size_t(shape.body)].isStatic) {
        return at("shape slot", slot) + "proxyKey must name its own leaf in the tree of its body's kind";
      }
    }
    return {};
  }

  bool liveShape(std::int32_t slot) const {
    return slot >= 0 && std::size_t(slot) < next_->shapes.size() && next_->shapes[std::size_t(slot)].alive;
  }

  bool liveBody(std::int32_t slot) const {
    return slot >= 0 && std::size_t(slot) < next_->bodies.size() &&
           next_->bodies[std::size_t(slot)].alive;
  }

  std::string checkContact(const ContactSlotState& c) const {
    const WorldData& w = *next_;
    if (!liveShape(c.shapeA) || !liveShape(c.shapeB)) return "shapeA and shapeB must be live shapes";
    const ShapeSlot& a = w.shapes[std::size_t(c.shapeA)];
    const ShapeSlot& b = w.shapes[std::size_t(c.shapeB)];
    if (a.body != c.bodyA || b.body != c.bodyB || c.bodyA == c.bodyB) {
      return "bodyA and bodyB must be the shapes' bodies, two different ones";
    }
    if (w.bodies[std::size_t(c.bodyA)].isStatic && w.bodies[std::size_t(c.bodyB)].isStatic) {
      return "two static bodies have no contact";
    }
    if (collideFunction(a.type(), b.type()) == nullptr || !shapesCanCollide(a.type(), b.type())) {
      return "the shapes must collide, in the order the collide table holds their types";
    }
    if (a.interaction.isSensor || b.interaction.isSensor) return "a sensor has no contacts";
    if (!shouldCollide(a.interaction.filter, b.interaction.filter)) return "the shapes' filters keep them apart";
    if (c.manifold.pointCount < 0 || c.manifold.pointCount > 2)
      return "a manifold has 0 to 2 points";
    std::string error =
        firstOf(checkVector("normal", c.manifold.normal, 2),
                checkRange("rollingImpulse", c.manifold.rollingImpulse, -kMaxImpulse, kMaxImpulse),
                checkVector("frame.relative.p", c.frame.relative.p, kMaxLocalLength),
                checkRotation("frame.relative.q", c.frame.relative.q),
                checkVector("frame.localNormal", c.frame.localNormal, 2),
                checkRange("staticFriction", c.staticFriction, 0, kMaxCoefficient),
                checkRange("dynamicFriction", c.dynamicFriction, 0, kMaxCoefficient),
                checkRange("restitution", c.restitution, 0, kMaxCoefficient),
                checkRange("rollingResistance", c.rollingResistance, 0, kMaxCoefficient));
    for (int i = 0; i < 2 && error.empty(); ++i) {
      const ManifoldPoint& p = c.manifold.points[std::size_t(i)];
      error =
          firstOf(checkVector("point", p.point, kMaxLocalLength),
                  checkVector("anchorA", p.anchorA, kMaxLocalLength),
                  checkVector("anchorB", p.anchorB, kMaxLocalLength),
                  checkRange("separation", p.separation, -kMaxLocalLength, kMaxLocalLength),
                  checkRange("normalImpulse", p.normalImpulse, -kMaxImpulse, kMaxImpulse),
                  checkRange("tangentImpulse", p.tangentImpulse, -kMaxImpulse, kMaxImpulse),
                  checkRange("supportImpulse", p.supportImpulse, 0, kMaxImpulse),
                  checkVector("frame.localPointA", c.frame.localPointA[i], kMaxLocalLength),
                  checkVector("frame.localPointB", c.frame.localPointB[i], kMaxLocalLength),
                  checkRange("frame.offset", c.frame.offset[i], -kMaxLocalLength, kMaxLocalLength));
    }
    return error;
  }

  std::string contacts() {
    WorldData& w = *next_;
    std::vector<bool> alive;
    for (std::size_t slot = 0; slot < state_.contacts.size(); ++slot) {
      const ContactSlotState& c = state_.contacts[slot];
      alive.push_back(c.alive);
      Contact contact;
      if (c.alive) {
        if (std::string error = checkContact(c); !error.empty())
          return at("contact slot", slot) + error;
        contact.edges.bodyA = c.bodyA;
        contact.edges.bodyB = c.bodyB;
        setContactShapes(contact, c.shapeA, w.shapes[std::size_t(c.shapeA)], c.shapeB,
                         w.shapes[std::size_t(c.shapeB)]);
        contact.manifold = c.manifold;
        contact.frame = c.frame;
        contact.staticFriction = c.staticFriction;
        contact.dynamicFriction = c.dynamicFriction;
        contact.restitution = c.restitution;
        contact.rollingResistance = c.rollingResistance;
        contact.touching = c.touching;
        setContactEventFlags(w, contact);
        if (!w.contactByPair.insert(contact.pairKey)) {
          return at("contact slot", slot) + "a pair of shapes has one contact";
        }
      }
      w.contacts.push_back(contact);
    }
    if (std::string error = checkFreeList("contact", state_.freeContacts, alive); !error.empty())
      return error;
    w.freeContacts.assign(state_.freeContacts);
    return {};
  }

  std::string checkJoint(const JointSlotState& j) const {
    const WorldData& w = *next_;
    if (!liveBody(j.bodyA)) return "bodyA must be a live body (a joint on a missing body)";
    if (j.bodyB != kNullIndex && (!liveBody(j.bodyB) || j.bodyB == j.bodyA)) {
      return "bodyB must be another live body or the world (-1)";
    }
    const bool staticA = w.bodies[std::size_t(j.bodyA)].isStatic;
    if (staticA && (j.bodyB == kNullIndex || w.bodies[std::size_t(j.bodyB)].isStatic)) {
      return "a joint needs a dynamic body";
    }
    const JointImpulses& i = j.impulses;
    return firstOf(
        checkJointSettings(j.settings),
        checkVector("localAnchorA", j.localAnchorA, kMaxLocalLength),
        checkVector("localAnchorB", j.localAnchorB,
                    kMaxLocalLength + w.settings.inputLimits.escapeMargin),
        checkVector("localAxisA", j.localAxisA, 2),
        checkRange("referenceAngle", j.referenceAngle, -4, 4),
        checkRange("referenceTranslation", j.referenceTranslation, -kMaxLocalLength,
                   kMaxLocalLength),
        checkRange("referencePerpendicular", j.referencePerpendicular, -kMaxLocalLength,
                   kMaxLocalLength),
        checkRange("length", j.length, 0, kMaxLocalLength),
        checkApplicationPoint(w.settings.inputLimits, w.settings.bounds, w.origin, j.target, "target"),
        checkVector("impulses.point", i.point, kMaxImpulse),
        checkVector("impulses.pointSpring", i.pointSpring, kMaxImpulse),
        checkRange("impulses.perpendicular", i.perpendicular, -kMaxImpulse, kMaxImpulse),
        checkRange("impulses.angular", i.angular, -kMaxImpulse, kMaxImpulse),
        checkRange("impulses.axial", i.axial, -kMaxImpulse, kMaxImpulse),
        checkRange("impulses.spring", i.spring, -kMaxImpulse, kMaxImpulse),
        checkRange("impulses.motor", i.motor, -kMaxImpulse, kMaxImpulse),
        checkRange("impulses.lower", i.lower, -kMaxImpulse, kMaxImpulse),
        checkRange("impulses.upper", i.upper, -kMaxImpulse, kMaxImpulse),
        checkVector("reactionForce", j.reactionForce, kMaxImpulse),
        checkRange("reactionTorque", j.reactionTorque, -kMaxImpulse, kMaxImpulse));
  }

  std::string joints() {
    WorldData& w = *next_;
    if (state_.joints.size() > BodyId::kIndexMask) return "too many joint slots";
    std::vector<bool> alive;
    for (std::size_t slot = 0; slot < state_.joints.size(); ++slot) {
      const JointSlotState& j = state_.joints[slot];
      alive.push_back(j.alive);
      Joint joint;
      joint.generation = j.generation;
      if (j.alive) {
        if (std::string error = checkJoint(j); !error.empty())
          return at("joint slot", slot) + error;
        joint.edges.bodyA = j.bodyA;
        joint.edges.bodyB = j.bodyB;
        joint.settings = j.settings;
        joint.localAnchorA = j.localAnchorA;
        joint.localAnchorB = j.localAnchorB;
        joint.localAxisA = j.localAxisA;
        joint.referenceAngle = j.referenceAngle;
        joint.referenceTranslation = j.referenceTranslation;
        joint.referencePerpendicular = j.referencePerpendicular;
        joint.length = j.length;
        joint.target = j.target;
        joint.impulses = j.impulses;
        joint.reactionForce = j.reactionForce;
        joint.reactionTorque = j.reactionTorque;
        joint.collideConnected = j.collideConnected;
        joint.alive = true;
        ++w.liveJoints;
      }
      w.joints.push_back(joint);
    }
    if (std::string error = checkFreeList("joint", state_.freeJoints, alive); !error.empty())
      return error;
    w.freeJoints.assign(state_.freeJoints);
    return {};
  }

  // Links one body's saved list: each key names a live element whose side
  // is this body, each (element, side) once over all bodies. Linking at the
  // front, last key first, rebuilds the saved order.
  template <class Elements>
  std::string linkList(Elements& elements, std::vector<bool>& seen, std::int32_t slot,
                       const std::vector<std::int32_t>& keys, std::int32_t& head,
                       const char* kind) {
    for (std::int32_t key : keys) {
      const std::int32_t element = edgeElement(key);
      if (key < 0 || std::size_t(element) >= elements.size() || seen[std::size_t(key)] ||
          !isLive(elements, element) ||
          elements[std::size_t(element)].edges.body(edgeSide(key)) != slot) {
        return at("body slot", std::size_t(slot)) + kind + " edge " + std::to_string(key) +
               " must name a live element of this body, once";
      }
      seen[std::size_t(key)] = true;
    }
    for (auto key = keys.rbegin(); key != keys.rend(); ++key) {
      linkEdge(elements, head, edgeElement(*key), edgeSide(*key));
    }
    return {};
  }

  bool isLive(const std::vector<Contact>&, std::int32_t element) const {
    return state_.contacts[std::size_t(element)].alive;
  }
  bool isLive(const std::vector<Joint>& joints, std::int32_t element) const {
    return joints[std::size_t(element)].alive;
  }

  std::string edges() {
    WorldData& w = *next_;
    std::vector<bool> contactSeen(w.contacts.size() * 2, false);
    std::vector<bool> jointSeen(w.joints.size() * 2, false);
    for (std::size_t slot = 0; slot < w.bodies.size(); ++slot) {
      const BodySlotState& b = state_.bodies[slot];
      if (!b.alive && (!b.contactEdges.empty() || !b.jointEdges.empty())) {
        return at("body slot", slot) + "a free slot has no edges";
      }
      Body& body = w.bodies[slot];
      std::string error = firstOf(
          linkList(w.contacts, contactSeen, std::int32_t(slot), b.contactEdges, body.contactHead,
                   "contact"),
          linkList(w.joints, jointSeen, std::int32_t(slot), b.jointEdges, body.jointHead, "joint"));
      if (!error.empty()) return error;
    }
    return firstOf(
        allLinked(
            contactSeen, "contact",
            [&](std::size_t key) { return isLive(w.contacts, edgeElement(std::int32_t(key))); }),
        allLinked(jointSeen, "joint", [&](std::size_t key) {
          const Joint& joint = w.joints[std::size_t(edgeElement(std::int32_t(key)))];
          return joint.alive && joint.edges.body(edgeSide(std::int32_t(key))) != kNullIndex;
        }));
  }

  template <class Linkable>
  static std::string allLinked(const std::vector<bool>& seen, const char* kind,
                               Linkable&& linkable) {
    for (std::size_t key = 0; key < seen.size(); ++key) {
      if (!seen[key] && linkable(key)) {
        return std::string(kind) + " " + std::to_string(key / 2) +
               " is missing from a body's edge list";
      }
    }
    return {};
  }

  // The awake list names each awake body once, and only them.
  std::string awakeList() {
    WorldData& w = *next_;
    std::vector<bool> listed(w.bodies.size(), false);
    for (std::int32_t slot : state_.awakeBodies) {
      if (!liveBody(slot) || !w.bodies[std::size_t(slot)].awake || listed[std::size_t(slot)]) {
        return "awake list must name each awake body once (bad entry " + std::to_string(slot) + ")";
      }
      listed[std::size_t(slot)] = true;
    }
    for (std::size_t slot = 0; slot < w.bodies.size(); ++slot) {
      if (w.bodies[slot].awake && !listed[slot])
        return at("body slot", slot) + "awake but not in the awake list";
    }
    w.awakeBodies = state_.awakeBodies;
    for (std::int32_t slot : w.awakeBodies) activateBodyContacts(w, slot);
    return {};
  }

  std::string clock() {
    if (!std::isfinite(state_.time) || state_.time < 0) return "time must be a finite number >= 0";
    next_->stepCount = state_.stepCount;
    next_->time = state_.time;
    return {};
  }

  // Sensors see what the saved world's sensors saw after its last step.
  std::string sensors() {
    rebuildSensors(*next_);
    return {};
  }

  const WorldState& state_;
  std::unique_ptr<WorldData> next_ = std::make_unique<WorldData>();
};

}  // namespace

InputResult World::importState(const WorldState& state) {
  StateImport import(impl_->settings, state);
  if (std::string error = import.run(); !error.empty()) return {"scene refused: " + error};
  replaceContents(import.take());
  return {};
}

}  // namespace impulse
