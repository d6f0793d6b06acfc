#include "impulse/server/simulation.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "impulse/wire/event_convert.h"
#include "impulse/wire/scene_convert.h"

namespace impulse::server {

namespace {

WorldSettings worldSettings(const SimulationSettings& settings) {
  WorldSettings world;
  world.subSteps = settings.subSteps;
  world.maxBodies = settings.maxBodies;
  world.bounds = settings.bounds;
  world.tasks = settings.tasks;
  return world;
}

std::string presetTooLarge(const AABB& bounds) {
  const Vec2 size = bounds.upper - bounds.lower;
  char message[160];
  std::snprintf(message, sizeof message,
                "load_preset: the preset scene is %g x %g m: it does not fit in the room's bounds (%g x %g m)",
                double(kSceneSize.x()), double(kSceneSize.y()), double(size.x()), double(size.y()));
  return message;
}

}  // namespace

Simulation::Simulation(const SimulationSettings& settings)
    : tickHz_(settings.tickHz),
      fieldLimits_(settings.fieldLimits),
      roomBounds_(settings.bounds),
      roomOrigin_(settings.origin),
      world_(worldSettings(settings)),
      serverShare_(settings.serverBodies),
      paused_(settings.paused),
      stepTimes_(std::size_t(settings.tickHz + 0.5)) {
  world_.recordChanges(true);
  // An empty world takes any origin the room's bounds allow.
  world_.shiftOrigin(settings.origin);
  // A room smaller than the preset scene starts empty (loadPreset refuses
  // it and keeps the world).
  loadPreset(settings.preset, Material::Solid);
}

void Simulation::step() {
  const auto start = std::chrono::steady_clock::now();
  const Real dt = Real(1.0 / tickHz_);
  if (preset_.drive) preset_.drive(world_, world_.simulatedTime(), dt);
  world_.step(dt);
  ++tick_;
  stepTimes_.record(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  if (!world_.escapedBodies().empty()) serverShare_.set(world_.bodyCount());
  bodiesLeftWorld_ += world_.escapedBodies().size();
  recordEvents();
}

void Simulation::recordEvents() {
  if (!eventsWanted_ || world_.events().empty()) return;
  ++eventSequence_;
  if (pendingEvents_.size() >= kMaxPendingEventMessages) return;
  wire::toWire(world_.events(), tick_, eventSequence_, pendingEvents_.emplace_back().mutable_events());
}

void Simulation::setEventsWanted(bool wanted) { eventsWanted_ = wanted; }

std::vector<v1::ServerMessage>& Simulation::takeEvents() {
  takenEvents_.clear();
  takenEvents_.swap(pendingEvents_);
  return takenEvents_;
}

std::string Simulation::spawnRefusal() const {
  // A scene carrying a larger counter is refused (wire::kMaxNextCreationOrder):
  // past it, the world could not reload its own save.
  if (world_.nextCreationOrder() >= wire::kMaxNextCreationOrder) {
    return "this world has made " + std::to_string(world_.nextCreationOrder() - 1) +
           " bodies in its life, the most a scene may count: clear it or load another scene";
  }
  std::string refusal = bodyRefusal(world_, fieldLimits_);
  return refusal.empty() ? serverShare_.refusal(1) : refusal;
}

template <class Make>
CreateResult Simulation::spawn(Make make) {
  if (std::string refusal = spawnRefusal(); !refusal.empty()) return {{}, std::move(refusal)};
  CreateResult created = make();
  if (created.ok()) serverShare_.set(world_.bodyCount());
  return created;
}

CreateResult Simulation::createCircle(const Vec2& center, Real radius, const BodyOptions& options) {
  return spawn([&] { return world_.createCircle(center, radius, options); });
}

CreateResult Simulation::createPolygon(std::span<const Vec2> points, const BodyOptions& options) {
  return spawn([&] { return world_.createPolygon(points, options); });
}

CreateResult Simulation::createCapsule(const Vec2& center1, const Vec2& center2, Real radius,
                                       const BodyOptions& options) {
  return spawn([&] { return world_.createCapsule(center1, center2, radius, options); });
}

CreateResult Simulation::createSegment(const Vec2& point1, const Vec2& point2, const BodyOptions& options) {
  return spawn([&] { return world_.createSegment(point1, point2, options); });
}

CreateResult Simulation::createChain(std::span<const Vec2> points, bool loop, const BodyOptions& options) {
  return spawn([&] { return world_.createChain(points, loop, options); });
}

CreateResult Simulation::createBody(const BodyDef& def) {
  return spawn([&] { return world_.createBody(def); });
}

InputResult Simulation::setTargetTransform(BodyId id, const Vec2& position, Real angle) {
  return world_.setTargetTransform(id, position, angle, Real(1 / tickHz_));
}

InputResult Simulation::setTransform(BodyId id, const Vec2& position, Real angle) {
  return world_.setTransform(id, position, angle);
}

InputResult Simulation::setMaterial(BodyId id, Material material) {
  return world_.setMaterial(id, material);
}

InputResult Simulation::setBodyType(BodyId id, BodyType type) {
  return world_.setBodyType(id, type);
}

bool Simulation::removeBody(BodyId id) {
  if (!world_.destroyBody(id)) return false;
  serverShare_.set(world_.bodyCount());
  return true;
}

JointResult Simulation::createJoint(const JointDef& def) {
  // The joint slots a scene may carry (wire::sceneSlotLimits): a world
  // always reloads its own save.
  const std::size_t maxJoints = wire::sceneSlotLimits(world_.settings().maxBodies).joints;
  if (std::size_t(world_.jointCount()) >= maxJoints) {
    return {{},
            "joint limit reached: a room holds at most " + std::to_string(maxJoints) + " joints (" +
                std::to_string(wire::kJointSlotsPerBody) + " per body of --max-bodies)"};
  }
  return world_.createJoint(def);
}

bool Simulation::removeJoint(JointId id) { return world_.destroyJoint(id); }

InputResult Simulation::updateJoint(JointId id, const JointUpdate& update) {
  return world_.updateJoint(id, update);
}

InputResult Simulation::applyImpulse(BodyId id, const Vec2& impulse, std::optional<Vec2> point) {
  return world_.applyImpulse(id, impulse, point);
}

InputResult Simulation::setVelocity(BodyId id, const Vec2& linear, Real angular) {
  return world_.setVelocity(id, linear, angular);
}

InputResult Simulation::setShapeFlags(BodyId id, const ShapeInteraction& flags) {
  const std::optional<BodyDescription> description = world_.bodyDescription(id);
  if (!description) return {"unknown body id " + std::to_string(id.value)};
  for (const ShapeDescription& shape : description->shapes)
    world_.setShapeInteraction(shape.id, flags);
  return {};
}

InputResult Simulation::setGravity(const Vec2& gravity) { return world_.setGravity(gravity); }

FieldResult Simulation::addField(const FieldDef& def) {
  FieldBuild build = makeField(def);
  if (!build.ok()) return {{}, build.error};
  // As for bodies: a larger counter than a scene may carry would make the
  // world's own save unloadable.
  if (world_.nextFieldId() >= wire::kMaxNextFieldId) {
    return {{}, "this world has added " + std::to_string(world_.nextFieldId() - 1) +
                    " force fields in its life, the most a scene may count: clear it or load another scene"};
  }
  if (std::string refusal = fieldRefusal(world_, def, fieldLimits_); !refusal.empty()) {
    return {{}, std::move(refusal)};
  }
  return {world_.addField(std::move(build.field)), {}};
}

bool Simulation::removeField(FieldId id) { return world_.removeField(id); }

InputResult Simulation::loadPreset(int id, Material selected) {
  if (id < 0 || id >= kPresetCount) {
    return {"load_preset: preset " + std::to_string(id) + " does not exist (0-" +
            std::to_string(kPresetCount - 1) + ")"};
  }
  // Where the scene was drawn, when the room holds it there (every room
  // around (0, 0) large enough): as presets always loaded.
  if (!roomBounds_.contains(kPresetScene)) return loadPresetCentred(id, selected);
  preset_ = *impulse::loadPreset(world_, id, selected);
  startWorldGeneration();
  return {};
}

InputResult Simulation::loadPresetCentred(int id, Material selected) {
  const Vec2 roomSize = roomBounds_.upper - roomBounds_.lower;
  if (roomSize.x() < kSceneSize.x() || roomSize.y() < kSceneSize.y()) return {presetTooLarge(roomBounds_)};
  // The world's origin goes where the scene's own origin must lie for its
  // centre to be the bounds' centre, and stays there: the preset's script
  // and markers are written around that origin. Clients see no difference
  // (positions leave the room from (0, 0)); floats are finer there still.
  const Vec2d origin = roomOrigin_ + (presetLanding(roomBounds_).lower - kPresetScene.lower).cast<double>();
  const Vec2d roomOffset = roomOrigin_ - origin;
  WorldSettings settings = world_.settings();
  settings.bounds = {(roomBounds_.lower.cast<double>() + roomOffset).cast<Real>(),
                     (roomBounds_.upper.cast<double>() + roomOffset).cast<Real>()};
  World candidate(settings);
  if (InputResult moved = candidate.shiftOrigin(origin); !moved) return {"load_preset: " + moved.error};
  preset_ = *impulse::loadPreset(candidate, id, selected);
  world_ = std::move(candidate);
  startWorldGeneration();
  return {};
}

void Simulation::clear() {
  world_.clear();
  // The cleared world has none of the bodies the preset's script moved.
  preset_.drive = nullptr;
  startWorldGeneration();
}

void Simulation::startWorldGeneration() {
  serverShare_.set(world_.bodyCount());
  ++worldGeneration_;
}

InputResult Simulation::loadScene(std::string_view data) {
  // Loaded beside the world, which stays as it is unless every check passes.
  World candidate(world_.settings());
  InputResult loaded = wire::loadScene(candidate, data);
  if (!loaded) return loaded;
  // Saved with its own origin: moved to the world's, where its bounds are.
  if (InputResult moved = candidate.shiftOrigin(world_.origin()); !moved) return {"scene refused: " + moved.error};
  std::string refusal = worldRefusal(candidate, fieldLimits_);
  if (refusal.empty()) refusal = serverShare_.refusal(candidate.bodyCount() - world_.bodyCount());
  if (!refusal.empty()) return {"scene refused: " + refusal};
  world_ = std::move(candidate);
  // The scene's bodies are not the ones the preset's script moved.
  preset_.drive = nullptr;
  startWorldGeneration();
  return loaded;
}

void Simulation::setPaused(bool paused) {
  paused_ = paused;
  ++metaChanges_;
}

InputResult Simulation::setTimeScale(double scale) {
  if (!(scale >= kMinTimeScale && scale <= kMaxTimeScale)) {
    char message[96];
    std::snprintf(message, sizeof message, "time scale %g must be in [%g, %g]", scale,
                  kMinTimeScale, kMaxTimeScale);
    return {message};
  }
  timeScale_ = scale;
  ticksAtScale_ = 0;
  stepsAtScale_ = 0;
  ++metaChanges_;
  return {};
}

int Simulation::stepsDueThisTick() {
  ++ticksAtScale_;
  // The tiny allowance keeps a scale like 0.1 (not exact in binary) from
  // owing its tenth step one tick late.
  const auto owed = std::uint64_t(std::floor(timeScale_ * double(ticksAtScale_) + 1e-9));
  const auto due = owed - stepsAtScale_;
  stepsAtScale_ = owed;
  return int(due);
}

std::uint64_t Simulation::version() const { return world_.changes().revision + metaChanges_; }

WorldChanges& Simulation::takeChanges() {
  taken_.assign(world_.changes());
  world_.clearChanges();
  return taken_;
}

std::uint64_t Simulation::stateHash() {
  if (hashVersion_ != version()) {
    hash_ = world_.stateHash();
    hashVersion_ = version();
  }
  return hash_;
}

}  // namespace impulse::server
