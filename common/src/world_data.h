#pragma once
// Private state of a World, shared by the files that implement the step
// phases (contacts, solver, islands, continuous). Not a public header.

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "impulse/broad_phase.h"
#include "impulse/manifold.h"
#include "impulse/world.h"
#include "simd.h"

namespace impulse {

inline constexpr std::int32_t kNullIndex = -1;

struct Body {
  Transform transform;
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  Vec2 force = Vec2::Zero();
  Real torque = 0;
  Real invMass = 0;
  Real invInertia = 0;
  MassProperties mass;
  Real linearDrag = 0;
  Real angularDrag = 0;
  // Sizes used by sleeping (how fast the rim moves) and continuous collision
  // (how far a body may move in a step before it could skip a thin wall).
  Real extent = 0;
  Real innerRadius = 0;
  Real sleepTime = 0;
  // Centre at the start of the step (continuous collision sweeps from it).
  Vec2 center0 = Vec2::Zero();
  Rot rotation0;
  std::int32_t proxyKey = kNullIndex;
  // Head of this body's contact edge list (edge key = contact * 2 + side).
  std::int32_t contactHead = kNullIndex;
  // Index into the solver's state array during a step (0 = static dummy).
  std::int32_t solverIndex = 0;
  std::uint64_t islandMark = 0;
  std::uint64_t creationOrder = 0;
  std::uint32_t generation = 0;
  std::int32_t nextFree = kNullIndex;
  Material material = Material::Solid;
  /// The material's coefficients with any per-body override applied.
  MaterialProperties coefficients{};
  bool alive = false;
  bool isStatic = false;
  bool ignoreGravity = false;
  bool awake = false;
};

/// A manifold's geometry in the bodies' own frames, for updating it cheaply
/// while the bodies move only a little (contact.cpp).
struct ManifoldFrame {
  bool computed = false;  ///< false until the narrow phase first ran
  Transform relative;     ///< B's pose in A's frame when it ran
  Vec2 localNormal = Vec2::Zero();  ///< in A's frame
  Vec2 localPointA[2] = {Vec2::Zero(), Vec2::Zero()};  ///< material point on A
  Vec2 localPointB[2] = {Vec2::Zero(), Vec2::Zero()};  ///< material point on B
  Real offset[2] = {0, 0};  ///< separation minus the points' gap along the normal
};

struct Contact {
  std::int32_t bodyA = kNullIndex;
  std::int32_t bodyB = kNullIndex;
  Manifold manifold;
  ManifoldFrame frame;
  CollideFunction collide = nullptr;
  Real staticFriction = 0;
  Real dynamicFriction = 0;
  Real restitution = 0;
  /// Rolling resistance as a length: c_rr times the rolling radius.
  Real rollingResistance = 0;
  // Doubly linked edge lists through both bodies (edge keys, see Body).
  std::int32_t edgePrev[2] = {kNullIndex, kNullIndex};
  std::int32_t edgeNext[2] = {kNullIndex, kNullIndex};
  std::int32_t nextFree = kNullIndex;
  std::uint64_t pairKey = 0;
  bool touching = false;
};

/// Velocity and accumulated motion of an awake body during a step: the hot
/// data the contact solver streams through every sub-step (32 bytes).
struct SolverState {
  Vec2 linearVelocity = Vec2::Zero();
  Real angularVelocity = 0;
  Vec2 deltaPosition = Vec2::Zero();
  Rot deltaRotation;
  Real padding = 0;
};

/// A touching contact the solver takes this step, with its bodies' solver
/// states (0: the static dummy, for anything not awake).
struct ConstraintRef {
  std::int32_t contact = kNullIndex;
  std::int32_t stateA = 0;
  std::int32_t stateB = 0;
};

/// A body's real velocity, set aside while the push pass borrows the state's
/// velocity slots for pseudo velocities.
struct ParkedVelocity {
  Vec2 linear = Vec2::Zero();
  Real angular = 0;
};

/// Per-body integration inputs, read once per sub-step.
struct SolverIntegration {
  Vec2 linearAcceleration = Vec2::Zero();  ///< gravity plus force / mass
  Real angularAcceleration = 0;
  Real linearDamping = 1;   ///< velocity factor per sub-step
  Real angularDamping = 1;
  std::int32_t body = kNullIndex;
};

struct Softness {
  Real biasRate = 0;
  Real massScale = 1;
  Real impulseScale = 0;
};

struct ConstraintPoint {
  Vec2 anchorA = Vec2::Zero();
  Vec2 anchorB = Vec2::Zero();
  Real baseSeparation = 0;
  Real normalImpulse = 0;
  Real tangentImpulse = 0;
  Real totalNormalImpulse = 0;
  Real normalMass = 0;
  Real tangentMass = 0;
  Real relativeVelocity = 0;
  Real friction = 0;
  /// Overlap at which the soft contact holds the load it carried last step.
  Real loadOverlap = 0;
  /// Fastest the soft contact may push (m/s): enough to carry that load.
  Real pushCap = 0;
};

struct ContactConstraint {
  std::int32_t stateA = 0;
  std::int32_t stateB = 0;
  std::int32_t contact = kNullIndex;
  int pointCount = 0;
  Vec2 normal = Vec2::Zero();
  Real invMassA = 0;
  Real invInertiaA = 0;
  Real invMassB = 0;
  Real invInertiaB = 0;
  Real restitution = 0;
  Real rollingResistance = 0;
  Real rollingImpulse = 0;
  Real rollingMass = 0;
  Softness softness;
  ConstraintPoint points[2];
};

// Constraints side by side for the SIMD solver (contact_solver_wide.h), as
// many as the lane type F holds: four on SSE2, eight on AVX2.
template <class F>
struct WidePoint {
  F anchorAX, anchorAY, anchorBX, anchorBY;
  F baseSeparation;
  F normalImpulse, tangentImpulse, totalNormalImpulse;
  F normalMass, tangentMass;
  F relativeVelocity, friction;
  F loadOverlap, pushCap;
};

template <class F>
struct WideConstraint {
  std::int32_t stateA[F::kLanes];
  std::int32_t stateB[F::kLanes];
  /// The contact each lane came from (-1: padding).
  std::int32_t source[F::kLanes];
  F normalX, normalY;
  F invMassA, invInertiaA, invMassB, invInertiaB;
  F biasRate, massScale, impulseScale;
  F restitution, rollingResistance, rollingMass, rollingImpulse;
  WidePoint<F> points[2];
};

// Eight-lane bundles: a type only the AVX2 file completes (see simd_avx2.h
// on why no other file may lay them out).
struct Avx2Bundles;
struct Avx2BundlesDeleter {
  void operator()(Avx2Bundles* bundles) const;  // contact_solver_wide_avx2.cpp
};

struct WideContactSet {
  /// Bundles of the width in use (the other stays empty).
  std::vector<WideConstraint<simd::F4>> bundles4;
  std::unique_ptr<Avx2Bundles, Avx2BundlesDeleter> bundles8;
  std::vector<ContactConstraint> overflow;
  // Scratch for colouring, kept to avoid allocation per step.
  std::vector<std::uint64_t> usedColors;
  std::vector<std::int32_t> colorOf;
  std::vector<std::int32_t> order;
};

struct WorldData {
  WorldSettings settings;
  std::vector<Body> bodies;
  std::vector<Shape> shapes;
  std::int32_t freeBody = kNullIndex;
  int liveBodies = 0;
  std::uint64_t nextCreationOrder = 1;

