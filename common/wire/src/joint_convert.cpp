// Joints on the wire (docs/protocol.md, "Joints"). CreateJoint and JointDescriptor
// carry the same oneof of kinds under the same names, so one template per
// direction serves both.
#include <type_traits>
#include <variant>

#include "impulse/wire/convert.h"
#include "wire_reader.h"

namespace impulse::wire {

namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
// Spelled out: clang before 17 does not deduce an aggregate's arguments.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

void fill(const DistanceJointSettings& s, v1::DistanceJoint* out) {
  out->set_length(s.length);
  out->set_stiffness(s.stiffness);
  out->set_damping(s.damping);
}

void fill(const RopeJointSettings& s, v1::RopeJoint* out) { out->set_max_length(s.maxLength); }

void fill(const RevoluteJointSettings& s, v1::RevoluteJoint* out) {
  out->set_enable_limit(s.enableLimit);
  out->set_lower_angle(s.lowerAngle);
  out->set_upper_angle(s.upperAngle);
  out->set_enable_motor(s.enableMotor);
  out->set_motor_speed(s.motorSpeed);
  out->set_max_motor_torque(s.maxMotorTorque);
  out->set_stiffness(s.stiffness);
  out->set_damping(s.damping);
}

void fill(const PrismaticJointSettings& s, v1::PrismaticJoint* out) {
  toWire(s.axis, out->mutable_axis());
  out->set_enable_limit(s.enableLimit);
  out->set_lower(s.lower);
  out->set_upper(s.upper);
  out->set_enable_motor(s.enableMotor);
  out->set_motor_speed(s.motorSpeed);
  out->set_max_motor_force(s.maxMotorForce);
  out->set_stiffness(s.stiffness);
  out->set_damping(s.damping);
}

void fill(const WeldJointSettings& s, v1::WeldJoint* out) {
  out->set_linear_stiffness(s.linearStiffness);
  out->set_angular_stiffness(s.angularStiffness);
}

void fill(const WheelJointSettings& s, v1::WheelJoint* out) {
  toWire(s.axis, out->mutable_axis());
  out->set_stiffness(s.stiffness);
  out->set_damping(s.damping);
  out->set_enable_motor(s.enableMotor);
  out->set_motor_speed(s.motorSpeed);
  out->set_max_motor_torque(s.maxMotorTorque);
}

void fill(const MouseJointSettings& s, v1::MouseJoint* out) {
  out->set_max_force(s.maxForce);
  out->set_stiffness(s.stiffness);
  out->set_damping(s.damping);
}

template <class Message>
void kindToWire(const JointSettings& settings, Message* out) {
  std::visit(Overloaded{
                 [&](const DistanceJointSettings& s) { fill(s, out->mutable_distance()); },
                 [&](const RopeJointSettings& s) { fill(s, out->mutable_rope()); },
                 [&](const RevoluteJointSettings& s) { fill(s, out->mutable_revolute()); },
                 [&](const PrismaticJointSettings& s) { fill(s, out->mutable_prismatic()); },
                 [&](const WeldJointSettings& s) { fill(s, out->mutable_weld()); },
                 [&](const WheelJointSettings& s) { fill(s, out->mutable_wheel()); },
                 [&](const MouseJointSettings& s) { fill(s, out->mutable_mouse()); },
             },
             settings);
}

DistanceJointSettings read(Reader& r, const v1::DistanceJoint& m) {
  return {r.real(m.length(), "length"), r.real(m.stiffness(), "stiffness"),
          r.real(m.damping(), "damping")};
}

RopeJointSettings read(Reader& r, const v1::RopeJoint& m) {
  return {r.real(m.max_length(), "max_length")};
}

RevoluteJointSettings read(Reader& r, const v1::RevoluteJoint& m) {
  RevoluteJointSettings s;
  s.enableLimit = m.enable_limit();
  s.lowerAngle = r.real(m.lower_angle(), "lower_angle");
  s.upperAngle = r.real(m.upper_angle(), "upper_angle");
  s.enableMotor = m.enable_motor();
  s.motorSpeed = r.real(m.motor_speed(), "motor_speed");
  s.maxMotorTorque = r.real(m.max_motor_torque(), "max_motor_torque");
  s.stiffness = r.real(m.stiffness(), "stiffness");
  s.damping = r.real(m.damping(), "damping");
  return s;
}

PrismaticJointSettings read(Reader& r, const v1::PrismaticJoint& m) {
  PrismaticJointSettings s;
  // An unset axis keeps the engine's default (x).
  if (m.has_axis()) s.axis = r.vec(m.axis(), "axis");
  s.enableLimit = m.enable_limit();
  s.lower = r.real(m.lower(), "lower");
  s.upper = r.real(m.upper(), "upper");
  s.enableMotor = m.enable_motor();
  s.motorSpeed = r.real(m.motor_speed(), "motor_speed");
  s.maxMotorForce = r.real(m.max_motor_force(), "max_motor_force");
  s.stiffness = r.real(m.stiffness(), "stiffness");
  s.damping = r.real(m.damping(), "damping");
  return s;
}

WeldJointSettings read(Reader& r, const v1::WeldJoint& m) {
  return {r.real(m.linear_stiffness(), "linear_stiffness"),
          r.real(m.angular_stiffness(), "angular_stiffness")};
}

WheelJointSettings read(Reader& r, const v1::WheelJoint& m) {
  WheelJointSettings s;
  // An unset axis keeps the engine's default (y, a suspension).
  if (m.has_axis()) s.axis = r.vec(m.axis(), "axis");
  s.stiffness = r.real(m.stiffness(), "stiffness");
  s.damping = r.real(m.damping(), "damping");
  s.enableMotor = m.enable_motor();
  s.motorSpeed = r.real(m.motor_speed(), "motor_speed");
  s.maxMotorTorque = r.real(m.max_motor_torque(), "max_motor_torque");
  return s;
}

MouseJointSettings read(Reader& r, const v1::MouseJoint& m) {
  return {r.real(m.max_force(), "max_force"), r.real(m.stiffness(), "stiffness"),
          r.real(m.damping(), "damping")};
}

// Reads one kind into `out` (in place: copying a variant out of an optional
// makes GCC warn of uninitialised members); false with `error` set on a bad
// number.
template <class Kind>
bool readKind(const Reader& parent, std::string_view name, const Kind& kind, JointSettings& out,
              std::string& error) {
  Reader r = parent.kind(name);
  out = read(r, kind);
  error = r.error();
  return error.empty();
}

// The kind of a CreateJoint or JointDescriptor into `out`; false with
// `error` set when it is missing or a number is bad.
template <class Message>
bool kindFromWire(const Message& m, const Reader& r, JointSettings& out, std::string& error) {
  switch (m.kind_case()) {
    case Message::kDistance: return readKind(r, "distance", m.distance(), out, error);
    case Message::kRope: return readKind(r, "rope", m.rope(), out, error);
    case Message::kRevolute: return readKind(r, "revolute", m.revolute(), out, error);
    case Message::kPrismatic: return readKind(r, "prismatic", m.prismatic(), out, error);
    case Message::kWeld: return readKind(r, "weld", m.weld(), out, error);
    case Message::kWheel: return readKind(r, "wheel", m.wheel(), out, error);
    case Message::kMouse: return readKind(r, "mouse", m.mouse(), out, error);
    case Message::KIND_NOT_SET: break;
  }
  error = std::string(r.prefix()) +
          "kind: none of distance, rope, revolute, prismatic, weld, wheel, mouse is set";
  return false;
}

}  // namespace

