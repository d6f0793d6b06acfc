// World::importState: a saved state (impulse/world_state.h) checked piece by
// piece and built into fresh private data, which replaces the world's only
// when every check passed. A state may come from anyone over the network, so
// nothing in it is trusted: numbers, shapes, slot indices, free lists, edge
// lists and both broad-phase trees are all checked before they are used.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

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
              checkRange("timeToSleep", s.timeToSleep, 0, kMaxSleepTime));
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
  return {};
}

// A saved polygon is kept as it is (rebuilding it would move its bits), so
// it is checked instead: convex and in range (buildPolygon), anticlockwise
// with each normal the unit outward normal of its edge, centroid at the
// origin.
std::string checkPolygon(const Polygon& polygon, const ShapeLimits& limits) {
  if (polygon.count < 3 || polygon.count > kMaxPolygonVertices) {
    return "polygon must have 3 to " + std::to_string(kMaxPolygonVertices) + " vertices";
  }
  const std::span<const Vec2> vertices(polygon.vertices.data(), std::size_t(polygon.count));
  const PolygonBuild build = buildPolygon(vertices, limits);
  if (build.error != ShapeError::None) return "polygon: " + std::string(describe(build.error));
  const Real extent = computeExtent(Shape::makePolygon(polygon));
  if (build.centroid.norm() > kUnitTolerance * (1 + extent)) {
    return "polygon's centroid must be at the body's origin (vertices are local to the centre of "
           "mass)";
  }
  for (int i = 0; i < polygon.count; ++i) {
    const Vec2 edge =
        polygon.vertices[std::size_t((i + 1) % polygon.count)] - polygon.vertices[std::size_t(i)];
    const Vec2 outward = Vec2(edge.y(), -edge.x()).normalized();
    const Vec2& normal = polygon.normals[std::size_t(i)];
    if (!isFinite(normal) || (normal - outward).norm() > kUnitTolerance ||
        normal.dot(polygon.vertices[std::size_t(i)]) <= 0) {
      return "polygon normal " + std::to_string(i) +
             " must be the unit outward normal of its edge (vertices anticlockwise)";
    }
  }
  return {};
}

std::string checkShape(const Shape& shape, const ShapeLimits& limits) {
  if (shape.type == ShapeType::Circle) {
    const ShapeError error = validateCircle(shape.circle.radius, limits);
    return error == ShapeError::None ? std::string() : "circle: " + std::string(describe(error));
  }
  return checkPolygon(shape.polygon, limits);
}

MaterialOverride coefficientsOf(const BodySlotState& b) {
  return {b.density, b.restitution, b.staticFriction, b.dynamicFriction, b.rollingResistance};
}

std::string checkBody(const WorldSettings& settings, const BodySlotState& b) {
  const InputLimits& limits = settings.inputLimits;
  if (static_cast<int>(b.material) >= kMaterialCount) return "unknown material";
  std::string error =
      firstOf(checkShape(b.shape, settings.shapeLimits),
              checkApplicationPoint(limits, settings.bounds, b.transform.p, "position"),
              checkRotation("rotation", b.transform.q),
              checkBodyMotion(limits, b.linearVelocity, b.angularVelocity),
              validateMaterialOverride(coefficientsOf(b)),
              checkRange("linearDrag", b.linearDrag, 0, kMaxRate),
              checkRange("angularDrag", b.angularDrag, 0, kMaxRate),
              checkRange("gravityScale", b.gravityScale, -kMaxGravityScale, kMaxGravityScale),
              checkRange("sleepTime", b.sleepTime, 0, kMaxSleepTime),
              checkApplicationPoint(limits, settings.bounds, b.center0, "center0"),
              checkRotation("rotation0", b.rotation0));
  if (!error.empty()) return error;
  if (b.isStatic && b.awake) return "a static body cannot be awake";
  return {};
}

// Pending forces within the accelerations InputLimits allow for the mass.
std::string checkForces(const InputLimits& limits, const BodySlotState& b,
                        const MassProperties& mass) {
  const double maxForce = b.isStatic ? 0 : double(limits.maxForceAcceleration) * mass.mass;
  const double maxTorque = b.isStatic ? 0 : double(limits.maxTorqueAcceleration) * mass.inertia;
  return firstOf(checkVector("force", b.force, maxForce),
                 checkRange("torque", b.torque, -maxTorque, maxTorque));
}

