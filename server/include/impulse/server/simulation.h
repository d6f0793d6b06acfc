#pragma once
/// The served world: the only way to change it, with the server's limits
/// on top of the engine's. The world records what each change changed
/// (World::changes): takeChanges hands that to the snapshots and version()
/// names the state, so nothing here or in the callers records a change (a
/// command's "changed" is the version moving).

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse.pb.h"

#include "impulse/field_kinds.h"
#include "impulse/material.h"
#include "impulse/scenes/presets.h"
#include "impulse/server/field_budget.h"
#include "impulse/server/server_bodies.h"
#include "impulse/server/tick_schedule.h"
#include "impulse/server/world_changes.h"
#include "impulse/world.h"

namespace impulse::server {

/// A field added, or why it was refused.
struct FieldResult {
  FieldId id;
  std::string error;
  bool ok() const { return error.empty(); }
};

struct SimulationSettings {
  double tickHz = 60;
  int subSteps = 4;
  int maxBodies = 10000;
  int preset = 0;
  bool paused = false;
  FieldLimits fieldLimits{};
  /// The server-wide body count this world is part of; none: unbounded.
  std::shared_ptr<ServerBodies> serverBodies = nullptr;
  /// Bodies may not be created with a centre outside (WorldSettings::bounds,
  /// relative to the origin).
  AABB bounds = WorldSettings{}.bounds;
  /// The world's origin (World::shiftOrigin): where its float positions are
  /// precise. Presets load around it when the bounds hold their scene
  /// there (else centred on the bounds: Simulation::loadPreset); scenes are
  /// moved to the world's.
  Vec2d origin = Vec2d::Zero();
  /// Worker threads for the world's step (the room's share of the stepping pool).
  TaskSettings tasks{};
};

/// Events messages a Simulation keeps for its room between takes.
inline constexpr std::size_t kMaxPendingEventMessages = 64;

/// Range of SetTimeScale (docs/protocol.md, "Time").
inline constexpr double kMinTimeScale = 0.01;
inline constexpr double kMaxTimeScale = 16;

/// What a snapshot says besides bodies.
struct SnapshotMeta {
  std::uint64_t tick = 0;
  double simTime = 0;
  bool paused = false;
  double timeScale = 1;
};

class Simulation {
 public:
  explicit Simulation(const SimulationSettings& settings);

  const World& world() const { return world_; }

  /// Advances one tick.
  void step();
  /// Bodies are refused past the body limit, past the fields' cost budget
  /// (field_budget.h) when the world has fields, and past the server-wide
  /// limit (server_bodies.h).
  CreateResult createCircle(const Vec2& center, Real radius, const BodyOptions& options);
  CreateResult createPolygon(std::span<const Vec2> points, const BodyOptions& options);
  CreateResult createCapsule(const Vec2& center1, const Vec2& center2, Real radius, const BodyOptions& options);
  CreateResult createSegment(const Vec2& point1, const Vec2& point2, const BodyOptions& options);
  CreateResult createChain(std::span<const Vec2> points, bool loop, const BodyOptions& options);
  /// A body of any shapes (World::createBody).
  CreateResult createBody(const BodyDef& def);
  /// The velocity that takes the body to the pose over the next world step.
  InputResult setTargetTransform(BodyId id, const Vec2& position, Real angle);
  /// World::setTransform, setMaterial and setBodyType; a new material or
  /// type goes out as the body's descriptor again.
  InputResult setTransform(BodyId id, const Vec2& position, Real angle);
  InputResult setMaterial(BodyId id, Material material);
  InputResult setBodyType(BodyId id, BodyType type);
  /// False for an unknown id.
  bool removeBody(BodyId id);
  InputResult applyImpulse(BodyId id, const Vec2& impulse, std::optional<Vec2> point);
  InputResult setVelocity(BodyId id, const Vec2& linear, Real angular);
  /// Every shape of the body takes the flags (World::setShapeInteraction);
  /// its descriptor is sent again.
  InputResult setShapeFlags(BodyId id, const ShapeInteraction& flags);
  /// While wanted, each step with events leaves an Events message for
  /// takeEvents (at most kMaxPendingEventMessages wait; past them a step's
  /// events are dropped and the next message's sequence shows the gap).
  void setEventsWanted(bool wanted);
  /// The Events messages (ServerMessage.events) of the steps since the
  /// last call. Valid until the next call.
  std::vector<v1::ServerMessage>& takeEvents();
  InputResult setGravity(const Vec2& gravity);
  JointResult createJoint(const JointDef& def);
  /// False for an unknown id.
  bool removeJoint(JointId id);
  InputResult updateJoint(JointId id, const JointUpdate& update);
  /// The field, or the error naming the refused number, or the field limit
  /// or cost budget it would break (world unchanged).
  FieldResult addField(const FieldDef& def);
  /// False for an unknown id.
  bool removeField(FieldId id);
  /// Replaces the world with preset `id`, its scene (kSceneSize from the
  /// origin) where it was drawn when the room's bounds hold it there, else
  /// centred on the bounds (docs/networked-play.md, "Large rooms").
  /// Refused, with the reason and the world untouched: an id out of range,
  /// bounds smaller than the scene.
  InputResult loadPreset(int id, Material selected);
  /// Removes every body.
  void clear();
  /// Replaces the world with a serialised Scene (docs/scenes.md), moved to
  /// this world's origin; refused, with the reason and the world untouched,
  /// when it does not parse, the engine refuses its state, a body would lie
  /// outside the bounds at this origin, or its fields break the field limits.
  InputResult loadScene(std::string_view data);
  void setPaused(bool paused);
  /// Simulated seconds per wall second, kMinTimeScale..kMaxTimeScale; an
  /// error naming the range otherwise (nothing changes).
  InputResult setTimeScale(double scale);
  /// One wall tick passed on the clock: how many world steps the time scale
  /// owes now (0 at most ticks below 1x, `scale` at whole scales above). The
  /// caller runs them with step(); those it cannot fit are simply not run.
  int stepsDueThisTick();

