#pragma once
/// The simulated world: bodies, gravity and the fixed step.
///
/// The world does no I/O and starts threads only when its settings ask for
/// workers (impulse/tasks.h). Callers create bodies, call
/// step(dt) at a fixed rate and read states back (movedBodies() lists only
/// bodies whose state changed in the last step; changes() what changed
/// since the reader last cleared them).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "impulse/body.h"
#include "impulse/change_view.h"
#include "impulse/events.h"
#include "impulse/field.h"
#include "impulse/joint.h"
#include "impulse/limits.h"
#include "impulse/math.h"
#include "impulse/query.h"
#include "impulse/shape.h"
#include "impulse/tasks.h"
#include "impulse/world_state.h"

namespace impulse {

struct WorldData;  // private state, defined in common/src/world_data.h

inline const Vec2 kDefaultGravity = Vec2(0, Real(-9.81));

/// Lane width of the contact solver. Best takes AVX2 when the CPU has it;
/// every width gives bit-identical results.
enum class SimdWidth : std::uint8_t { Best, Sse2, Avx2 };

/// How far from (0, 0) a world's origin may be put, in metres on each axis:
/// a double resolves better than a micrometre there.
inline constexpr double kMaxOriginCoordinate = 1e9;

/// Solver and world parameters. The benchmark sweeps them.
struct WorldSettings {
  Vec2 gravity = kDefaultGravity;
  /// Sub-steps per step: more gives stiffer, more accurate contacts.
  int subSteps = 4;
  /// Relaxation passes (no position bias) per sub-step.
  int relaxIterations = 1;
  /// Contact stiffness (Hz) and damping ratio of the soft contact constraint;
  /// the stiffness is capped at a quarter of the sub-step rate for stability.
  Real contactHertz = 30;
  Real contactDampingRatio = 10;
  /// Fastest speed (m/s) at which overlap is pushed out. A contact's soft
  /// push is further held to what its load needs; overlap beyond that is
  /// pushed out through positions only (no velocity), so deep overlaps
  /// resolve without launching bodies.
  Real maxContactPushSpeed = 3;
  /// Approach speeds below this (m/s) do not bounce, so resting stacks stay put.
  Real restitutionThreshold = 1;
  /// Contacts slower than this (m/s) in the tangent direction use static friction.
  Real stickSpeed = Real(0.02);
  SimdWidth simdWidth = SimdWidth::Best;
  bool enableWarmStarting = true;
  bool enableSleep = true;
  /// A body whose fastest point (centre or rim) stays slower than this (m/s)
  /// for timeToSleep seconds may sleep with its island.
  Real linearSleepTolerance = Real(0.05);
  Real timeToSleep = Real(0.5);
  bool enableContinuous = true;
  /// Touches that close faster than this (m/s) are hits (ContactHitEvent).
  Real hitEventThreshold = 1;
  /// Bodies may not be created with a centre outside these bounds, relative
  /// to the world's origin (they move with it, World::shiftOrigin).
  AABB bounds{Vec2(-25, -25), Vec2(50, 45)};
  /// Hard cap on live bodies (the server lowers it).
  int maxBodies = 200000;
  ShapeLimits shapeLimits;
  /// Speeds, spins, gravity, forces and how far out bodies may go.
  InputLimits inputLimits;
  /// Threads for the step (impulse/tasks.h); results are the same bits for
  /// any worker count. Not part of a saved world: it belongs to the machine.
  TaskSettings tasks;
};

/// How much of the last step's constraints the solver's optional passes ran
/// on. Each is chosen per step from what it measures, where the soft rows
/// alone would fall short: the support pass on stacks whose soft contacts
/// would sink (tall or heavy on light), the exact tree pass on acyclic joint
/// groups, the push pass on contacts overlapping deeper than their load.
struct SolverPasses {
  int contacts = 0;        ///< touching contacts solved
  int supportRows = 0;     ///< contacts the support pass held a body up on
  int joints = 0;          ///< joints solved
  int treeJoints = 0;      ///< joints the exact tree pass solved
  int pushedContacts = 0;  ///< contacts the push pass ran on (0: no push)
  /// Of the contacts, the quiet ones: speculative, every point apart and no
  /// impulse carried from the last step (each pass first checks whether
  /// they would act, and leaves their bodies alone where not).
  int quietContacts = 0;
};

/// Wall-clock milliseconds spent in each phase of the last step.
struct StepProfile {
  double pairs = 0;       ///< broad phase: new pairs
  double collide = 0;     ///< narrow phase: manifolds
  double fields = 0;      ///< force fields
  double solve = 0;       ///< contact solver and integration
  double continuous = 0;  ///< time of impact for fast bodies
  double sleep = 0;       ///< islands and sleeping
  double sensors = 0;     ///< sensor overlaps
  double total = 0;
  /// Manifolds the narrow phase recomputed; contacts whose bodies have not
  /// moved keep theirs.
  int manifoldUpdates = 0;
  SolverPasses passes;
};

/// Outcome of a body creation: an id, or a message that says what was wrong.
struct CreateResult {
  BodyId id;
  std::string error;
  bool ok() const { return error.empty(); }
};

/// Outcome of a shape creation: an id, or a message that says what was wrong.
struct ShapeResult {
  ShapeId id;
  std::string error;
  bool ok() const { return error.empty(); }
};

class World {
 public:
  explicit World(const WorldSettings& settings = {});
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  World(World&&) noexcept;
  /// Takes the other world's contents; this world's changes() then say
  /// `replaced`, at a later revision than before.
  World& operator=(World&&) noexcept;