// The body as createBody would have made it, with the saved motion and
// solver state.
Body buildBody(const WorldSettings& settings, const BodySlotState& b, std::string& error) {
  Body body;
  body.alive = true;
  body.generation = b.generation;
  body.isStatic = b.isStatic;
  body.ignoreGravity = b.ignoreGravity;
  body.material = b.material;
  body.coefficients = resolveCoefficients(b.material, coefficientsOf(b));
  body.transform = b.transform;
  body.linearVelocity = b.linearVelocity;
  body.angularVelocity = b.angularVelocity;
  body.force = b.force;
  body.torque = b.torque;
  body.linearDrag = b.linearDrag;
  body.gravityScale = b.gravityScale;
  body.angularDrag = b.angularDrag;
  body.sleepTime = b.sleepTime;
  body.center0 = b.center0;
  body.rotation0 = b.rotation0;
  body.proxyKey = b.proxyKey;
  body.creationOrder = b.creationOrder;
  body.awake = b.awake;
  body.mass = computeMassProperties(b.shape, body.coefficients.density);
  if (body.isStatic) {
    body.mass.mass = 0;
    body.mass.inertia = 0;
  } else {
    body.invMass = body.mass.mass > 0 ? 1 / body.mass.mass : 0;
    body.invInertia = body.mass.inertia > 0 ? 1 / body.mass.inertia : 0;
  }
  body.extent = computeExtent(b.shape);
  body.innerRadius = computeInnerRadius(b.shape);
  error = checkForces(settings.inputLimits, b, body.mass);
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
    for (auto stage : {&StateImport::settings, &StateImport::bodies, &StateImport::broadPhase,
                       &StateImport::contacts, &StateImport::joints, &StateImport::fields, &StateImport::edges,
                       &StateImport::awakeList, &StateImport::clock}) {
      if (std::string error = (this->*stage)(); !error.empty()) return error;
    }
    return {};
  }
  std::unique_ptr<WorldData> take() { return std::move(next_); }

 private:
  std::string settings() { return applySolverSettings(state_.settings, next_->settings); }

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
        if (std::string error = checkBody(w.settings, b); !error.empty())
          return at("body slot", slot) + error;
        if (b.creationOrder >= state_.nextCreationOrder) {
          return at("body slot", slot) + "creationOrder must be below nextCreationOrder";
        }
        std::string error;
        body = buildBody(w.settings, b, error);
        if (!error.empty()) return at("body slot", slot) + error;
        ++w.liveBodies;
      }
      w.bodies.push_back(body);
      w.shapes.push_back(b.alive ? b.shape : Shape{});
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

  // Every live body owns exactly one leaf, in the tree of its kind, whose
  // user value is its slot; no other leaf exists.
  std::string broadPhase() {
    WorldData& w = *next_;
    if (!w.broadPhase.restore(state_.broadPhase)) {
      return "broad phase: a tree is not a valid tree, or the queue names a node that is no leaf";
    }
    if (w.broadPhase.proxyCount() != w.liveBodies)
      return "broad phase: one leaf per live body is needed";
    for (std::size_t slot = 0; slot < w.bodies.size(); ++slot) {
      const Body& body = w.bodies[slot];
      if (!body.alive) continue;
      const bool staticKey = (body.proxyKey & 1) == static_cast<int>(BroadPhase::ProxyKind::Static);
      if (w.broadPhase.leafUserValue(body.proxyKey) != std::int32_t(slot) ||
          staticKey != body.isStatic) {
        return at("body slot", slot) + "proxyKey must name its own leaf in the tree of its kind";
      }
    }
    return {};
  }

  bool liveBody(std::int32_t slot) const {
    return slot >= 0 && std::size_t(slot) < next_->bodies.size() &&
           next_->bodies[std::size_t(slot)].alive;
  }

  std::string checkContact(const ContactSlotState& c) const {
    const WorldData& w = *next_;
    if (!liveBody(c.bodyA) || !liveBody(c.bodyB) || c.bodyA == c.bodyB) {
      return "bodyA and bodyB must be two live bodies";
    }
    if (w.bodies[std::size_t(c.bodyA)].isStatic && w.bodies[std::size_t(c.bodyB)].isStatic) {
      return "two static bodies have no contact";
    }
    if (collideFunction(w.shapes[std::size_t(c.bodyA)].type, w.shapes[std::size_t(c.bodyB)].type) ==
        nullptr) {
      return "bodyA's shape must be the polygon when the shapes differ";
    }
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
        contact.manifold = c.manifold;
        contact.frame = c.frame;
        contact.collide = collideFunction(w.shapes[std::size_t(c.bodyA)].type,
                                          w.shapes[std::size_t(c.bodyB)].type);
        contact.staticFriction = c.staticFriction;
        contact.dynamicFriction = c.dynamicFriction;
        contact.restitution = c.restitution;
        contact.rollingResistance = c.rollingResistance;
        contact.pairKey = contactPairKey(c.bodyA, c.bodyB);
        contact.touching = c.touching;
        if (!w.contactByPair.emplace(contact.pairKey, std::int32_t(slot)).second) {
          return at("contact slot", slot) + "a pair of bodies has one contact";
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
        checkApplicationPoint(w.settings.inputLimits, w.settings.bounds, j.target, "target"),
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

  const WorldState& state_;
  std::unique_ptr<WorldData> next_ = std::make_unique<WorldData>();
};

}  // namespace

InputResult World::importState(const WorldState& state) {
  StateImport import(impl_->settings, state);
  if (std::string error = import.run(); !error.empty()) return {"scene refused: " + error};
  impl_ = import.take();
  guard_.escaped.clear();
  return {};
}

}  // namespace impulse