  std::uint64_t tick() const { return tick_; }
  double tickHz() const { return tickHz_; }
  double simTime() const { return double(tick_) / tickHz_; }
  bool paused() const { return paused_; }
  double timeScale() const { return timeScale_; }
  SnapshotMeta meta() const { return {tick_, simTime(), paused_, timeScale_}; }
  /// The preset in force (cleared worlds keep the last one's text).
  const PresetInfo& preset() const { return preset_; }
  /// Changes with every change of the world or its meta: names its state.
  std::uint64_t version() const;
  /// Changes each time the world is replaced (clear, preset, scene), after
  /// which body and joint ids start over.
  std::uint64_t worldGeneration() const { return worldGeneration_; }
  /// The world's changes since the last call, which the world then forgets.
  /// Valid until the next call; its lists keep their capacity, so a
  /// broadcast allocates no new ones.
  WorldChanges& takeChanges();

  /// Wall-clock milliseconds of the world steps over the last second.
  const TickTimes& stepTimes() const { return stepTimes_; }
  /// World::stateHash(), computed at most once per change of the world.
  std::uint64_t stateHash();
  /// Bodies removed so far for leaving the world bounds far behind.
  std::uint64_t bodiesLeftWorld() const { return bodiesLeftWorld_; }

 private:
  /// Builds preset `id` with its scene centred on the room's bounds, in a
  /// world of its own that replaces this one when the preset is made.
  InputResult loadPresetCentred(int id, Material selected);
  /// Creates a body by `make` unless spawnRefusal() says why not (a
  /// refused creation changes nothing).
  template <class Make>
  CreateResult spawn(Make make);
  /// After a step: its events as an Events message, when wanted.
  void recordEvents();
  /// After the world was replaced: its bodies are counted again and its
  /// ids start over.
  void startWorldGeneration();
  /// Why one more body may not be made (fields' cost, server-wide limit,
  /// creation counter at the most a scene may carry).
  std::string spawnRefusal() const;

  double tickHz_;
  FieldLimits fieldLimits_;
  /// The room's bounds, relative to `roomOrigin_` (where the world starts).
  AABB roomBounds_;
  Vec2d roomOrigin_;
  World world_;
  /// This world's bodies in the server's total (after every change).
  ServerBodies::Share serverShare_;
  /// The changes last taken (takeChanges), kept for their lists' capacity.
  WorldChanges taken_;
  PresetInfo preset_;
  /// Changes of the meta (pause, time scale): the version adds them to the
  /// world's revision.
  std::uint64_t metaChanges_ = 0;
  std::uint64_t worldGeneration_ = 0;
  std::uint64_t tick_ = 0;
  bool paused_ = false;
  double timeScale_ = 1;
  // Wall ticks since the scale was set and steps owed for them so far: the
  // steps due are counted from these, so no rounding error accumulates.
  std::uint64_t ticksAtScale_ = 0;
  std::uint64_t stepsAtScale_ = 0;
  TickTimes stepTimes_;
  std::uint64_t bodiesLeftWorld_ = 0;
  std::uint64_t hash_ = 0;
  std::uint64_t hashVersion_ = ~std::uint64_t(0);
  bool eventsWanted_ = false;
  std::uint64_t eventSequence_ = 0;
  std::vector<v1::ServerMessage> pendingEvents_;
  std::vector<v1::ServerMessage> takenEvents_;
};

}  // namespace impulse::server