  std::vector<Contact> contacts;
  std::int32_t freeContact = kNullIndex;
  // Lookup only (never iterated), so its order cannot leak into the step.
  std::unordered_map<std::uint64_t, std::int32_t> contactByPair;

  BroadPhase broadPhase;
  // Awake dynamic bodies in a deterministic order.
  std::vector<std::int32_t> awakeBodies;
  std::vector<BodyId> movedBodies;

  // Scratch reused every step, so the steady state allocates nothing.
  std::vector<ProxyPair> newPairs;
  std::vector<std::int32_t> activeContacts;
  std::vector<SolverState> solverStates;
  std::vector<SolverIntegration> solverIntegration;
  std::vector<ParkedVelocity> parkedVelocities;
  std::vector<ConstraintRef> constraintRefs;
  WideContactSet wideContacts;
  std::vector<std::int32_t> islandStack;
  std::vector<std::int32_t> islandBodies;
  std::vector<std::int32_t> stillAwake;

  StepProfile profile;
  std::uint64_t stepCount = 0;
  std::uint64_t islandStamp = 0;
  double time = 0;

  BodyId idOf(std::int32_t slot) const { return BodyId::make(slot, bodies[slot].generation); }
  Body* find(BodyId id);
  const Body* find(BodyId id) const;
};

// Edge list helpers (contact.cpp).
inline std::int32_t edgeKey(std::int32_t contact, int side) { return contact * 2 + side; }
inline std::int32_t edgeContact(std::int32_t key) { return key >> 1; }
inline int edgeSide(std::int32_t key) { return key & 1; }
/// The body at the other end of an edge.
inline std::int32_t otherBody(const Contact& c, std::int32_t key) {
  return edgeSide(key) == 0 ? c.bodyB : c.bodyA;
}

// Phases of the step, one file each.
void updatePairs(WorldData& world);                              // contact.cpp
void collideContacts(WorldData& world);                          // contact.cpp
void destroyContact(WorldData& world, std::int32_t contact);     // contact.cpp
void destroyBodyContacts(WorldData& world, std::int32_t body);   // contact.cpp
void solve(WorldData& world, Real dt);                           // solver.cpp
void solveContinuous(WorldData& world);                          // continuous.cpp
void updateSleep(WorldData& world, Real dt);                     // island.cpp
void wakeIsland(WorldData& world, std::int32_t body);            // island.cpp
AABB bodyAABB(const WorldData& world, std::int32_t body);        // world.cpp

}  // namespace impulse
