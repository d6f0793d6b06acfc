#pragma once
/// Conversion between engine types and wire messages.
///
/// The engine computes in float and the wire carries double: engine -> wire is
/// exact, and wire -> engine checks that every number is finite and fits a
/// float before anything is converted (a huge finite double would otherwise
/// become an infinite float inside the engine).

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "impulse.pb.h"
#include "impulse/body.h"
#include "impulse/joint.h"
#include "impulse/material.h"
#include "impulse/math.h"
#include "impulse/scenes/presets.h"
#include "impulse/shape.h"
#include "impulse/world.h"

namespace impulse::wire {

/// A value decoded from the wire, or the reason it was refused.
template <class T>
struct Decoded {
  std::optional<T> value;
  std::string error;

  static Decoded success(T v) { return {std::move(v), {}}; }
  static Decoded failure(std::string message) { return {std::nullopt, std::move(message)}; }
  bool ok() const { return value.has_value(); }
};

// ------------------------------------------------------------ engine -> wire

void toWire(const Vec2& v, v1::Vec2* out);
v1::Material toWire(Material material);
v1::BodyType toWire(BodyType type);
void toWire(const Shape& shape, v1::Shape* out);
void toWire(const BodyState& state, v1::BodyState* out);
void toWire(const BodyDescription& description, v1::BodyDescriptor* out);
void toWire(const PresetInfo& preset, v1::PresetInfo* out);
/// Everything QueryBody answers about one body.
void toWire(const BodyDescription& description, const BodyState& state, v1::BodyInfo* out);
void toWire(const JointDescription& description, v1::JointDescriptor* out);
/// The kind and its values, into CreateJoint (client) or JointDescriptor.
void toWire(const JointSettings& settings, v1::CreateJoint* out);
void toWire(const JointSettings& settings, v1::JointDescriptor* out);
/// Everything QueryJoint answers about one joint.
void toWire(const JointDescription& description, const JointState& state, v1::JointInfo* out);

// ------------------------------------------------------------ wire -> engine

/// `value` as a Real, or an error naming `what` when it is not finite or does
/// not fit the engine's float.
Decoded<Real> realFromWire(double value, std::string_view what);
/// Both components checked as by realFromWire ("what.x", "what.y").
Decoded<Vec2> vecFromWire(const v1::Vec2& v, std::string_view what);
/// MATERIAL_UNSPECIFIED and SOLID give Solid; nothing for a value outside the
/// enum (proto3 enums carry unknown numbers through).
std::optional<Material> materialFromWire(int material);
/// The enum's range as error messages print it: "(0-8)".
std::string materialRange();
/// Nothing for BODY_TYPE_UNSPECIFIED (a type must be named) and for a value
/// outside the enum.
std::optional<BodyType> bodyTypeFromWire(int type);
/// Material, flags, initial velocities and per-body properties, each checked.
/// A `friction` sets both the static and the dynamic coefficient.
Decoded<BodyOptions> optionsFromWire(const v1::BodyOptions& options);

/// A shape as described by the server (body-local polygon, anticlockwise).
/// Checks the vertex count and finiteness only; normals are recomputed.
Decoded<Shape> shapeFromWire(const v1::Shape& shape);
/// States come from the server: converted as they are.
BodyState stateFromWire(const v1::BodyState& state);
Vec2 vecFromWireUnchecked(const v1::Vec2& v);
PresetInfo presetFromWire(const v1::PresetInfo& preset);

/// A CreateJoint as the engine's JointDef, every number checked; errors name
/// the field ("create_joint.distance.stiffness is not a finite number").
/// Ranges (negative stiffness, unknown bodies) are the engine's to judge.
Decoded<JointDef> jointDefFromWire(const v1::CreateJoint& command);
/// An UpdateJoint's fields that are set, each checked.
Decoded<JointUpdate> jointUpdateFromWire(const v1::UpdateJoint& command);
/// Joints come from the server: converted as they are. Nothing for a
/// descriptor without a kind.
std::optional<JointDescription> jointFromWire(const v1::JointDescriptor& joint);
/// A scene joint's kind and values into SceneJoint (scene_convert.h), and
/// back with every number checked.
void toWire(const JointSettings& settings, v1::SceneJoint* out);
Decoded<JointSettings> jointSettingsFromWire(const v1::SceneJoint& joint);
/// The wire name of a joint kind ("distance", "rope", ... "mouse").
std::string_view jointKindName(const JointSettings& settings);

/// Upper-case wire name of a material ("SOLID".."FOAM").
std::string_view materialName(Material material);
/// Material from its name, case-insensitive ("ice", "RUBBER").
std::optional<Material> materialFromName(std::string_view name);

}  // namespace impulse::wire