  /// Validates the definition (finite numbers, bounds, shape, body limit).
  CreateResult createBody(const BodyDef& def);
  /// A circle centred at `center` (world).
  CreateResult createCircle(const Vec2& center, Real radius, const BodyOptions& options = {});
  /// A polygon from world-space points in either winding. A simple outline
  /// that is not convex is split (createConcavePolygon).
  CreateResult createPolygon(std::span<const Vec2> points, const BodyOptions& options = {});
  /// A capsule between world points center1 and center2; its centre of mass
  /// is their midpoint.
  CreateResult createCapsule(const Vec2& center1, const Vec2& center2, Real radius, const BodyOptions& options = {});
  /// A segment between world points: static, or kinematic if the options
  /// say so (a segment has no area, so no mass to be dynamic with).
  CreateResult createSegment(const Vec2& point1, const Vec2& point2, const BodyOptions& options = {});
  /// A chain of one-sided segments through world-space points (terrain):
  /// bodies collide on the right of the way the points run (terrain runs
  /// right to left; an anticlockwise loop holds bodies outside it). One body of
  /// up to kMaxShapesPerBody segments; static unless the options say
  /// kinematic. Refused as buildChain refuses.
  CreateResult createChain(std::span<const Vec2> points, bool loop, const BodyOptions& options = {});
  /// A simple polygon (not self-intersecting), convex or not, from
  /// world-space points in either winding: one body of convex pieces.
  CreateResult createConcavePolygon(std::span<const Vec2> points, const BodyOptions& options = {});
  /// Adds a shape to a live body; its geometry is in the body's frame as it
  /// is now (origin at bodyState's position, turned by its angle). The body's
  /// centre of mass moves to the new union's centroid and every shape stays
  /// where it is in the world. Refused, with the reason, past
  /// kMaxShapesPerBody, for an invalid shape, or when the shapes would reach
  /// past kMaxBodyExtent from the centre.
  ShapeResult createShape(BodyId body, const ShapeDef& def);
  /// Removes a shape and its contacts; the body's mass follows. Refused for
  /// an unknown id and for a body's last shape (remove the body instead).
  InputResult destroyShape(ShapeId id);
  /// The body that carries the shape.
  std::optional<BodyId> shapeBody(ShapeId id) const;
  /// The shape's filter, sensor flag and events.
  std::optional<ShapeInteraction> shapeInteraction(ShapeId id) const;
  /// Changes what the shape collides with, whether it is a sensor and the
  /// events it asks for, from the next step on: contacts the new filter
  /// forbids (all of them, for a new sensor) end now, and pairs it allows
  /// are found in the next step. Wakes the body. Refused for an unknown id.
  InputResult setShapeInteraction(ShapeId id, const ShapeInteraction& interaction);
  int shapeCount() const;
  /// Removes a body and wakes what touched it. False for an unknown id.
  bool destroyBody(BodyId id);
  /// Removes every body.
  void clear();

