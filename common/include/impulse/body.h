#pragma once
/// Public description of bodies: handles, creation definitions, state.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "impulse/material.h"
#include "impulse/math.h"
#include "impulse/shape.h"

namespace impulse {

/// Stable body handle. 0 is null. The low bits hold slot index + 1, the high
/// bits a generation that changes each time the slot is reused, so a stale id
/// is recognised instead of silently naming another body. The value travels
/// on the wire as uint32.
struct BodyId {
  std::uint32_t value = 0;

  static constexpr int kIndexBits = 18;
  static constexpr std::uint32_t kIndexMask = (1u << kIndexBits) - 1;
  static constexpr std::uint32_t kGenerationMask = (1u << (32 - kIndexBits)) - 1;

  static BodyId make(std::int32_t slot, std::uint32_t generation) {
    return {((generation & kGenerationMask) << kIndexBits) | (std::uint32_t(slot) + 1)};
  }
  bool isNull() const { return value == 0; }
  std::int32_t slot() const { return std::int32_t(value & kIndexMask) - 1; }
  std::uint32_t generation() const { return value >> kIndexBits; }
  friend bool operator==(BodyId, BodyId) = default;
  friend auto operator<=>(BodyId, BodyId) = default;
};

/// Stable shape handle, with BodyId's layout: 0 is null, a generation
/// recognises a stale id.
struct ShapeId {
  std::uint32_t value = 0;

  static ShapeId make(std::int32_t slot, std::uint32_t generation) {
    return {BodyId::make(slot, generation).value};
  }
  bool isNull() const { return value == 0; }
  std::int32_t slot() const { return BodyId{value}.slot(); }
  std::uint32_t generation() const { return BodyId{value}.generation(); }
  friend bool operator==(ShapeId, ShapeId) = default;
  friend auto operator<=>(ShapeId, ShapeId) = default;
};

/// How a body moves: never (static: infinite mass, no velocity), by its
/// own velocity only (kinematic: infinite mass, pushes dynamic bodies and is
/// never pushed), or by gravity, forces and contacts (dynamic).
enum class BodyType : std::uint8_t { Static, Kinematic, Dynamic };

/// Coefficients that replace the material's for one body, for scenes that
/// need values outside the material table (tools, benchmarks). Unset fields
/// keep the material's value.
struct MaterialOverride {
  std::optional<Real> density = std::nullopt;            ///< kg/m^2, > 0
  std::optional<Real> restitution = std::nullopt;        ///< 0..1
  std::optional<Real> staticFriction = std::nullopt;     ///< >= 0
  std::optional<Real> dynamicFriction = std::nullopt;    ///< >= 0
  std::optional<Real> rollingResistance = std::nullopt;  ///< >= 0
};

/// Which shapes collide, decided as Box2D v3 decides it: shapes of one
/// positive group index always collide, of one negative group never; other
/// pairs collide when each one's category has a bit in the other's mask.
struct CollisionFilter {
  std::uint64_t categoryBits = 1;
  std::uint64_t maskBits = ~std::uint64_t{0};
  std::int32_t groupIndex = 0;
  friend bool operator==(const CollisionFilter&, const CollisionFilter&) = default;
};

bool shouldCollide(const CollisionFilter& a, const CollisionFilter& b);

/// What a query sees: shapes whose category has a bit in maskBits and whose
/// mask has a bit of categoryBits.
struct QueryFilter {
  std::uint64_t categoryBits = 1;
  std::uint64_t maskBits = ~std::uint64_t{0};
};

bool queryAccepts(const QueryFilter& query, const CollisionFilter& shape);

/// How a shape meets others besides its geometry: what it collides with,
/// whether it is a sensor, and which events it asks for. Events cost only
/// the shapes that ask for them.
struct ShapeInteraction {
  CollisionFilter filter;
  /// Reports the shapes overlapping it (sensor events) and never collides.
  bool isSensor = false;
  /// Sensors see this shape (when it is not a sensor itself).
  bool enableSensorEvents = true;
  /// Begin and end touch events for this shape's contacts.
  bool enableContactEvents = false;
  /// Hit events: touches that begin faster than the world's hit threshold.
  bool enableHitEvents = false;
  friend bool operator==(const ShapeInteraction&, const ShapeInteraction&) = default;
};

/// One shape of a body: its geometry in the body's frame and its material.
struct ShapeDef {
  Shape shape;
  Material material = Material::Solid;
  MaterialOverride materialOverride;
  ShapeInteraction interaction;
};

/// Most shapes one body may carry, and how far (m) any point of a moving
/// (dynamic or kinematic) body's shapes may lie from its centre of mass.
inline constexpr int kMaxShapesPerBody = 1024;
/// A world holds at most this many shapes per body of its body limit
/// (WorldSettings::maxBodies), however they are spread over its bodies.
inline constexpr int kShapesPerBodyOfLimit = 4;
inline constexpr Real kMaxBodyExtent = 50;

/// A body's own properties: its type and how gravity and air act on it
/// (the material belongs to its shapes, the motion to its state). Declared
/// once: BodyOptions and BodyDef hold the ones a body is made with,
/// BodyDescription the ones it has, and a saved scene's body slot the ones it
/// had; each copies them whole.
struct BodyProperties {
  bool isStatic = false;
  /// Moved only by its velocity (setVelocity, setTargetTransform): infinite
  /// mass, no gravity, forces or drag; pushes dynamic bodies, never pushed.
  bool isKinematic = false;
  bool ignoreGravity = false;
  /// Air drag rates in 1/s: dv/dt = -linearDrag * v, exact over any dt.
  Real linearDrag = 0;
  Real angularDrag = 0;
  /// The body feels gravityScale * gravity (unless ignoreGravity).
  Real gravityScale = 1;

