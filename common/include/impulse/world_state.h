#pragma once
/// A world's whole state as plain data, for saving and loading scenes.
///
/// World::exportState() copies out everything that decides how the world
/// steps on: every body, contact and joint slot (live or free, with the
/// free lists' order, so ids and slot reuse continue as they would have),
/// the contacts' manifolds with their feature keys, warm-start impulses and
/// cached frames, each body's edge lists in their order (they decide the
/// order contacts are gathered, coloured and solved in), the awake list in
/// its order, both broad-phase trees node by node with the queue of moved
/// proxies, the solver settings, the step count, the time and the origin.
/// World::importState() of that state steps on bit-identically (same build).
///
/// Left out, because they do not change what later steps compute: the step's
/// scratch (constraint rows, colouring, island stacks), island marks (only a
/// mark equal to the next step's fresh stamp matters, and none can be), the
/// last step's outputs (moved, escaped, removed lists, profile, guard
/// counters). Force fields are polymorphic objects and are not part of the
/// state yet (see docs/scenes.md).

#include <cstdint>
#include <string>
#include <vector>

#include "impulse/body.h"
#include "impulse/broad_phase.h"
#include "impulse/field_kinds.h"
#include "impulse/joint.h"
#include "impulse/manifold.h"
#include "impulse/material.h"
#include "impulse/math.h"
#include "impulse/shape.h"

namespace impulse {

/// The settings a scene carries: how the world is solved. The limits
/// (bounds, body cap, shape and input limits) and the SIMD width belong to
/// the world that loads the scene, which checks the scene against them.
struct SolverSettingsState {
  Vec2 gravity = Vec2::Zero();
  int subSteps = 0;
  int relaxIterations = 0;
  Real contactHertz = 0;
  Real contactDampingRatio = 0;
  Real maxContactPushSpeed = 0;
  Real restitutionThreshold = 0;
  Real stickSpeed = 0;
  bool enableWarmStarting = true;
  bool enableSleep = true;
  Real linearSleepTolerance = 0;
  Real timeToSleep = 0;
  bool enableContinuous = true;
  Real hitEventThreshold = 1;
};

/// One shape slot. A free slot keeps only its generation.
struct ShapeSlotState {
  bool alive = false;
  std::uint32_t generation = 0;
  std::int32_t body = -1;
  /// Local to the body's centre of mass; polygon normals are kept as they are.
  Shape shape;
  Material material = Material::Solid;
  /// Coefficients in force (the material's, or overridden); the body's mass
  /// follows from its shapes and their densities.
  Real density = 0;
  Real restitution = 0;
  Real staticFriction = 0;
  Real dynamicFriction = 0;
  Real rollingResistance = 0;
  ShapeInteraction interaction;
  std::int32_t proxyKey = -1;
};

/// One body slot. A free slot keeps only its generation.
struct BodySlotState {
  bool alive = false;
  std::uint32_t generation = 0;
  /// The body's shape slots, in the order they were added.
  std::vector<std::int32_t> shapes;
  Transform transform;
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  /// Forces applied for the next step.
  Vec2 force = Vec2::Zero();
  Real torque = 0;
  BodyProperties properties;
  Real sleepTime = 0;
  /// Pose at the start of the last step.
  Vec2 center0 = Vec2::Zero();
  Rot rotation0;
  std::uint64_t creationOrder = 0;
  bool awake = false;
  /// Edge keys (element * 2 + side) of the body's contact and joint lists,
  /// head first.
  std::vector<std::int32_t> contactEdges;
  std::vector<std::int32_t> jointEdges;
};

/// One contact slot between shape slots shapeA and shapeB (their bodies'
/// slots are bodyA and bodyB).
struct ContactSlotState {
  bool alive = false;
  std::int32_t shapeA = -1;
  std::int32_t shapeB = -1;
  std::int32_t bodyA = -1;
  std::int32_t bodyB = -1;
  Manifold manifold;
  ManifoldFrame frame;
  Real staticFriction = 0;
  Real dynamicFriction = 0;
  Real restitution = 0;
  Real rollingResistance = 0;
  bool touching = false;
};

/// One joint slot; bodyB -1 is the world.
struct JointSlotState {
  bool alive = false;
  std::uint32_t generation = 0;
  std::int32_t bodyA = -1;
  std::int32_t bodyB = -1;
  JointSettings settings;
  Vec2 localAnchorA = Vec2::Zero();
  Vec2 localAnchorB = Vec2::Zero();
  Vec2 localAxisA = Vec2(1, 0);
  Real referenceAngle = 0;
  Real referenceTranslation = 0;
  Real referencePerpendicular = 0;
  Real length = 0;
  Vec2 target = Vec2::Zero();
  JointImpulses impulses;
  Vec2 reactionForce = Vec2::Zero();
  Real reactionTorque = 0;
  bool collideConnected = false;
};

/// A force field of one of the built-in kinds, by the numbers it was made
/// from (fields are stateless between steps).
struct FieldSlotState {
  FieldId id;
  FieldDef def;
};

struct WorldState {
  SolverSettingsState settings;
  /// The world's origin (World::origin); every position below is relative
  /// to it.
  Vec2d origin = Vec2d::Zero();
  std::vector<BodySlotState> bodies;
  /// Free slots in the order they are handed out again (last first).
  std::vector<std::int32_t> freeBodies;
  std::uint64_t nextCreationOrder = 1;
  std::vector<ShapeSlotState> shapes;
  std::vector<std::int32_t> freeShapes;
  std::vector<ContactSlotState> contacts;
  std::vector<std::int32_t> freeContacts;
  std::vector<JointSlotState> joints;
  std::vector<std::int32_t> freeJoints;
  /// Fields in the order the step applies them. A field of a kind of one's
  /// own (not made by makeField) cannot be described and is not saved.
  std::vector<FieldSlotState> fields;
  std::uint32_t nextFieldId = 1;
  BroadPhase::State broadPhase;
  /// Awake body slots in the order the step visits them.
  std::vector<std::int32_t> awakeBodies;
  std::uint64_t stepCount = 0;
  double time = 0;
};

}  // namespace impulse
