// WorldState <-> Scene, field by field. Engine floats travel as proto
// floats, so both directions are bit-exact; what the engine must judge
// (ranges, shapes, links) is left to World::importState.

#include "impulse/wire/scene_convert.h"

#include "impulse/wire/field_convert.h"

#include <algorithm>
#include <string>

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

void putSettings(const SolverSettingsState& s, v1::SceneSettings* out) {
  put(s.gravity, out->mutable_gravity());
  out->set_sub_steps(s.subSteps);
  out->set_relax_iterations(s.relaxIterations);
  out->set_contact_hertz(s.contactHertz);
  out->set_contact_damping_ratio(s.contactDampingRatio);
  out->set_max_contact_push_speed(s.maxContactPushSpeed);
  out->set_restitution_threshold(s.restitutionThreshold);
  out->set_stick_speed(s.stickSpeed);
  out->set_enable_warm_starting(s.enableWarmStarting);
  out->set_enable_sleep(s.enableSleep);
  out->set_linear_sleep_tolerance(s.linearSleepTolerance);
  out->set_time_to_sleep(s.timeToSleep);
  out->set_enable_continuous(s.enableContinuous);
  out->set_hit_event_threshold(s.hitEventThreshold);
}

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
  out->set_density(s.density);
  out->set_restitution(s.restitution);
  out->set_static_friction(s.staticFriction);
  out->set_dynamic_friction(s.dynamicFriction);
  out->set_rolling_resistance(s.rollingResistance);
  out->set_proxy_key(s.proxyKey);
  toWire(s.interaction, out->mutable_flags());
}

void putBody(const BodySlotState& b, v1::SceneBody* out) {
  out->set_alive(b.alive);
  out->set_generation(b.generation);
  if (!b.alive) return;
  for (std::int32_t shape : b.shapes) out->add_shapes(shape);
  put(b.transform.p, out->mutable_position());
  put(b.transform.q, out->mutable_rotation());
  put(b.linearVelocity, out->mutable_velocity());
  out->set_angular_velocity(b.angularVelocity);
  put(b.force, out->mutable_force());
  out->set_torque(b.torque);
  out->set_linear_drag(b.linearDrag);
  out->set_gravity_scale(b.gravityScale);
  out->set_angular_drag(b.angularDrag);
  out->set_sleep_time(b.sleepTime);
  put(b.center0, out->mutable_start_center());
  put(b.rotation0, out->mutable_start_rotation());
  out->set_creation_order(b.creationOrder);
  out->set_is_static(b.isStatic);
  out->set_is_kinematic(b.isKinematic);
  out->set_ignore_gravity(b.ignoreGravity);
  out->set_awake(b.awake);
  for (std::int32_t key : b.contactEdges) out->add_contact_edges(key);
  for (std::int32_t key : b.jointEdges) out->add_joint_edges(key);
}

void putContact(const ContactSlotState& c, v1::SceneContact* out) {
  out->set_alive(c.alive);
  if (!c.alive) return;
  out->set_shape_a(c.shapeA);
  out->set_shape_b(c.shapeB);
  out->set_body_a(c.bodyA);
  out->set_body_b(c.bodyB);
  put(c.manifold.normal, out->mutable_normal());
  for (int i = 0; i < c.manifold.pointCount; ++i) {
    const ManifoldPoint& p = c.manifold.points[std::size_t(i)];
    v1::SceneManifoldPoint* point = out->add_points();
    put(p.point, point->mutable_point());
    put(p.anchorA, point->mutable_anchor_a());
    put(p.anchorB, point->mutable_anchor_b());
    point->set_separation(p.separation);
    point->set_feature(p.id);
    point->set_normal_impulse(p.normalImpulse);
    point->set_tangent_impulse(p.tangentImpulse);
    point->set_support_impulse(p.supportImpulse);
    put(c.frame.localPointA[i], point->mutable_frame_point_a());
    put(c.frame.localPointB[i], point->mutable_frame_point_b());
    point->set_frame_offset(c.frame.offset[i]);
  }
  out->set_rolling_impulse(c.manifold.rollingImpulse);
  out->set_frame_computed(c.frame.computed);
  put(c.frame.relative.p, out->mutable_frame_relative_position());
  put(c.frame.relative.q, out->mutable_frame_relative_rotation());
  put(c.frame.localNormal, out->mutable_frame_normal());
  out->set_static_friction(c.staticFriction);
  out->set_dynamic_friction(c.dynamicFriction);
  out->set_restitution(c.restitution);
  out->set_rolling_resistance(c.rollingResistance);
  out->set_touching(c.touching);
}

