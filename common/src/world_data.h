#pragma once
// Private state of a World, shared by the files that implement the step's
// stages (contacts, fields, solver, islands, continuous). Not a public
// header; each kind of element has its own (body_data.h, contact_data.h,
// contact_constraint.h, solver_data.h).

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "body_data.h"
#include "change_record.h"
#include "shape_data.h"
#include "contact_constraints.h"
#include "contact_data.h"
#include "pair_set.h"
#include "free_list.h"
#include "joint_constraints.h"
#include "joint_data.h"
#include "graph_coloring.h"
#include "slot_bits.h"
#include "impulse/broad_phase.h"
#include "impulse/events.h"
#include "impulse/field.h"
#include "impulse/world.h"
#include "solver_data.h"
#include "task_runner.h"

namespace impulse {

/// A shape overlapping a sensor, and its body (kept for the end event of a
/// visitor that was removed).
struct SensorVisitor {
  ShapeId shape;
  BodyId body;
};

/// A sensor shape and the shapes that overlapped it when last looked at,
/// sorted by id.
struct Sensor {
  std::int32_t shape = kNullIndex;
  std::vector<SensorVisitor> visitors;
};

/// Copies of the shapes of the bodies a field sees, and their addresses,
/// which FieldBody::shapes spans (the world stores geometry by type, not as
/// Shapes). reset() reserves room for every live shape, so the addresses
/// handed out stay valid while the copies fill.
struct FieldShapes {
  std::vector<Shape> copies;
  std::vector<const Shape*> addresses;

  void reset(int liveShapes) {
    copies.clear();
    addresses.clear();
    copies.reserve(std::size_t(liveShapes));
    addresses.reserve(std::size_t(liveShapes));
  }
};

struct FieldSlot {
  FieldId id;
  std::shared_ptr<const ForceField> field;
};

/// How an awake body's boxes are stretched after a solve, and whether one
/// of them left its fat box.
struct BodyReach {
  ProxyMotion motion;
  bool escapes = false;
};

/// What a chunk of the narrow phase's contacts found (contact.cpp).
struct CollideTally {
  std::int32_t touching = 0;
  std::int32_t recomputed = 0;
  std::int32_t eventful = 0;
  /// Where its touching contacts start in the touching list, and its
  /// eventful ones in the eventful list.
  std::int32_t firstTouching = 0;
  std::int32_t firstEventful = 0;
};

/// A shape's tight box as last computed, its body's pose then and the
/// shape's generation (a slot used again holds another shape): until the
/// body has moved or turned far enough for the box to leave its fat box,
/// the box need not be computed again (a settled pyramid's boxes never
/// are). A box of NaN (a slot never anchored) proves nothing.
struct ShapeBoxAnchor {
  AABB tight{Vec2::Constant(std::numeric_limits<Real>::quiet_NaN()),
             Vec2::Constant(std::numeric_limits<Real>::quiet_NaN())};
  Vec2 position = Vec2::Zero();
  Rot rotation;
  std::uint32_t generation = 0;
};

struct WorldData {
  WorldSettings settings;
  /// World::origin: every float position here is relative to it.
  Vec2d origin = Vec2d::Zero();
  TaskRunner tasks;  ///< runs the step's parallel phases (settings.tasks)
  std::vector<Body> bodies;
  FreeList freeBodies;
  int liveBodies = 0;
  std::vector<ShapeSlot> shapes;
  FreeList freeShapes;
  ShapeGeometries shapeGeometries;  ///< the geometry the live shapes point at
  int liveShapes = 0;
  std::uint64_t nextCreationOrder = 1;

  std::vector<Contact> contacts;
  FreeList freeContacts;
  /// Contacts with an awake body: the narrow phase's work. Kept as contacts
  /// come and go and bodies wake and sleep.
  SlotBits activeContacts;
  // Lookup only (never iterated), so its order cannot leak into the step.
  PairSet contactByPair;

  std::vector<Joint> joints;
  FreeList freeJoints;
  int liveJoints = 0;
  /// Counts every joint linked to or unlinked from its bodies: which bodies
  /// are jointed has not changed while it stays.
  std::uint64_t jointLinkChanges = 0;

  /// In the order they were added, which is the order they apply in.
  std::vector<FieldSlot> fields;
  std::uint32_t nextFieldId = 1;

  /// What changed since the reader last cleared it (World::changes). It
  /// belongs to the World, not to its contents: a clear or a load carries
  /// it over.
  ChangeRecord changes;

  /// Sensor shapes by slot, each with what overlapped it after the last step.
  std::vector<Sensor> sensors;
  /// Events since the last step ended (removals between steps included),
  /// moved sorted into `events` when the next one ends.
  StepEvents pendingEvents;
  StepEvents events;