  bool isValid(BodyId id) const;
  std::optional<BodyState> bodyState(BodyId id) const;
  std::optional<BodyDescription> bodyDescription(BodyId id) const;
  /// Every live body's id in slot order.
  std::vector<BodyId> bodyIds() const;
  int bodyCount() const;
  /// The creation order the next body gets: one more than the bodies ever
  /// created in this world (a scene carries it on).
  std::uint64_t nextCreationOrder() const;
  int awakeBodyCount() const;
  int contactCount() const;

  /// Ids whose state changed in the last step: awake bodies and the bodies
  /// that fell asleep in it (a client needs their final rest state).
  std::span<const BodyId> movedBodies() const;

  /// Refused (world unchanged) outside InputLimits::maxGravity.
  InputResult setGravity(const Vec2& gravity);
  Vec2 gravity() const;

  /// Who runs the step's parallel phases from the next step on. Refused
  /// (unchanged) for a worker count outside [1, kMaxWorkers] or only one of
  /// the two callbacks. Settings given at construction are used as far as
  /// they go: the count clamped, a half pair of callbacks ignored.
  InputResult setTaskSettings(const TaskSettings& tasks);
  TaskSettings taskSettings() const;

  /// Wakes the body. The point defaults to the centre of mass. Refused, with
  /// the reason, for an unknown id, a static body, a non-finite vector, a
  /// point outside the bounds grown by the escape margin, or a push that
  /// would take the body past the speed limits (InputLimits).
  InputResult applyImpulse(BodyId id, const Vec2& impulse, std::optional<Vec2> point = std::nullopt);
  /// Force applied over the next step only; refused when the forces pending
  /// on the body would exceed InputLimits' accelerations.
  InputResult applyForce(BodyId id, const Vec2& force, std::optional<Vec2> point = std::nullopt);
  InputResult setVelocity(BodyId id, const Vec2& linear, Real angular);
  /// Gives the body the velocity that takes it to `position` and `angle`
  /// over the next step of `dt` seconds (b2Body_SetTargetTransform): how a
  /// kinematic platform, door or pusher follows a path. Refused, with the
  /// reason, as setVelocity is (speeds past the limits included) and for a
  /// dt that is not positive.
  InputResult setTargetTransform(BodyId id, const Vec2& position, Real angle, Real dt);
  /// Moves the body to `position` (its centre of mass) and `angle` at once,
  /// as b2Body_SetTransform does (a teleport: velocities are kept, nothing is
  /// swept in between). Wakes the body, what touched it where it was and, for
  /// a static body, what lies where it goes. Refused, with the reason, for
  /// an unknown id, a non-finite number or a position outside the bounds.
  InputResult setTransform(BodyId id, const Vec2& position, Real angle);
  /// Gives every shape of the body the material's coefficients (replacing
  /// any per-shape material or override); the mass, centre of mass and
  /// inertia follow the new density. Wakes the body and what touches it.
  /// Refused for an unknown id or material.
  InputResult setMaterial(BodyId id, Material material);
  /// Changes the body's type at run time, as b2Body_SetType does. The mass
  /// comes from the shapes again (a static body has none); the body's
  /// contacts are rebuilt from its new type (two non-dynamic bodies have
  /// none) and what touched it wakes. A static body stops and sleeps; a
  /// kinematic or dynamic one wakes keeping its velocity. Refused, with the
  /// reason and nothing changed: an unknown id or type; dynamic for a body
  /// without area (segments and chains only); kinematic or dynamic for one
  /// whose shapes reach past kMaxBodyExtent; a type that would leave one of
  /// its joints without a dynamic body (or a mouse joint pulling a body that
  /// is not dynamic).
  InputResult setBodyType(BodyId id, BodyType type);