void putImpulses(const JointImpulses& i, v1::SceneJointImpulses* out) {
  put(i.point, out->mutable_point());
  put(i.pointSpring, out->mutable_point_spring());
  out->set_perpendicular(i.perpendicular);
  out->set_angular(i.angular);
  out->set_axial(i.axial);
  out->set_spring(i.spring);
  out->set_motor(i.motor);
  out->set_lower(i.lower);
  out->set_upper(i.upper);
}

void putJoint(const JointSlotState& j, v1::SceneJoint* out) {
  out->set_alive(j.alive);
  out->set_generation(j.generation);
  if (!j.alive) return;
  out->set_body_a(j.bodyA);
  out->set_body_b(j.bodyB);
  toWire(j.settings, out);
  put(j.localAnchorA, out->mutable_local_anchor_a());
  put(j.localAnchorB, out->mutable_local_anchor_b());
  put(j.localAxisA, out->mutable_local_axis_a());
  out->set_reference_angle(j.referenceAngle);
  out->set_reference_translation(j.referenceTranslation);
  out->set_reference_perpendicular(j.referencePerpendicular);
  out->set_length(j.length);
  put(j.target, out->mutable_target());
  putImpulses(j.impulses, out->mutable_impulses());
  put(j.reactionForce, out->mutable_reaction_force());
  out->set_reaction_torque(j.reactionTorque);
  out->set_collide_connected(j.collideConnected);
}

void putTree(const DynamicTree::State& tree, v1::SceneTree* out) {
  for (const DynamicTree::Node& node : tree.nodes) {
    v1::SceneTreeNode* n = out->add_nodes();
    put(node.box.lower, n->mutable_lower());
    put(node.box.upper, n->mutable_upper());
    n->set_parent(node.parent);
    n->set_child1(node.child1);
    n->set_child2(node.child2);
    n->set_user_value(node.userValue);
    n->set_height(node.height);
  }
  out->set_root(tree.root);
  out->set_free_list(tree.freeList);
  out->set_leaf_count(tree.leafCount);
}

template <class Repeated>
void putSlots(const std::vector<std::int32_t>& slots, Repeated* out) {
  out->Add(slots.begin(), slots.end());
}

// ------------------------------------------------------------ wire -> engine

Vec2 get(const v1::SceneVec2& v) { return Vec2(v.x(), v.y()); }
Rot get(const v1::SceneRotation& q) { return {q.c(), q.s()}; }

