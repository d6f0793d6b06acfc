#pragma once
// A body's properties described once, for every message that carries them.
// Scenes, snapshots, body queries and spawn options are written and read
// from these rows, so a new property is a row here (with its proto fields
// and its member of impulse::BodyProperties) instead of a line in each
// converter.

#include <string>
#include <string_view>
#include <utility>

#include "impulse/body.h"
#include "impulse/wire/convert.h"

// A body's own properties, one row each: the member of impulse::BodyProperties
// (which BodyOptions, BodyDescription and the scene's BodySlotState hold
// whole), its field in the commands and snapshots (BodyOptions,
// BodyDescriptor, BodyInfo), its field in a SceneBody, and what a message
// without the field means.
// clang-format off
#define IMPULSE_BODY_PROPERTIES(ROW)                           \
  ROW(isStatic,      is_static,       is_static,      false)   \
  ROW(isKinematic,   is_kinematic,    is_kinematic,   false)   \
  ROW(ignoreGravity, ignore_gravity,  ignore_gravity, false)   \
  ROW(linearDrag,    linear_damping,  linear_drag,    0)       \
  ROW(angularDrag,   angular_damping, angular_drag,   0)       \
  ROW(gravityScale,  gravity_scale,   gravity_scale,  1)

// The material coefficients in force, one row each: the engine member (a
// scene's ShapeSlotState; a BodyDescription gives its first shape's) and the
// field of the same meaning in SceneShape, a version 1-2 SceneBody,
// BodyDescriptor and BodyInfo.
#define IMPULSE_MATERIAL_COEFFICIENTS(ROW) \
  ROW(density,           density)          \
  ROW(restitution,       restitution)      \
  ROW(staticFriction,    static_friction)  \
  ROW(dynamicFriction,   dynamic_friction) \
  ROW(rollingResistance, rolling_resistance)
// clang-format on

namespace impulse::wire {

/// Writes the body properties into a snapshot message, each that the
/// message has a field for (a BodyInfo's flags are in its descriptor).
template <class Message>
void putBodyProperties(const BodyProperties& in, Message& out) {
#define IMPULSE_PUT_PROPERTY(member, field, sceneField, fallback) \
  if constexpr (requires { out.set_##field(in.member); }) out.set_##field(in.member);
  IMPULSE_BODY_PROPERTIES(IMPULSE_PUT_PROPERTY)
#undef IMPULSE_PUT_PROPERTY
}

/// Writes every body property into a SceneBody: a scene carries them all.
template <class Message>
void putSceneBodyProperties(const BodyProperties& in, Message& out) {
#define IMPULSE_PUT_SCENE_PROPERTY(member, field, sceneField, fallback) out.set_##sceneField(in.member);
  IMPULSE_BODY_PROPERTIES(IMPULSE_PUT_SCENE_PROPERTY)
#undef IMPULSE_PUT_SCENE_PROPERTY
}

/// Reads every body property from a SceneBody; an optional field left out
/// means the row's value.
template <class Message>
void getSceneBodyProperties(const Message& in, BodyProperties& out) {
#define IMPULSE_GET_SCENE_PROPERTY(member, field, sceneField, fallback)        \
  if constexpr (requires { in.has_##sceneField(); }) {                       \
    out.member = in.has_##sceneField() ? in.sceneField() : decltype(out.member)(fallback); \
  } else {                                                                   \
    out.member = in.sceneField();                                            \
  }
  IMPULSE_BODY_PROPERTIES(IMPULSE_GET_SCENE_PROPERTY)
#undef IMPULSE_GET_SCENE_PROPERTY
}

namespace detail {

inline std::string readProperty(bool present, bool value, std::string_view, bool fallback, bool& out) {
  out = present ? value : fallback;
  return {};
}

// A number is checked as realFromWire; its range is the engine's to judge
// (World::createBody names the field).
inline std::string readProperty(bool present, double value, std::string_view what, Real fallback, Real& out) {
  if (!present) {
    out = fallback;
    return {};
  }
  Decoded<Real> real = realFromWire(value, what);
  if (!real.ok()) return std::move(real.error);
  out = *real.value;
  return {};
}

}  // namespace detail

/// Reads every body property from a spawn's BodyOptions: the error naming
/// the first field that is not a finite number, or empty.
template <class Message>
std::string getOptionProperties(const Message& in, BodyProperties& out) {
#define IMPULSE_GET_OPTION(member, field, sceneField, fallback)                                       \
  {                                                                                                    \
    bool present = true;                                                                               \
    if constexpr (requires { in.has_##field(); }) present = in.has_##field();                          \
    std::string error = detail::readProperty(present, in.field(), "options." #field,                  \
                                             decltype(out.member)(fallback), out.member);              \
    if (!error.empty()) return error;                                                                  \
  }
  IMPULSE_BODY_PROPERTIES(IMPULSE_GET_OPTION)
#undef IMPULSE_GET_OPTION
  return {};
}

/// Writes the coefficients, each that the message has a field for (a
/// BodyDescriptor has no rolling resistance).
template <class Engine, class Message>
void putCoefficients(const Engine& in, Message& out) {
#define IMPULSE_PUT_COEFFICIENT(member, field) \
  if constexpr (requires { out.set_##field(in.member); }) out.set_##field(in.member);
  IMPULSE_MATERIAL_COEFFICIENTS(IMPULSE_PUT_COEFFICIENT)
#undef IMPULSE_PUT_COEFFICIENT
}

/// Reads every coefficient from a SceneShape or a version 1-2 SceneBody.
template <class Message, class Engine>
void getCoefficients(const Message& in, Engine& out) {
#define IMPULSE_GET_COEFFICIENT(member, field) out.member = in.field();
  IMPULSE_MATERIAL_COEFFICIENTS(IMPULSE_GET_COEFFICIENT)
#undef IMPULSE_GET_COEFFICIENT
}

}  // namespace impulse::wire