void toWire(const JointSettings& settings, v1::CreateJoint* out) { kindToWire(settings, out); }

void toWire(const JointSettings& settings, v1::JointDescriptor* out) { kindToWire(settings, out); }

void toWire(const JointDescription& description, v1::JointDescriptor* out) {
  out->set_id(description.id.value);
  out->set_body_a(description.bodyA.value);
  out->set_body_b(description.bodyB.value);
  toWire(description.localAnchorA, out->mutable_local_anchor_a());
  toWire(description.localAnchorB, out->mutable_local_anchor_b());
  out->set_collide_connected(description.collideConnected);
  kindToWire(description.settings, out);
}

void toWire(const JointDescription& description, const JointState& state, v1::JointInfo* out) {
  toWire(description, out->mutable_descriptor());
  toWire(state.reactionForce, out->mutable_reaction_force());
  out->set_reaction_torque(state.reactionTorque);
  out->set_length(state.length);
  out->set_angle(state.angle);
  out->set_translation(state.translation);
}

Decoded<JointDef> jointDefFromWire(const v1::CreateJoint& command) {
  Reader reader("create_joint.");
  JointDef def;
  def.bodyA = BodyId{command.body_a()};
  def.bodyB = BodyId{command.body_b()};
  def.anchorA = reader.vec(command.anchor_a(), "anchor_a");
  def.anchorB = reader.vec(command.anchor_b(), "anchor_b");
  def.collideConnected = command.collide_connected();
  if (!reader.error().empty()) return Decoded<JointDef>::failure(reader.error());
  std::string error;
  if (!kindFromWire(command, reader, def.settings, error)) {
    return Decoded<JointDef>::failure(std::move(error));
  }
  return Decoded<JointDef>::success(std::move(def));
}

Decoded<JointUpdate> jointUpdateFromWire(const v1::UpdateJoint& command) {
  Reader reader("update_joint.");
  JointUpdate update;
  if (command.has_target()) update.target = reader.vec(command.target(), "target");
  if (command.has_motor_speed()) {
    update.motorSpeed = reader.real(command.motor_speed(), "motor_speed");
  }
  if (command.has_max_motor_force()) {
    update.maxMotorForce = reader.real(command.max_motor_force(), "max_motor_force");
  }
  if (!reader.error().empty()) return Decoded<JointUpdate>::failure(reader.error());
  return Decoded<JointUpdate>::success(update);
}

std::optional<JointDescription> jointFromWire(const v1::JointDescriptor& joint) {
  JointDescription result;
  // The server's numbers are its engine's floats: only a missing kind fails.
  std::string error;
  if (!kindFromWire(joint, Reader("joint."), result.settings, error) &&
      joint.kind_case() == v1::JointDescriptor::KIND_NOT_SET) {
    return std::nullopt;
  }
  result.id = JointId{joint.id()};
  result.bodyA = BodyId{joint.body_a()};
  result.bodyB = BodyId{joint.body_b()};
  result.localAnchorA = vecFromWireUnchecked(joint.local_anchor_a());
  result.localAnchorB = vecFromWireUnchecked(joint.local_anchor_b());
  result.collideConnected = joint.collide_connected();
  return result;
}

void toWire(const JointSettings& settings, v1::SceneJoint* out) { kindToWire(settings, out); }

Decoded<JointSettings> jointSettingsFromWire(const v1::SceneJoint& joint) {
  JointSettings settings;
  std::string error;
  if (!kindFromWire(joint, Reader("joint."), settings, error)) {
    return Decoded<JointSettings>::failure(error);
  }
  return Decoded<JointSettings>::success(settings);
}

std::string_view jointKindName(const JointSettings& settings) {
  static constexpr std::string_view kNames[] = {"distance", "rope", "revolute", "prismatic",
                                                "weld",     "wheel", "mouse"};
  static_assert(std::size(kNames) == std::variant_size_v<JointSettings>);
  return kNames[settings.index()];
}

}  // namespace impulse::wire