  BroadPhase broadPhase;
  // Awake dynamic bodies in a deterministic order.
  std::vector<std::int32_t> awakeBodies;
  // Where updateSleep merges the bodies woken in a step into awakeBodies
  // (the two swap: both keep their room).
  std::vector<std::int32_t> awakeMerge;
  std::vector<BodyId> movedBodies;

  // The kinds of constraint the solver runs (solver.cpp lists them).
  JointConstraints jointConstraints;
  ContactConstraints contactConstraints;

  // Scratch reused every step, so the steady state allocates nothing.
  std::vector<ProxyPair> newPairs;
  /// The slot each new pair's contact takes, in newPairs' order.
  std::vector<std::int32_t> newContactSlots;
  /// The pair search's lists, one per chunk of queued proxies.
  std::vector<std::vector<ProxyPair>> pairChunks;
  SlotBits contactsToCollide;
  /// The narrow phase's contacts in visiting order, and what updating each
  /// found (parallel first, then applied in that order).
  std::vector<std::int32_t> collideList;
  std::vector<std::uint8_t> collideOutcomes;
  /// Per touching entry of collideList, its key in the touching list
  /// (the lowest slot of its awake bodies).
  std::vector<std::int32_t> collideKeys;
  /// Per chunk of collideList (contact.cpp, listTouching): how many of its
  /// contacts touch, were recomputed, or ask the serial pass for more.
  std::vector<CollideTally> collideTallies;
  /// The positions in collideList whose outcome asks the serial pass for
  /// more (contacts gone apart, events, wakes), in its order.
  std::vector<std::int32_t> eventfulEntries;
  /// Per awake body after the solve: how its boxes stretch, and whether one
  /// left its fat box (world.cpp, solveAndMoveProxies).
  std::vector<BodyReach> awakeReach;
  std::vector<std::uint8_t> shapeGrown;  ///< per shape slot, this step (growEscapingBoxes)
  /// Per shape slot, its tight box where growEscapingBoxes last computed it
  /// (world.cpp, ShapeBoxAnchor).
  std::vector<ShapeBoxAnchor> shapeBoxAnchors;
  /// The bodies continuous collision looks at (the fast ones, then the slow
  /// ones pressed into chains), and whether each was moved.
  std::vector<std::int32_t> fastBodies;
  std::vector<std::uint8_t> fastBodyMoved;
  /// Per touching contact (touchingUnsorted): which of its bodies lies
  /// pressed on a static chain, bit 0 A's, bit 1 B's (continuous.cpp).
  std::vector<std::uint8_t> chainPresses;
  /// Per awake body: whether it moved fast this step (movedFast), found
  /// where the solved bodies' boxes grow, while each body is at hand.
  std::vector<std::uint8_t> awakeBodyFast;
  /// Per moved body: what the step guard found of it (step_guard.cpp).
  std::vector<std::uint8_t> guardFindings;
  /// Per awake body: slow long enough that its island may sleep.
  std::vector<std::uint8_t> sleepCandidates;
  /// The touching contacts with an awake body, in solver order: the narrow
  /// phase's list for this step's solve.
  std::vector<std::int32_t> touchingContacts;
  /// The same contacts in the narrow phase's order, near the order memory
  /// holds them in (reading them so is far cheaper), and for each of
  /// touchingContacts its position there.
  std::vector<std::int32_t> touchingUnsorted;
  std::vector<std::int32_t> touchingOrder;
  std::vector<std::int32_t> touchingKeys;
  std::vector<std::int32_t> touchingStarts;
  std::vector<FieldBody> fieldBodies;
  std::vector<FieldBody> fieldStillBodies;
  FieldShapes fieldBodyShapes;
  FieldShapes fieldStillShapes;
  std::vector<FieldLoad> fieldLoads;
  /// The awake bodies whose field loads come per sub-step this step, and
  /// the sources the fields see meanwhile (field.cpp).
  std::vector<std::int32_t> subSteppedFieldBodies;
  std::vector<FieldBody> fieldSources;
  FieldShapes fieldSourceShapes;
  std::vector<SolverState> solverStates;
  std::vector<SolverIntegration> solverIntegration;
  std::vector<ParkedVelocity> parkedVelocities;
  GraphColoring coloring;
  std::vector<std::int32_t> islandStack;
  std::vector<std::int32_t> islandBodies;
  std::vector<MassProperties> massParts;
  std::vector<SensorVisitor> sensorScratch;
  std::vector<SensorVisitor> sensorChanges;

  StepProfile profile;
  std::uint64_t stepCount = 0;
  std::uint64_t islandStamp = 0;
  double time = 0;