SolverSettingsState getSettings(const v1::SceneSettings& s) {
  return {get(s.gravity()),           s.sub_steps(),
          s.relax_iterations(),       s.contact_hertz(),
          s.contact_damping_ratio(),  s.max_contact_push_speed(),
          s.restitution_threshold(),  s.stick_speed(),
          s.enable_warm_starting(),   s.enable_sleep(),
          s.linear_sleep_tolerance(), s.time_to_sleep(),
          s.enable_continuous(),
          s.has_hit_event_threshold() ? s.hit_event_threshold() : SolverSettingsState{}.hitEventThreshold};
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
  s.density = in.density();
  s.restitution = in.restitution();
  s.staticFriction = in.static_friction();
  s.dynamicFriction = in.dynamic_friction();
  s.rollingResistance = in.rolling_resistance();
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

std::string getBody(const v1::SceneBody& in, BodySlotState& b) {
  b.alive = in.alive();
  b.generation = in.generation();
  if (!b.alive) return {};
  b.shapes.assign(in.shapes().begin(), in.shapes().end());
  b.transform = {get(in.position()), get(in.rotation())};
  b.linearVelocity = get(in.velocity());
  b.angularVelocity = in.angular_velocity();
  b.force = get(in.force());
  b.torque = in.torque();
  b.linearDrag = in.linear_drag();
  b.gravityScale = in.has_gravity_scale() ? in.gravity_scale() : 1;
  b.angularDrag = in.angular_drag();
  b.sleepTime = in.sleep_time();
  b.center0 = get(in.start_center());
  b.rotation0 = get(in.start_rotation());
  b.creationOrder = in.creation_order();
  b.isStatic = in.is_static();
  b.isKinematic = in.is_kinematic();
  b.ignoreGravity = in.ignore_gravity();
  b.awake = in.awake();
  b.contactEdges.assign(in.contact_edges().begin(), in.contact_edges().end());
  b.jointEdges.assign(in.joint_edges().begin(), in.joint_edges().end());
  return {};
}

std::string getContact(const v1::SceneContact& in, ContactSlotState& c) {
  c.alive = in.alive();
  if (!c.alive) return {};
  if (in.points_size() > 2) return "a manifold has at most 2 points";
  c.shapeA = in.shape_a();
  c.shapeB = in.shape_b();
  c.bodyA = in.body_a();
  c.bodyB = in.body_b();
  c.manifold.normal = get(in.normal());
  c.manifold.pointCount = in.points_size();
  for (int i = 0; i < in.points_size(); ++i) {
    const v1::SceneManifoldPoint& p = in.points(i);
    if (p.feature() > 0xFFFF) return "a feature key has 16 bits";
    ManifoldPoint& point = c.manifold.points[std::size_t(i)];
    point.point = get(p.point());
    point.anchorA = get(p.anchor_a());
    point.anchorB = get(p.anchor_b());
    point.separation = p.separation();
    point.id = static_cast<std::uint16_t>(p.feature());
    point.normalImpulse = p.normal_impulse();
    point.tangentImpulse = p.tangent_impulse();
    point.supportImpulse = p.support_impulse();
    c.frame.localPointA[i] = get(p.frame_point_a());
    c.frame.localPointB[i] = get(p.frame_point_b());
    c.frame.offset[i] = p.frame_offset();
  }
  c.manifold.rollingImpulse = in.rolling_impulse();
  c.frame.computed = in.frame_computed();
  c.frame.relative = {get(in.frame_relative_position()), get(in.frame_relative_rotation())};
  c.frame.localNormal = get(in.frame_normal());
  c.staticFriction = in.static_friction();
  c.dynamicFriction = in.dynamic_friction();
  c.restitution = in.restitution();
  c.rollingResistance = in.rolling_resistance();
  c.touching = in.touching();
  return {};
}

JointImpulses getImpulses(const v1::SceneJointImpulses& in) {
  return {get(in.point()),    get(in.point_spring()),
          in.perpendicular(), in.angular(),
          in.axial(),         in.spring(),
          in.motor(),         in.lower(),
          in.upper()};
}

std::string getJoint(const v1::SceneJoint& in, JointSlotState& j) {
  j.alive = in.alive();
  j.generation = in.generation();
  if (!j.alive) return {};
  Decoded<JointSettings> settings = jointSettingsFromWire(in);
  if (!settings.ok()) return settings.error;
  j.settings = *settings.value;
  j.bodyA = in.body_a();
  j.bodyB = in.body_b();
  j.localAnchorA = get(in.local_anchor_a());
  j.localAnchorB = get(in.local_anchor_b());
  j.localAxisA = get(in.local_axis_a());
  j.referenceAngle = in.reference_angle();
  j.referenceTranslation = in.reference_translation();
  j.referencePerpendicular = in.reference_perpendicular();
  j.length = in.length();
  j.target = get(in.target());
  j.impulses = getImpulses(in.impulses());
  j.reactionForce = get(in.reaction_force());
  j.reactionTorque = in.reaction_torque();
  j.collideConnected = in.collide_connected();
  return {};
}

std::string getTree(const v1::SceneTree& in, DynamicTree::State& tree) {
  for (const v1::SceneTreeNode& n : in.nodes()) {
    if (n.height() < -1 || n.height() > 1000) return "a tree node's height must be -1 to 1000";
    DynamicTree::Node node;
    node.box = {get(n.lower()), get(n.upper())};
    node.parent = n.parent();
    node.child1 = n.child1();
    node.child2 = n.child2();
    node.userValue = n.user_value();
    node.height = static_cast<std::int16_t>(n.height());
    tree.nodes.push_back(node);
  }
  tree.root = in.root();
  tree.freeList = in.free_list();
  tree.leafCount = in.leaf_count();
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
  putSettings(state.settings, out->mutable_settings());
  for (const BodySlotState& body : state.bodies) putBody(body, out->add_bodies());
  putSlots(state.freeBodies, out->mutable_free_bodies());
  out->set_next_creation_order(state.nextCreationOrder);
  for (const ShapeSlotState& shape : state.shapes) putShape(shape, out->add_shapes());
  putSlots(state.freeShapes, out->mutable_free_shapes());
  for (const ContactSlotState& contact : state.contacts) putContact(contact, out->add_contacts());
  putSlots(state.freeContacts, out->mutable_free_contacts());
  for (const JointSlotState& joint : state.joints) putJoint(joint, out->add_joints());
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