  /// Validates the definition (live, distinct bodies; finite numbers in
  /// range) before anything changes. Wakes both bodies.
  JointResult createJoint(const JointDef& def);
  /// Wakes both bodies. False for an unknown id.
  bool destroyJoint(JointId id);
  /// Refused, with the reason, for an unknown id, a field the kind lacks or
  /// a number out of range. Wakes both bodies.
  InputResult updateJoint(JointId id, const JointUpdate& update);
  std::optional<JointDescription> jointDescription(JointId id) const;
  std::optional<JointState> jointState(JointId id) const;
  /// Every live joint's id in slot order.
  std::vector<JointId> jointIds() const;
  int jointCount() const;

  /// Adds a force field; it acts from the next step on, after the fields
  /// added before it. Wakes every body, as a change of gravity does.
  FieldId addField(std::shared_ptr<const ForceField> field);
  /// False for an unknown id.
  bool removeField(FieldId id);
  int fieldCount() const;
  /// The id the next addField hands out (field ids are never reused).
  std::uint32_t nextFieldId() const;
  /// Every field's id, in the order they apply.
  std::vector<FieldId> fieldIds() const;
  /// The field, or nullptr for an unknown id.
  const ForceField* field(FieldId id) const;

  /// The body whose shape contains the point (the topmost-created if
  /// several), among the shapes the filter accepts; sensors are not seen.
  /// Nothing for a point that is not finite.
  std::optional<BodyId> queryPoint(const Vec2& point, const QueryFilter& filter = {}) const;

  /// Queries (impulse/query.h): every one goes through the broad phase,
  /// skips sensors and the shapes the filter refuses, and refuses bad input
  /// (the error names the field) without touching the world.
  ///
  /// The first shape the segment origin -> origin + translation enters;
  /// equal fractions go to the lower shape slot. A ray that starts inside a
  /// shape does not hit it; a segment is hit from either side, a chain
  /// segment only from its collision side (the right of the way the chain
  /// runs). Refused for a non-finite origin or translation and a
  /// zero-length translation.
  CastResult castRayClosest(const Vec2& origin, const Vec2& translation,
                            const QueryFilter& filter = {}) const;
  /// Every shape the ray enters, nearest first (equal fractions by shape
  /// slot), at most maxHits (1..kMaxQueryResults) of them: the nearest, with
  /// `truncated` set when there were more. Refused as castRayClosest is, and
  /// for maxHits out of range.
  QueryResult<CastHit> castRay(const Vec2& origin, const Vec2& translation,
                               const QueryFilter& filter = {}, int maxHits = kMaxQueryResults) const;
  /// A circle, capsule or polygon (in a frame of its own, placed at `start`)
  /// swept along `translation` without turning: the first shape it touches,
  /// within kShapeCastTolerance (the pose at `fraction` is that close to
  /// touching and never overlapping). A cast that starts overlapping a shape
  /// hits it at fraction 0. Chain segments are hit from their collision side
  /// only. Refused for a shape that validateShape refuses, a segment or
  /// chain segment, a non-finite pose or translation and a zero-length
  /// translation.
  CastResult castShape(const Shape& shape, const Transform& start, const Vec2& translation,
                       const QueryFilter& filter = {}) const;
  /// The shapes whose tight bounding box (computeAABB where the body is
  /// now) overlaps the box, in shape slot order, at most maxResults
  /// (1..kMaxQueryResults). Refused for a box that is not finite or whose
  /// lower corner is above or right of its upper one.
  QueryResult<ShapeId> overlapAABB(const AABB& box, const QueryFilter& filter = {},
                                   int maxResults = kMaxQueryResults) const;
  /// The shapes that truly overlap the shape placed at `transform` (their
  /// separation is negative: touching is not overlapping), in shape slot
  /// order, at most maxResults (1..kMaxQueryResults). Chain segments count
  /// from either side. Refused for a shape that validateShape refuses and a
  /// transform that is not finite.
  QueryResult<ShapeId> overlapShape(const Shape& shape, const Transform& transform,
                                    const QueryFilter& filter = {},
                                    int maxResults = kMaxQueryResults) const;