  BodyId idOf(std::int32_t slot) const { return BodyId::make(slot, bodies[slot].generation); }
  ShapeId shapeIdOf(std::int32_t slot) const { return ShapeId::make(slot, shapes[slot].generation); }
  Body* find(BodyId id);
  const Body* find(BodyId id) const;
  ShapeSlot* find(ShapeId id);
  const ShapeSlot* find(ShapeId id) const;

  /// Calls visit(shapeSlot) for each of the body's shapes, in the order they
  /// were added.
  template <typename Visit>
  void forEachShape(std::int32_t body, Visit&& visit) const {
    for (std::int32_t s = bodies[body].shapeHead; s != kNullIndex; s = shapes[s].nextInBody) visit(s);
  }
};

// The stages of the step, in order, one file each (World::step runs them).
void updatePairs(WorldData& world, Real dt);      // contact.cpp: new broad-phase pairs
void collideContacts(WorldData& world, Real dt);  // contact.cpp: manifolds
void applyFields(WorldData& world, Real dt);      // field.cpp: field forces
void applySubStepFields(WorldData& world, int subStep, Real h);  // field.cpp: per sub-step, where a body needs it
void solve(WorldData& world, Real dt);            // solver.cpp: constraints, integration
void solveContinuous(WorldData& world, Real dt);  // continuous.cpp: time of impact
/// Whether a dynamic body moved or turned far enough in the step (half its
/// inner radius) for continuous collision to sweep it (continuous.cpp).
bool movedFast(const Body& body);
void updateSleep(WorldData& world, Real dt);      // island.cpp: islands, sleeping
void updateSensors(WorldData& world, Real dt);    // sensor.cpp: sensor overlaps and events

// Used across stages.
void destroyContact(WorldData& world, std::int32_t contact);     // contact.cpp
void destroyBodyContacts(WorldData& world, std::int32_t body);   // contact.cpp
void destroyShapeContacts(WorldData& world, std::int32_t shape); // contact.cpp
// contact.cpp: the shape's filter or flags changed; its contacts that may no
// longer touch end, the others take its new event requests.
void refilterShapeContacts(WorldData& world, std::int32_t shape);
// contact.cpp: the body's shapes changed; its manifolds are recomputed.
void forgetManifoldFrames(WorldData& world, std::int32_t body);
// contact.cpp: the body woke; its contacts join the active ones.
void activateBodyContacts(WorldData& world, std::int32_t body);
// contact.cpp: the body fell asleep; its contacts whose other body is not
// awake leave the active ones.
void deactivateBodyContacts(WorldData& world, std::int32_t body);
void wakeIsland(WorldData& world, std::int32_t body);            // island.cpp
void addSensor(WorldData& world, std::int32_t shape);            // sensor.cpp
void removeSensor(WorldData& world, std::int32_t shape);         // sensor.cpp
// sensor.cpp: after a load, each sensor's visitors as they are (no events:
// the saved world's last step reported them already).
void rebuildSensors(WorldData& world);
// contact.cpp: whether the contact reports touches and hits, from its shapes.
void setContactEventFlags(const WorldData& world, Contact& contact);
// contact.cpp: the events gathered since the last step, sorted, become the
// step's.
void publishEvents(WorldData& world);
// world.cpp: the shape's tight box where its body is now.
AABB shapeAABB(const WorldData& world, std::int32_t shape);
// world.cpp: the room the shape's type keeps in its fat box (kPolygonRoom),
// and the body's expected motion as the broad phase takes it for one of its
// shapes, with that room.
Real shapeRoom(const WorldData& world, std::int32_t shape);
ProxyMotion shapeMotion(const WorldData& world, std::int32_t shape, ProxyMotion bodyMotion);
// world.cpp: the broad phase learns where the body went (every shape's proxy)
// and, for dt > 0, where its velocity takes it over a step of dt (0: a body
// placed by hand, whose next motion is unknown).
void moveBodyProxies(WorldData& world, std::int32_t body, Real dt = 0);
// contact.cpp: whether any of the body's contacts touches (has points).
bool hasTouchingContact(const WorldData& world, std::int32_t body);
// world.cpp: the body's proxies look for new pairs without having moved.
void touchBodyProxies(WorldData& world, std::int32_t body);
// joint_world.cpp: a joint with collideConnected off between the bodies.
bool jointBlocksContact(const WorldData& world, std::int32_t bodyA, std::int32_t bodyB);
// joint_world.cpp: removes the body's joints, marking them destroyed.
void destroyBodyJoints(WorldData& world, std::int32_t body);
// joint_world.cpp: empty when the settings' numbers are finite and in range.
std::string checkJointSettings(const JointSettings& settings);

}  // namespace impulse