  bool isDynamic() const { return !isStatic && !isKinematic; }
  BodyType type() const { return isStatic ? BodyType::Static : isKinematic ? BodyType::Kinematic : BodyType::Dynamic; }
  void setType(BodyType type) {
    isStatic = type == BodyType::Static;
    isKinematic = type == BodyType::Kinematic;
  }
  friend bool operator==(const BodyProperties&, const BodyProperties&) = default;
};

/// Ranges of the per-body properties that the material table does not hold.
inline constexpr Real kMaxDrag = 1000;         ///< 1/s, linear and angular
inline constexpr Real kMaxGravityScale = 10;   ///< |gravityScale|

/// Empty when the properties are consistent (not static and kinematic at
/// once) and every number is finite and in its range, else what is wrong.
std::string validateBodyProperties(const BodyProperties& properties);

/// A body created from user-facing input (wire commands, tools): validated
/// fully before anything changes.
struct BodyOptions {
  Material material = Material::Solid;
  BodyProperties properties{};
  /// False: the body starts asleep (BodyDef::isAwake).
  bool isAwake = true;
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  /// Per-body coefficients replacing the material's (unset: the material's).
  MaterialOverride materialOverride{};
  /// Every shape's filter, sensor flag and events.
  ShapeInteraction interaction{};
};

/// Everything needed to create a body. Its shapes are given in a frame whose
/// origin is `position`, turned by `angle`; the body's centre of mass is the
/// union's centroid, and the shapes are kept relative to it. A body of one
/// shape centred on the origin (the usual case) has its centre at `position`.
struct BodyDef {
  /// The first shape, made of `material` (with `materialOverride`).
  Shape shape;
  /// Further shapes, each with a material of its own (compound bodies).
  std::vector<ShapeDef> extraShapes;
  Vec2 position = Vec2::Zero();
  Real angle = 0;
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  Material material = Material::Solid;
  MaterialOverride materialOverride;
  /// The first shape's filter, sensor flag and events.
  ShapeInteraction interaction;
  BodyProperties properties;
  /// False: the body starts asleep (b2BodyDef::isAwake). It keeps still,
  /// costing nothing per step, until something touches it, a push or a
  /// joint wakes it, or the world changes (gravity, a field). Static bodies
  /// are never awake.
  bool isAwake = true;
};

/// The definition of a body of `shape` (local to its centroid) whose
/// centroid goes to `position`, with the options' material and motion.
BodyDef makeBodyDef(const Shape& shape, const Vec2& position, const BodyOptions& options);

/// Empty when every coefficient given is finite and in its range, else what
/// is wrong.
std::string validateMaterialOverride(const MaterialOverride& materialOverride);

/// The material's coefficients with the override's given ones in their place.
MaterialProperties resolveCoefficients(Material material, const MaterialOverride& materialOverride);

/// Snapshot of one body's motion.
struct BodyState {
  BodyId id;
  Vec2 position = Vec2::Zero();  ///< centre of mass
  Real angle = 0;
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  bool awake = false;
};

/// One shape of a body as the world holds it: geometry relative to the
/// body's centre of mass and the coefficients in force.
struct ShapeDescription {
  ShapeId id;
  Shape shape;
  Material material = Material::Solid;
  MaterialProperties coefficients{};
  ShapeInteraction interaction;
};

/// What does not change over a body's life but by an edit. The shape,
/// material and coefficients are its first shape's; `shapes` lists every
/// shape.
struct BodyDescription {
  BodyId id;
  Shape shape;
  Material material = Material::Solid;
  BodyProperties properties;
  MassProperties mass;  ///< zero mass and inertia for static bodies
  Real restitution = 0;
  Real staticFriction = 0;
  Real dynamicFriction = 0;
  Real rollingResistance = 0;
  Real density = 0;  ///< kg/m^2, the one the mass came from
  std::vector<ShapeDescription> shapes;
};

}  // namespace impulse
