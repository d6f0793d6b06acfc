#pragma once
// A body as the step sees it (the public face is body.h and World).

#include <cstdint>

#include "edge_list.h"
#include "impulse/body.h"
#include "impulse/math.h"
#include "impulse/shape.h"

namespace impulse {

// The body's own properties (impulse/body.h) are a base, not a member, so
// the step reads them as body.isStatic; they are copied whole through
// properties().
// Laid out by who reads what, on whole cache lines: the first line holds
// what the narrow phase and the solver's contact refs read of every
// touching body (after the properties, which a base must open with); the
// first two all that the solver's load and finish of an awake body read;
// the third what island walks, events and the fields read.
struct alignas(64) Body : BodyProperties {
  BodyProperties& properties() { return *this; }
  const BodyProperties& properties() const { return *this; }

  Transform transform;
  Vec2 linearVelocity = Vec2::Zero();
  Real invMass = 0;
  Real invInertia = 0;
  // Sizes used by sleeping (how fast the rim moves) and continuous collision
  // (how far a body may move in a step before it could skip a thin wall).
  // Over all of the body's shapes: the farthest point from the centre of
  // mass, and the thinnest shape's inner radius.
  Real extent = 0;
  // Index into the solver's state array during a step (0 = static dummy).
  std::int32_t solverIndex = 0;
  // Head of this body's joint edge list.
  std::int32_t jointHead = kNullIndex;
  bool alive = false;
  bool awake = false;
  // Its field loads come per sub-step this step (field.cpp).
  bool fieldsPerSubStep = false;

  MassProperties mass;
  Real angularVelocity = 0;
  Real innerRadius = 0;
  Real sleepTime = 0;
  // Centre at the start of the step (continuous collision sweeps from it).
  Vec2 center0 = Vec2::Zero();
  Rot rotation0;
  // First of this body's shapes (ShapeSlot::nextInBody links the rest).
  std::int32_t shapeHead = kNullIndex;
  Vec2 force = Vec2::Zero();
  Real torque = 0;

  // Head of this body's contact edge list (edge_list.h).
  std::int32_t contactHead = kNullIndex;
  std::int32_t shapeCount = 0;
  std::uint32_t generation = 0;
  // How fast the fields' part of `force` changes over the step (field.cpp).
  Vec2 fieldForceChange = Vec2::Zero();
  std::uint64_t islandMark = 0;
  std::uint64_t creationOrder = 0;
};

}  // namespace impulse