  /// Advances the world by dt seconds (sub-stepped internally). Ends with the
  /// step guard: no non-finite number and no speed past the limits leaves a
  /// step, and bodies far outside the bounds are removed.
  void step(Real dt);
  /// Bodies the last step removed for leaving the bounds far behind.
  std::span<const BodyId> escapedBodies() const;
  /// The last step's events (impulse/events.h), contact ends caused by
  /// removals since the step before it included; valid until the next step.
  const StepEvents& events() const;
  /// What the step guard did (repairs and clamps since creation).
  const StepGuardReport& guardReport() const;

  /// The large-world origin. Every position the world takes or gives as a
  /// float (bodies, shapes, joint anchors, mouse targets, fields, queries,
  /// contact points, events, the bounds) is relative to it; near it a float
  /// resolves micrometres however far it is from (0, 0). It starts at (0, 0).
  Vec2d origin() const;
  /// Moves the origin to `origin` (metres from (0, 0), in double): every
  /// body, joint anchor held by the world, mouse target, contact point,
  /// field of a built-in kind and broad-phase box is moved by the
  /// difference, so nothing moves in the world itself (to float rounding of
  /// each position at its new place). Call it when the action has moved far
  /// from the origin, between steps. The bounds stay where they are relative
  /// to the origin. Fields of a kind of one's own are not moved (they see
  /// positions relative to the origin). Refused, with the reason and nothing
  /// changed: an origin not finite or past kMaxOriginCoordinate, a body
  /// whose centre would lie further outside the bounds than the escape
  /// margin (the step would remove it), a field that could not be made at
  /// its new place.
  InputResult shiftOrigin(const Vec2d& origin);
  /// A point given from (0, 0), as a position relative to the origin.
  Vec2 toLocal(const Vec2d& point) const;
  /// A position relative to the origin, as a point from (0, 0).
  Vec2d toGlobal(const Vec2& position) const;

  const WorldSettings& settings() const;
  /// Changes solver parameters between steps (gravity and bounds included).
  void setSettings(const WorldSettings& settings);
  const StepProfile& profile() const;
  std::uint64_t stepCount() const;
  double simulatedTime() const;

  /// The whole state (impulse/world_state.h), for saving a scene.
  WorldState exportState() const;
  /// Replaces the world with a saved state, after checking every number,
  /// shape, index and link in it against this world's limits (which it
  /// keeps); refused with the reason, world unchanged, otherwise. The world
  /// then steps on bit-identically to the one that was saved (same build,
  /// same limits).
  InputResult importState(const WorldState& state);

  /// Hash of every body's exact bits (position, rotation, velocities, awake),
  /// for determinism tests.
  std::uint64_t stateHash() const;

  /// What every call that changed the world, and every step, changed since
  /// the last clearChanges (impulse/change_view.h): a mirror of the world
  /// reads this instead of tracking its own calls. A refused call marks
  /// nothing.
  ChangeView changes() const;
  /// Forgets the changes (the revision stays). Until a reader clears them
  /// they only gather: each edit adds at most an id to a list.
  void clearChanges();
  /// Starts or stops listing changes. Off by default: changes() then lists
  /// nothing and only its revision moves, so a world nobody mirrors keeps
  /// no lists. Turned on, the lists start empty.
  void recordChanges(bool on);

 private:
  /// Installs new contents (clear, importState, assignment), keeping this
  /// world's change record, which then says `replaced`.
  void replaceContents(std::unique_ptr<WorldData> next);

  std::unique_ptr<WorldData> impl_;
  StepGuardReport guard_;
};

}  // namespace impulse
