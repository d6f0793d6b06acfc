// WorldState <-> Scene, field by field. Engine floats travel as proto
// floats, so both directions are bit-exact; what the engine must judge
// (ranges, shapes, links) is left to World::importState.

#include "impulse/wire/scene_convert.h"

#include "impulse/wire/field_convert.h"

#include "body_properties.h"

#include <algorithm>
#include <string>
#include <type_traits>

namespace impulse::wire {

namespace {

// ------------------------------------------------------------ engine -> wire

void put(const Vec2& v, v1::SceneVec2* out) {
  out->set_x(v.x());
  out->set_y(v.y());
}

void put(const Rot& q, v1::SceneRotation* out) {
  out->set_c(q.c);
  out->set_s(q.s);
}

Vec2 get(const v1::SceneVec2& v) { return Vec2(v.x(), v.y()); }
Rot get(const v1::SceneRotation& q) { return {q.c(), q.s()}; }

// ------------------------------------------------------------ field tables
// The plain fields of each state struct and its scene message, one row
// (engine member, wire field) each, expanded into both directions by
// IMPULSE_PUT_FIELD and IMPULSE_GET_FIELD: a field the state gains is a
// row here. Fields that need a check, a cast or a list are converted by
// hand below.

// clang-format off
#define IMPULSE_SETTINGS_FIELDS(FIELD)                                          \
  FIELD(gravity, gravity) FIELD(subSteps, sub_steps)                            \
  FIELD(relaxIterations, relax_iterations) FIELD(contactHertz, contact_hertz)   \
  FIELD(contactDampingRatio, contact_damping_ratio)                             \
  FIELD(maxContactPushSpeed, max_contact_push_speed)                            \
  FIELD(restitutionThreshold, restitution_threshold) FIELD(stickSpeed, stick_speed) \
  FIELD(enableWarmStarting, enable_warm_starting) FIELD(enableSleep, enable_sleep) \
  FIELD(linearSleepTolerance, linear_sleep_tolerance) FIELD(timeToSleep, time_to_sleep) \
  FIELD(enableContinuous, enable_continuous) FIELD(hitEventThreshold, hit_event_threshold)

// The body's own properties (gravity scale, drags, type flags) are rows of
// IMPULSE_BODY_PROPERTIES (body_properties.h).
#define IMPULSE_BODY_FIELDS(FIELD)                                              \
  FIELD(transform.p, position) FIELD(transform.q, rotation)                     \
  FIELD(linearVelocity, velocity) FIELD(angularVelocity, angular_velocity)      \
  FIELD(force, force) FIELD(torque, torque) FIELD(sleepTime, sleep_time)        \
  FIELD(center0, start_center) FIELD(rotation0, start_rotation)                 \
  FIELD(creationOrder, creation_order) FIELD(awake, awake)

#define IMPULSE_CONTACT_FIELDS(FIELD)                                           \
  FIELD(shapeA, shape_a) FIELD(shapeB, shape_b) FIELD(bodyA, body_a) FIELD(bodyB, body_b) \
  FIELD(manifold.normal, normal) FIELD(manifold.rollingImpulse, rolling_impulse) \
  FIELD(frame.computed, frame_computed) FIELD(frame.relative.p, frame_relative_position) \
  FIELD(frame.relative.q, frame_relative_rotation) FIELD(frame.localNormal, frame_normal) \
  FIELD(staticFriction, static_friction) FIELD(dynamicFriction, dynamic_friction) \
  FIELD(restitution, restitution) FIELD(rollingResistance, rolling_resistance)  \
  FIELD(touching, touching)

#define IMPULSE_MANIFOLD_POINT_FIELDS(FIELD)                                    \
  FIELD(point, point) FIELD(anchorA, anchor_a) FIELD(anchorB, anchor_b)         \
  FIELD(separation, separation) FIELD(normalImpulse, normal_impulse)            \
  FIELD(tangentImpulse, tangent_impulse) FIELD(supportImpulse, support_impulse)

#define IMPULSE_JOINT_FIELDS(FIELD)                                             \
  FIELD(bodyA, body_a) FIELD(bodyB, body_b)                                     \
  FIELD(localAnchorA, local_anchor_a) FIELD(localAnchorB, local_anchor_b)       \
  FIELD(localAxisA, local_axis_a) FIELD(referenceAngle, reference_angle)        \
  FIELD(referenceTranslation, reference_translation)                            \
  FIELD(referencePerpendicular, reference_perpendicular) FIELD(length, length)  \
  FIELD(target, target) FIELD(reactionForce, reaction_force)                    \
  FIELD(reactionTorque, reaction_torque) FIELD(collideConnected, collide_connected)

#define IMPULSE_JOINT_IMPULSE_FIELDS(FIELD)                                     \
  FIELD(point, point) FIELD(pointSpring, point_spring)                          \
  FIELD(perpendicular, perpendicular) FIELD(angular, angular) FIELD(axial, axial) \
  FIELD(spring, spring) FIELD(motor, motor) FIELD(lower, lower) FIELD(upper, upper)

#define IMPULSE_TREE_NODE_FIELDS(FIELD)                                         \
  FIELD(box.lower, lower) FIELD(box.upper, upper) FIELD(parent, parent)         \
  FIELD(child1, child1) FIELD(child2, child2) FIELD(userValue, user_value)
// clang-format on

template <class Value>
constexpr bool kIsSceneMessage = std::is_same_v<Value, Vec2> || std::is_same_v<Value, Rot>;

// Engine `value` into a field: a vector or rotation into its message, a
// number or flag set as it is. The accessors are generic lambdas, so only
// the one that applies is instantiated.
template <class Value, class Message, class Mutable, class Set>
void putField(const Value& value, Message& out, Mutable mutableField, Set setField) {
  if constexpr (kIsSceneMessage<Value>) {
    put(value, mutableField(out));
  } else {
    setField(out, value);
  }
}

// A field into engine `value`. An optional number left out keeps the
// state's default (a scene written before the field existed).
template <class Message, class Value, class Get, class Has>
void getField(const Message& in, Value& value, Get field, Has present) {
  if constexpr (kIsSceneMessage<Value>) {
    value = get(field(in));
  } else if (present(in)) {
    value = static_cast<Value>(field(in));
  }
}

#define IMPULSE_PUT_FIELD(member, field)                                                          \
  putField(in.member, out, [](auto& message) { return message.mutable_##field(); },              \
           [](auto& message, auto value) { message.set_##field(value); });
#define IMPULSE_GET_FIELD(member, field)                                                          \
  getField(in, out.member, [](const auto& message) -> decltype(auto) { return message.field(); }, \
           [](const auto& message) {                                                              \
             if constexpr (requires { message.has_##field(); }) return message.has_##field();     \
             else return true;                                                                    \
           });

void putSettings(const SolverSettingsState& in, v1::SceneSettings& out) { IMPULSE_SETTINGS_FIELDS(IMPULSE_PUT_FIELD) }

void put(const Segment& segment, v1::SceneSegment* out) {
  put(segment.point1, out->mutable_point1());
  put(segment.point2, out->mutable_point2());
}

void putGeometry(const Shape& shape, v1::SceneShape* out) {
  switch (shape.type()) {
    case ShapeType::Circle:
      put(shape.circle().center, out->mutable_circle()->mutable_center());
      out->mutable_circle()->set_radius(shape.circle().radius);
      return;
    case ShapeType::Capsule:
      put(shape.capsule().center1, out->mutable_capsule()->mutable_center1());
      put(shape.capsule().center2, out->mutable_capsule()->mutable_center2());
      out->mutable_capsule()->set_radius(shape.capsule().radius);
      return;
    case ShapeType::Segment: put(shape.segment(), out->mutable_segment()); return;
    case ShapeType::Polygon: {
      v1::ScenePolygon* polygon = out->mutable_polygon();
      for (int i = 0; i < shape.polygon().count; ++i) {
        put(shape.polygon().vertices[std::size_t(i)], polygon->add_vertices());
        put(shape.polygon().normals[std::size_t(i)], polygon->add_normals());
      }
      put(shape.polygon().centroid, polygon->mutable_centroid());
      polygon->set_radius(shape.polygon().radius);
      return;
    }
    case ShapeType::ChainSegment: {
      const ChainSegment& chain = shape.chainSegment();
      put(chain.ghost1, out->mutable_chain_segment()->mutable_ghost1());
      put(chain.segment, out->mutable_chain_segment()->mutable_segment());
      put(chain.ghost2, out->mutable_chain_segment()->mutable_ghost2());
      out->mutable_chain_segment()->set_chain_id(chain.chainId);
      return;
    }
  }
}

void putShape(const ShapeSlotState& s, v1::SceneShape* out) {
  out->set_alive(s.alive);
  out->set_generation(s.generation);
  if (!s.alive) return;
  out->set_body(s.body);
  putGeometry(s.shape, out);
  out->set_material(toWire(s.material));
  putCoefficients(s, *out);
  out->set_proxy_key(s.proxyKey);
  toWire(s.interaction, out->mutable_flags());
}

void putBody(const BodySlotState& in, v1::SceneBody& out) {
  out.set_alive(in.alive);
  out.set_generation(in.generation);
  if (!in.alive) return;
  for (std::int32_t shape : in.shapes) out.add_shapes(shape);
  IMPULSE_BODY_FIELDS(IMPULSE_PUT_FIELD)
  putSceneBodyProperties(in.properties, out);
  for (std::int32_t key : in.contactEdges) out.add_contact_edges(key);
  for (std::int32_t key : in.jointEdges) out.add_joint_edges(key);
}

void putManifoldPoint(const ManifoldPoint& in, const ManifoldFrame& frame, int i, v1::SceneManifoldPoint& out) {
  IMPULSE_MANIFOLD_POINT_FIELDS(IMPULSE_PUT_FIELD)
  out.set_feature(in.id);
  put(frame.localPointA[i], out.mutable_frame_point_a());
  put(frame.localPointB[i], out.mutable_frame_point_b());
  out.set_frame_offset(frame.offset[i]);
}

void putContact(const ContactSlotState& in, v1::SceneContact& out) {
  out.set_alive(in.alive);
  if (!in.alive) return;
  IMPULSE_CONTACT_FIELDS(IMPULSE_PUT_FIELD)
  for (int i = 0; i < in.manifold.pointCount; ++i) {
    putManifoldPoint(in.manifold.points[std::size_t(i)], in.frame, i, *out.add_points());
  }
}

void putImpulses(const JointImpulses& in, v1::SceneJointImpulses& out) {
  IMPULSE_JOINT_IMPULSE_FIELDS(IMPULSE_PUT_FIELD)
}

void putJoint(const JointSlotState& in, v1::SceneJoint& out) {
  out.set_alive(in.alive);
  out.set_generation(in.generation);
  if (!in.alive) return;
  toWire(in.settings, &out);
  IMPULSE_JOINT_FIELDS(IMPULSE_PUT_FIELD)
  putImpulses(in.impulses, *out.mutable_impulses());
}

void putTreeNode(const DynamicTree::Node& in, v1::SceneTreeNode& out) {
  IMPULSE_TREE_NODE_FIELDS(IMPULSE_PUT_FIELD)
  out.set_height(in.height);
}

void putTree(const DynamicTree::State& tree, v1::SceneTree* out) {
  for (const DynamicTree::Node& node : tree.nodes) putTreeNode(node, *out->add_nodes());
  out->set_root(tree.root);
  out->set_free_list(tree.freeList);
  out->set_leaf_count(tree.leafCount);
}

template <class Repeated>
void putSlots(const std::vector<std::int32_t>& slots, Repeated* out) {
  out->Add(slots.begin(), slots.end());
}

// ------------------------------------------------------------ wire -> engine

SolverSettingsState getSettings(const v1::SceneSettings& in) {
  SolverSettingsState out;
  IMPULSE_SETTINGS_FIELDS(IMPULSE_GET_FIELD)
  return out;
}

Segment get(const v1::SceneSegment& s) { return {get(s.point1()), get(s.point2())}; }

std::string getPolygon(const v1::ScenePolygon& p, Shape& shape) {
  if (p.vertices_size() < 3 || p.vertices_size() > kMaxPolygonVertices || p.normals_size() != p.vertices_size()) {
    return "polygon must have 3 to " + std::to_string(kMaxPolygonVertices) + " vertices, a normal each";
  }
  Polygon polygon;
  polygon.count = p.vertices_size();
  for (int i = 0; i < polygon.count; ++i) {
    polygon.vertices[std::size_t(i)] = get(p.vertices(i));
    polygon.normals[std::size_t(i)] = get(p.normals(i));
  }
  polygon.centroid = get(p.centroid());
  polygon.radius = p.radius();
  shape = Shape::makePolygon(polygon);
  return {};
}

std::string getGeometry(const v1::SceneShape& in, Shape& shape) {
  switch (in.geometry_case()) {
    case v1::SceneShape::kCircle:
      shape = Shape::makeCircle(in.circle().radius(), get(in.circle().center()));
      return {};
    case v1::SceneShape::kCapsule:
      shape = Shape::makeCapsule(get(in.capsule().center1()), get(in.capsule().center2()), in.capsule().radius());
      return {};
    case v1::SceneShape::kSegment:
      shape = Shape{get(in.segment())};
      return {};
    case v1::SceneShape::kPolygon: return getPolygon(in.polygon(), shape);
    case v1::SceneShape::kChainSegment: {
      const v1::SceneChainSegment& c = in.chain_segment();
      shape = Shape{ChainSegment{get(c.ghost1()), get(c.segment()), get(c.ghost2()), c.chain_id()}};
      return {};
    }
    case v1::SceneShape::GEOMETRY_NOT_SET: break;
  }
  return "a live shape needs a geometry (circle, capsule, segment, polygon or chain_segment)";
}

// A shape's material, coefficients and proxy: fields of the same names in a
// SceneShape (version 3) and a SceneBody (versions 1-2, its one shape).
template <class Message>
std::string getMaterial(const Message& in, ShapeSlotState& s) {
  const std::optional<Material> material = materialFromWire(in.material());
  if (!material) return "material must be one of the Material enum";
  s.material = *material;
  getCoefficients(in, s);
  s.proxyKey = in.proxy_key();
  return {};
}

std::string getShape(const v1::SceneShape& in, ShapeSlotState& s) {
  s.alive = in.alive();
  s.generation = in.generation();
  if (!s.alive) return {};
  if (std::string error = getGeometry(in, s.shape); !error.empty()) return error;
  s.body = in.body();
  s.interaction = shapeFlagsFromWire(in.flags());
  return getMaterial(in, s);
}

// Versions 1-2: a body's one shape is part of the body message; it becomes
// the shape slot of the body's own index.
std::string getVersion2Shape(const v1::SceneBody& in, std::int32_t slot, ShapeSlotState& s) {
  s.alive = in.alive();
  if (!s.alive) return {};
  switch (in.shape_case()) {
    case v1::SceneBody::kCircleRadius: s.shape = Shape::makeCircle(in.circle_radius()); break;
    case v1::SceneBody::kPolygon:
      if (std::string error = getPolygon(in.polygon(), s.shape); !error.empty()) return error;
      break;
    case v1::SceneBody::SHAPE_NOT_SET: return "a live body needs a shape (circle_radius or polygon)";
  }
  s.body = slot;
  return getMaterial(in, s);
}

std::string getBody(const v1::SceneBody& in, BodySlotState& out) {
  out.alive = in.alive();
  out.generation = in.generation();
  if (!out.alive) return {};
  out.shapes.assign(in.shapes().begin(), in.shapes().end());
  IMPULSE_BODY_FIELDS(IMPULSE_GET_FIELD)
  getSceneBodyProperties(in, out.properties);
  out.contactEdges.assign(in.contact_edges().begin(), in.contact_edges().end());
  out.jointEdges.assign(in.joint_edges().begin(), in.joint_edges().end());
  return {};
}

std::string getManifoldPoint(const v1::SceneManifoldPoint& in, int i, ManifoldPoint& out, ManifoldFrame& frame) {
  if (in.feature() > 0xFFFF) return "a feature key has 16 bits";
  IMPULSE_MANIFOLD_POINT_FIELDS(IMPULSE_GET_FIELD)
  out.id = static_cast<std::uint16_t>(in.feature());
  frame.localPointA[i] = get(in.frame_point_a());
  frame.localPointB[i] = get(in.frame_point_b());
  frame.offset[i] = in.frame_offset();
  return {};
}

std::string getContact(const v1::SceneContact& in, ContactSlotState& out) {
  out.alive = in.alive();
  if (!out.alive) return {};
  if (in.points_size() > 2) return "a manifold has at most 2 points";
  IMPULSE_CONTACT_FIELDS(IMPULSE_GET_FIELD)
  out.manifold.pointCount = in.points_size();
  for (int i = 0; i < in.points_size(); ++i) {
    if (std::string error = getManifoldPoint(in.points(i), i, out.manifold.points[std::size_t(i)], out.frame);
        !error.empty()) {
      return error;
    }
  }
  return {};
}

JointImpulses getImpulses(const v1::SceneJointImpulses& in) {
  JointImpulses out;
  IMPULSE_JOINT_IMPULSE_FIELDS(IMPULSE_GET_FIELD)
  return out;
}

std::string getJoint(const v1::SceneJoint& in, JointSlotState& out) {
  out.alive = in.alive();
  out.generation = in.generation();
  if (!out.alive) return {};
  Decoded<JointSettings> settings = jointSettingsFromWire(in);
  if (!settings.ok()) return settings.error;
  out.settings = *settings.value;
  IMPULSE_JOINT_FIELDS(IMPULSE_GET_FIELD)
  out.impulses = getImpulses(in.impulses());
  return {};
}

std::string getTree(const v1::SceneTree& tree, DynamicTree::State& state) {
  for (const v1::SceneTreeNode& in : tree.nodes()) {
    if (in.height() < -1 || in.height() > 1000) return "a tree node's height must be -1 to 1000";
    DynamicTree::Node& out = state.nodes.emplace_back();
    IMPULSE_TREE_NODE_FIELDS(IMPULSE_GET_FIELD)
    out.height = static_cast<std::int16_t>(in.height());
  }
  state.root = tree.root();
  state.freeList = tree.free_list();
  state.leafCount = tree.leaf_count();
  return {};
}

std::string at(const char* kind, int index) {
  return std::string(kind) + " " + std::to_string(index) + ": ";
}

std::string getShapes(const v1::Scene& scene, WorldState& state) {
  if (scene.version() >= 3) {
    state.shapes.resize(std::size_t(scene.shapes_size()));
    for (int i = 0; i < scene.shapes_size(); ++i) {
      if (std::string error = getShape(scene.shapes(i), state.shapes[std::size_t(i)]); !error.empty()) {
        return at("shape slot", i) + error;
      }
    }
    state.freeShapes.assign(scene.free_shapes().begin(), scene.free_shapes().end());
    return {};
  }
  state.shapes.resize(state.bodies.size());
  for (int i = 0; i < scene.bodies_size(); ++i) {
    if (std::string error = getVersion2Shape(scene.bodies(i), i, state.shapes[std::size_t(i)]); !error.empty()) {
      return at("body slot", i) + error;
    }
    if (state.bodies[std::size_t(i)].alive) state.bodies[std::size_t(i)].shapes = {i};
  }
  state.freeShapes = state.freeBodies;
  return {};
}

// Versions 1-2: shape slot i is body slot i's only shape.
void nameVersion2ContactShapes(WorldState& state) {
  for (ContactSlotState& contact : state.contacts) {
    contact.shapeA = contact.bodyA;
    contact.shapeB = contact.bodyB;
  }
}

}  // namespace

void toWire(const WorldState& state, v1::Scene* out) {
  out->set_version(kSceneVersion);
  putSettings(state.settings, *out->mutable_settings());
  for (const BodySlotState& body : state.bodies) putBody(body, *out->add_bodies());
  putSlots(state.freeBodies, out->mutable_free_bodies());
  out->set_next_creation_order(state.nextCreationOrder);
  for (const ShapeSlotState& shape : state.shapes) putShape(shape, out->add_shapes());
  putSlots(state.freeShapes, out->mutable_free_shapes());
  for (const ContactSlotState& contact : state.contacts) putContact(contact, *out->add_contacts());
  putSlots(state.freeContacts, out->mutable_free_contacts());
  for (const JointSlotState& joint : state.joints) putJoint(joint, *out->add_joints());
  putSlots(state.freeJoints, out->mutable_free_joints());
  for (const FieldSlotState& field : state.fields) toWire(field.id, field.def, out->add_fields());
  out->set_next_field_id(state.nextFieldId);
  putTree(state.broadPhase.trees[0], out->mutable_static_tree());
  putTree(state.broadPhase.trees[1], out->mutable_movable_tree());
  putSlots(state.broadPhase.queued, out->mutable_queued_proxies());
  putSlots(state.awakeBodies, out->mutable_awake_bodies());
  out->set_step_count(state.stepCount);
  out->set_time(state.time);
  out->mutable_origin()->set_x(state.origin.x());
  out->mutable_origin()->set_y(state.origin.y());
}

std::string saveScene(const World& world) {
  v1::Scene scene;
  toWire(world.exportState(), &scene);
  return scene.SerializeAsString();
}

Decoded<WorldState> stateFromWire(const v1::Scene& scene) {
  using Result = Decoded<WorldState>;
  if (scene.version() == 0 || scene.version() > kSceneVersion) {
    return Result::failure("scene version " + std::to_string(scene.version()) +
                           " is not supported (this build reads 1 to " +
                           std::to_string(kSceneVersion) + ")");
  }
  WorldState state;
  state.settings = getSettings(scene.settings());
  state.bodies.resize(std::size_t(scene.bodies_size()));
  for (int i = 0; i < scene.bodies_size(); ++i) {
    if (std::string error = getBody(scene.bodies(i), state.bodies[std::size_t(i)]);
        !error.empty()) {
      return Result::failure(at("body slot", i) + error);
    }
  }
  state.freeBodies.assign(scene.free_bodies().begin(), scene.free_bodies().end());
  state.nextCreationOrder = scene.next_creation_order();
  if (std::string error = getShapes(scene, state); !error.empty()) return Result::failure(error);
  state.contacts.resize(std::size_t(scene.contacts_size()));
  for (int i = 0; i < scene.contacts_size(); ++i) {
    if (std::string error = getContact(scene.contacts(i), state.contacts[std::size_t(i)]);
        !error.empty()) {
      return Result::failure(at("contact slot", i) + error);
    }
  }
  state.freeContacts.assign(scene.free_contacts().begin(), scene.free_contacts().end());
  if (scene.version() < 3) nameVersion2ContactShapes(state);
  state.joints.resize(std::size_t(scene.joints_size()));
  for (int i = 0; i < scene.joints_size(); ++i) {
    if (std::string error = getJoint(scene.joints(i), state.joints[std::size_t(i)]);
        !error.empty()) {
      return Result::failure(at("joint slot", i) + error);
    }
  }
  state.freeJoints.assign(scene.free_joints().begin(), scene.free_joints().end());
  for (int i = 0; i < scene.fields_size(); ++i) {
    auto def = fieldFromWire(scene.fields(i));
    if (!def) return Result::failure(at("field", i) + "not a field kind this build knows");
    state.fields.push_back({FieldId{scene.fields(i).id()}, std::move(*def)});
  }
  // Version 1 had no fields: its worlds start their field ids at 1.
  state.nextFieldId = scene.version() >= 2 ? scene.next_field_id() : 1;
  if (std::string error = getTree(scene.static_tree(), state.broadPhase.trees[0]); !error.empty()) {
    return Result::failure("static_tree: " + error);
  }
  if (std::string error = getTree(scene.movable_tree(), state.broadPhase.trees[1]);
      !error.empty()) {
    return Result::failure("movable_tree: " + error);
  }
  state.broadPhase.queued.assign(scene.queued_proxies().begin(), scene.queued_proxies().end());
  state.awakeBodies.assign(scene.awake_bodies().begin(), scene.awake_bodies().end());
  state.stepCount = scene.step_count();
  state.time = scene.time();
  state.origin = Vec2d(scene.origin().x(), scene.origin().y());
  return Result::success(std::move(state));
}

SceneSlotLimits sceneSlotLimits(int maxBodies) {
  const auto bodies = std::size_t(std::max(maxBodies, 0));
  const std::size_t shapes = std::size_t(kShapesPerBodyOfLimit) * bodies;
  // A tree holds 2n - 1 nodes for n proxies (one per shape) and grows its
  // array by doubling.
  return {bodies, shapes, kContactSlotsPerShape * shapes, kJointSlotsPerBody * bodies, 4 * shapes + 16};
}

namespace {

std::string tooMany(const char* what, std::size_t count, std::size_t limit) {
  return std::to_string(count) + " " + what + " (live or free), over the " + std::to_string(limit) +
         " this world allows for its body limit";
}

std::string checkSlotCounts(const v1::Scene& scene, const SceneSlotLimits& limits) {
  const std::size_t bodies = std::size_t(scene.bodies_size());
  if (bodies > limits.bodies) return tooMany("body slots", bodies, limits.bodies);
  const std::size_t shapes = std::size_t(scene.shapes_size());
  if (shapes > limits.shapes) return tooMany("shape slots", shapes, limits.shapes);
  const std::size_t contacts = std::size_t(scene.contacts_size());
  if (contacts > limits.contacts) return tooMany("contact slots", contacts, limits.contacts);
  const std::size_t joints = std::size_t(scene.joints_size());
  if (joints > limits.joints) return tooMany("joint slots", joints, limits.joints);
  for (const auto* tree : {&scene.static_tree(), &scene.movable_tree()}) {
    const std::size_t nodes = std::size_t(tree->nodes_size());
    if (nodes > limits.treeNodes) return tooMany("broad-phase tree nodes", nodes, limits.treeNodes);
  }
  return {};
}

// Counters that would wrap in the world's life, or hand out an id in use.
std::string checkCounters(const v1::Scene& scene) {
  if (scene.next_creation_order() > kMaxNextCreationOrder) {
    return "next_creation_order " + std::to_string(scene.next_creation_order()) + " is past " +
           std::to_string(kMaxNextCreationOrder) + " (it would wrap)";
  }
  for (int i = 0; i < scene.bodies_size(); ++i) {
    const auto& body = scene.bodies(i);
    if (body.alive() && body.creation_order() >= scene.next_creation_order()) {
      return at("body slot", i) + "creation_order " + std::to_string(body.creation_order()) +
             " is not below next_creation_order " + std::to_string(scene.next_creation_order());
    }
  }
  if (scene.version() < 2) return {};
  if (scene.next_field_id() > kMaxNextFieldId) {
    return "next_field_id " + std::to_string(scene.next_field_id()) + " is past " +
           std::to_string(kMaxNextFieldId) + " (field ids would wrap)";
  }
  for (int i = 0; i < scene.fields_size(); ++i) {
    const std::uint32_t id = scene.fields(i).id();
    if (id == 0 || id >= scene.next_field_id()) {
      return at("field", i) + "id " + std::to_string(id) + " must be 1 to next_field_id - 1 (" +
             std::to_string(scene.next_field_id()) + " - 1)";
    }
  }
  return {};
}

}  // namespace

InputResult loadScene(World& world, std::string_view bytes) {
  v1::Scene scene;
  if (!scene.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()))) {
    return {"scene refused: the data does not parse as a Scene message"};
  }
  const SceneSlotLimits limits = sceneSlotLimits(world.settings().maxBodies);
  if (std::string error = checkSlotCounts(scene, limits); !error.empty()) {
    return {"scene refused: " + error};
  }
  if (std::string error = checkCounters(scene); !error.empty()) return {"scene refused: " + error};
  Decoded<WorldState> state = stateFromWire(scene);
  if (!state.ok()) return {"scene refused: " + state.error};
  return world.importState(*state.value);
}

}  // namespace impulse::wire
