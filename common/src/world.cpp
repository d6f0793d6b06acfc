// World API: body lifetime, queries and the step that runs the phases.

#include "impulse/world.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstring>
#include <span>
#include <string>
#include <utility>

#include "body_shapes.h"
#include "input_limits.h"
#include "step_guard.h"
#include "world_data.h"

namespace impulse {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

std::string validateDef(const WorldData& world, const BodyDef& def) {
  if (!isFinite(def.position) || !isFinite(def.angle) || !isFinite(def.linearVelocity) ||
      !isFinite(def.angularVelocity)) {
    return "body has a non-finite position, angle or velocity (NaN or infinity)";
  }
  if (std::string error = checkInsideBounds(world, def.position); !error.empty()) return error;
  if (std::string error = checkBodyMotion(world.settings.inputLimits, def.linearVelocity,
                                          def.angularVelocity);
      !error.empty()) {
    return error;
  }
  if (std::string error = validateBodyProperties(def.properties); !error.empty()) return error;
  if (static_cast<int>(def.material) >= kMaterialCount) return "unknown material";
  if (std::string error = validateMaterialOverride(def.materialOverride); !error.empty()) return error;
  if (world.liveBodies >= world.settings.maxBodies) {
    return "body limit reached (" + std::to_string(world.settings.maxBodies) + " bodies)";
  }
  return {};
}

std::int32_t allocateBody(WorldData& world) {
  std::int32_t slot = world.freeBodies.acquire(world.bodies.size());
  if (slot == static_cast<std::int32_t>(world.bodies.size())) world.bodies.emplace_back();
  return slot;
}

// The body's shapes, the first made of the body's own material.
std::vector<ShapeDef> shapeDefsOf(const BodyDef& def) {
  std::vector<ShapeDef> shapes;
  shapes.reserve(def.extraShapes.size() + 1);
  shapes.push_back({def.shape, def.material, def.materialOverride, def.interaction});
  shapes.insert(shapes.end(), def.extraShapes.begin(), def.extraShapes.end());
  return shapes;
}

// The world's shape limit: kShapesPerBodyOfLimit per body of its body limit.
std::string checkShapeRoom(const WorldData& world, std::size_t added) {
  const std::size_t limit = std::size_t(kShapesPerBodyOfLimit) * std::size_t(std::max(world.settings.maxBodies, 0));
  if (std::size_t(world.liveShapes) + added <= limit) return {};
  return "shape limit reached (" + std::to_string(limit) + " shapes: " + std::to_string(kShapesPerBodyOfLimit) +
         " per body of the body limit)";
}

std::string checkShapeDefs(const WorldData& world, const BodyDef& def) {
  if (def.extraShapes.size() + 1 > std::size_t(kMaxShapesPerBody)) {
    return "a body carries at most " + std::to_string(kMaxShapesPerBody) + " shapes (" +
           std::to_string(def.extraShapes.size() + 1) + " given)";
  }
  if (std::string error = checkShapeRoom(world, def.extraShapes.size() + 1); !error.empty()) return error;
  for (const ShapeDef& shape : shapeDefsOf(def)) {
    if (std::string error = checkShapeDef(world, shape); !error.empty()) return error;
  }
  return {};
}

// Undoes a body creation that failed a check made after its shapes were
// attached (the shapes have no proxy yet).
void discardNewBody(WorldData& world, std::int32_t slot) {
  while (world.bodies[slot].shapeHead != kNullIndex) detachShape(world, world.bodies[slot].shapeHead);
  world.bodies[slot].alive = false;
  world.freeBodies.release(slot);
  --world.liveBodies;
}

void wakeAll(WorldData& world) {
  for (std::size_t slot = 0; slot < world.bodies.size(); ++slot) wakeIsland(world, static_cast<std::int32_t>(slot));
}

// How far the body's shapes are expected to move over a step of dt, for the
// broad phase to stretch their boxes along: only a body in free flight (on
// no touching contact) needs it, to meet what lies ahead as a pair before it
// arrives (else a falling body first meets a pile inside it). A body resting
// on or moving with others has them as pairs already; stretching its boxes
// too would pair it with their neighbours (a tumbling drum's crowd: 1.4 times
// the contacts).
ProxyMotion expectedMotion(const Body& body, Real dt, bool touches) {
  if (touches) return {};
  const ProxyMotion motion{body.linearVelocity * dt, body.extent * std::abs(body.angularVelocity) * dt};
  const bool barelyMoves = motion.displacement.norm() + motion.turnReach <= kLinearSlop;
  return barelyMoves ? ProxyMotion{} : motion;
}

// Awake bodies per range when finding the ones whose boxes must grow: a
// body costs its shapes' boxes, tens of nanoseconds.
constexpr std::int32_t kBodiesPerReachRange = 256;

// How far, relative to the coordinates' size, two float computations of a
// shape's box may lie apart: a few roundings each (about 1e-7), with room.
constexpr Real kBoxRounding = 1e-5f;

// Whether shape s's tight box is sure to lie in its fat box without being
// computed: its body, not stretched along a motion, has moved and turned
// since the box's anchor (ShapeBoxAnchor) by less than the anchored box's
// room in the fat box. A point of the body moves by at most the centre's
// move plus |q - q0| (the rotation's change, bounded by |dc| + |ds|) times
// its distance from the centre, at most the body's extent; the float boxes
// both ways may be a few roundings off the exact ones, hence the allowance.
bool staysInFatBox(const WorldData& world, std::int32_t s, const Body& body, const ProxyMotion& motion) {
  if (!motion.displacement.isZero() || motion.turnReach != 0) return false;
  const ShapeBoxAnchor& anchor = world.shapeBoxAnchors[std::size_t(s)];
  if (anchor.generation != world.shapes[s].generation) return false;
  const Transform& now = body.transform;
  const Real turn = std::abs(now.q.c - anchor.rotation.c) + std::abs(now.q.s - anchor.rotation.s);
  const Real moved = (now.p - anchor.position).cwiseAbs().maxCoeff() + turn * body.extent;
  const Real rounding = kBoxRounding * (now.p.cwiseAbs().maxCoeff() + body.extent) + kBoxRounding;
  return world.broadPhase.fatAABBOfUser(s).contains(anchor.tight.expanded(moved + rounding));
}

// The leaves one range of bodies grew, whose ancestors are marked for the
// tree's rebuild a batch at a time (BroadPhase::markGrown). A fixed array:
// nothing allocates while a step runs.
class GrownLeaves {
 public:
  explicit GrownLeaves(BroadPhase& broadPhase) : broadPhase_(broadPhase) {}
  ~GrownLeaves() { mark(); }
  GrownLeaves(const GrownLeaves&) = delete;
  GrownLeaves& operator=(const GrownLeaves&) = delete;

  void add(std::int32_t proxyKey) {
    keys_[count_++] = proxyKey;
    if (count_ == keys_.size()) mark();
  }

 private:
  void mark() {
    broadPhase_.markGrown(std::span(keys_.data(), count_));
    count_ = 0;
  }

  BroadPhase& broadPhase_;
  std::array<std::int32_t, 64> keys_;
  std::size_t count_ = 0;
};

// The tight box of shape s, anchored for staysInFatBox; grows its fat box
// if it left it. Returns whether it did.
bool growBoxIfEscaped(WorldData& world, std::int32_t s, const Body& body, const ProxyMotion& motion,
                      GrownLeaves& grown) {
  const AABB tight = shapeAABB(world, s);
  world.shapeBoxAnchors[std::size_t(s)] = {tight, body.transform.p, body.transform.q, world.shapes[s].generation};
  const std::int32_t proxyKey = world.shapes[s].proxyKey;
  if (!world.broadPhase.resizeLeaf(proxyKey, tight, shapeMotion(world, s, motion))) return false;
  grown.add(proxyKey);
  return true;
}

// Per awake body (in awakeBodies' order), whether it moved fast for
// continuous collision, the motion its boxes are stretched along and whether
// a shape's box no longer held where it is heading; such a shape's box grows
// in place (shapeGrown). Side by side: reads the bodies
// and the solver, and writes only each shape's own leaf (an awake body is
// never static: its proxies are movable).
void growEscapingBoxes(WorldData& world, Real dt) {
  world.awakeReach.resize(world.awakeBodies.size());
  world.awakeBodyFast.resize(world.awakeBodies.size());
  world.shapeGrown.resize(world.shapes.size());
  world.shapeBoxAnchors.resize(world.shapes.size());
  const bool continuous = world.settings.enableContinuous;
  world.tasks.forRanges(std::int32_t(world.awakeBodies.size()), kBodiesPerReachRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          GrownLeaves grownLeaves(world.broadPhase);
                          for (std::int32_t i = begin; i < end; ++i) {
                            const std::int32_t slot = world.awakeBodies[std::size_t(i)];
                            const Body& body = world.bodies[slot];
                            world.awakeBodyFast[std::size_t(i)] = continuous && movedFast(body) ? 1 : 0;
                            // The solver knows which bodies touched: asking it
                            // spares a walk of the body's contact list.
                            BodyReach& reach = world.awakeReach[std::size_t(i)];
                            reach.motion = expectedMotion(body, dt, world.contactConstraints.touches(body.solverIndex));
                            reach.escapes = false;
                            world.forEachShape(slot, [&](std::int32_t s) {
                              const bool grown = !staysInFatBox(world, s, body, reach.motion) &&
                                                 growBoxIfEscaped(world, s, body, reach.motion, grownLeaves);
                              world.shapeGrown[std::size_t(s)] = grown ? 1 : 0;
                              reach.escapes = reach.escapes || grown;
                            });
                          }
                        });
}

// The solve stage; then the broad phase learns where the bodies went and
// where they are heading: the boxes they left grow in place, and the tree
// is rebuilt around them at once.
void solveAndMoveProxies(WorldData& world, Real dt) {
  solve(world, dt);
  growEscapingBoxes(world, dt);
  // Queued one by one, in awake order: the pair search's order.
  for (std::size_t i = 0; i < world.awakeBodies.size(); ++i) {
    const BodyReach& reach = world.awakeReach[i];
    if (!reach.escapes) continue;
    world.forEachShape(world.awakeBodies[i], [&](std::int32_t s) {
      if (world.shapeGrown[std::size_t(s)] != 0) world.broadPhase.queueGrown(world.shapes[s].proxyKey);
    });
  }
  world.broadPhase.rebuildEnlarged([&](int jobCount, auto&& job) {
    world.tasks.forRanges(jobCount, 1, [&](std::int32_t begin, std::int32_t end) {
      for (std::int32_t index = begin; index < end; ++index) job(index);
    });
  });
}

// A world without fields, and without bodies a removed field left taking
// loads per sub-step: the field stage would do nothing.
bool fieldsIdle(const WorldData& world) {
  return world.fields.empty() && world.subSteppedFieldBodies.empty();
}

bool sensorsIdle(const WorldData& world) { return world.sensors.empty(); }

/// One stage of the step: what it runs, where its time is recorded and,
/// for a stage most worlds have nothing for, when it would do nothing (the
/// step then neither runs it nor reads the clock for it: its time is 0).
struct StepStage {
  void (*run)(WorldData& world, Real dt);
  double StepProfile::*time;
  bool (*idle)(const WorldData& world) = nullptr;
};

// The step, in order.
constexpr StepStage kStepStages[] = {
    {updatePairs, &StepProfile::pairs},                   // broad phase: new pairs become contacts
    {collideContacts, &StepProfile::collide},             // narrow phase: manifolds
    {applyFields, &StepProfile::fields, fieldsIdle},      // force fields
    {solveAndMoveProxies, &StepProfile::solve},           // constraints and integration
    {solveContinuous, &StepProfile::continuous},          // fast bodies against thin statics
    {updateSleep, &StepProfile::sleep},                   // islands and sleeping
    {updateSensors, &StepProfile::sensors, sensorsIdle},  // sensor overlaps
};

template <typename T>
void hashBits(std::uint64_t& hash, const T& value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (unsigned char byte : bytes) {
    hash ^= byte;
    hash *= 1099511628211ull;  // FNV-1a 64-bit prime
  }
}

}  // namespace

Body* WorldData::find(BodyId id) { return findLive(bodies, id); }
const Body* WorldData::find(BodyId id) const { return findLive(bodies, id); }

ShapeSlot* WorldData::find(ShapeId id) { return findLive(shapes, id); }
const ShapeSlot* WorldData::find(ShapeId id) const { return findLive(shapes, id); }

Real shapeRoom(const WorldData& world, std::int32_t shape) {
  return world.shapes[shape].type() == ShapeType::Polygon ? kPolygonRoom : kDefaultRoom;
}

ProxyMotion shapeMotion(const WorldData& world, std::int32_t shape, ProxyMotion bodyMotion) {
  bodyMotion.room = shapeRoom(world, shape);
  return bodyMotion;
}

AABB shapeAABB(const WorldData& world, std::int32_t shape) {
  const ShapeSlot& slot = world.shapes[shape];
  return computeAABB(slot.ref(), world.bodies[slot.body].transform);
}

void moveBodyProxies(WorldData& world, std::int32_t body, Real dt) {
  const ProxyMotion motion = expectedMotion(world.bodies[body], dt, hasTouchingContact(world, body));
  world.forEachShape(body, [&](std::int32_t s) {
    world.broadPhase.updateProxy(world.shapes[s].proxyKey, shapeAABB(world, s), shapeMotion(world, s, motion));
  });
}

void touchBodyProxies(WorldData& world, std::int32_t body) {
  world.forEachShape(body, [&](std::int32_t s) { world.broadPhase.touchProxy(world.shapes[s].proxyKey); });
}

World::World(const WorldSettings& settings) : impl_(std::make_unique<WorldData>()) {
  impl_->settings = settings;
}
World::~World() = default;
World::World(World&&) noexcept = default;

World& World::operator=(World&& other) noexcept {
  if (this == &other) return *this;
  guard_ = std::move(other.guard_);
  replaceContents(std::move(other.impl_));
  return *this;
}

// The change record is this world's, not its contents': its reader learns
// that everything was replaced, and the revision keeps counting up.
void World::replaceContents(std::unique_ptr<WorldData> next) {
  if (impl_ && next) next->changes = std::move(impl_->changes);
  if (next) next->changes.replaced();
  impl_ = std::move(next);
  guard_.escaped.clear();
}

ChangeView World::changes() const { return impl_->changes.view(); }

void World::clearChanges() { impl_->changes.clear(); }

void World::recordChanges(bool on) {
  impl_->changes.clear();
  impl_->changes.keepLists(on);
}

CreateResult World::createBody(const BodyDef& def) {
  WorldData& w = *impl_;
  if (std::string error = validateDef(w, def); !error.empty()) return {{}, error};
  if (std::string error = checkShapeDefs(w, def); !error.empty()) return {{}, error};

  std::int32_t slot = allocateBody(w);
  Body& body = w.bodies[slot];
  std::uint32_t generation = body.generation;
  body = Body{};
  body.generation = generation;
  body.alive = true;
  body.properties() = def.properties;
  body.transform = {def.position, Rot::fromAngle(def.angle)};
  ++w.liveBodies;
  for (const ShapeDef& shape : shapeDefsOf(def)) attachShape(w, slot, shape);
  updateBodyMass(w, slot);
  if (std::string error = checkShapesSuitType(w, slot, body.type()); !error.empty()) {
    discardNewBody(w, slot);
    return {{}, error};
  }
  body.creationOrder = w.nextCreationOrder++;
  w.forEachShape(slot, [&](std::int32_t s) { createShapeProxy(w, s); });

  if (def.properties.isStatic) {
    w.forEachShape(slot, [&](std::int32_t s) { wakeBodiesUnder(w, shapeAABB(w, s)); });
  } else {
    body.linearVelocity = def.linearVelocity;
    body.angularVelocity = def.angularVelocity;
    // One created asleep waits, velocity and all, to be touched or woken.
    if (def.isAwake) {
      body.awake = true;
      w.awakeBodies.push_back(slot);
    }
  }
  w.changes.mark(BodyChange::Created, w.idOf(slot));
  return {w.idOf(slot), {}};
}

ShapeResult World::createShape(BodyId id, const ShapeDef& def) {
  WorldData& w = *impl_;
  Body* body = w.find(id);
  if (body == nullptr) return {{}, "no body " + std::to_string(id.value)};
  if (body->shapeCount >= kMaxShapesPerBody) {
    return {{}, "body " + std::to_string(id.value) + " already carries " + std::to_string(kMaxShapesPerBody) +
                    " shapes, the most a body may"};
  }
  if (std::string error = checkShapeDef(w, def); !error.empty()) return {{}, error};
  if (std::string error = checkShapeRoom(w, 1); !error.empty()) return {{}, error};
  const std::int32_t slot = id.slot();
  const std::int32_t s = attachShape(w, slot, def);
  createShapeProxy(w, s);
  if (std::string error = reshapeBody(w, slot); !error.empty()) {
    detachShape(w, s);
    reshapeBody(w, slot);
    return {{}, error};
  }
  if (w.bodies[slot].isStatic) wakeBodiesUnder(w, shapeAABB(w, s));
  w.changes.mark(BodyChange::Redescribed, id);
  return {w.shapeIdOf(s), {}};
}

InputResult World::destroyShape(ShapeId id) {
  WorldData& w = *impl_;
  const ShapeSlot* shape = w.find(id);
  if (shape == nullptr) return {"no shape " + std::to_string(id.value)};
  const std::int32_t body = shape->body;
  if (w.bodies[body].shapeCount == 1) {
    return {"shape " + std::to_string(id.value) + " is its body's only shape: remove the body instead"};
  }
  if (w.bodies[body].isDynamic() && isSolid(shape->type())) {
    int solidShapes = 0;
    w.forEachShape(body, [&](std::int32_t s) { solidShapes += isSolid(w.shapes[s].type()) ? 1 : 0; });
    if (solidShapes == 1) {
      return {"shape " + std::to_string(id.value) + " is the only one with area on a dynamic body: it would have no mass"};
    }
  }
  destroyShapeContacts(w, id.slot());
  detachShape(w, id.slot());
  reshapeBody(w, body);
  w.changes.mark(BodyChange::Redescribed, w.idOf(body));
  return {};
}

CreateResult World::createCircle(const Vec2& center, Real radius, const BodyOptions& options) {
  if (ShapeError error = validateCircle(radius, impl_->settings.shapeLimits); error != ShapeError::None) {
    return {{}, std::string(describe(error))};
  }
  return createBody(makeBodyDef(Shape::makeCircle(radius), center, options));
}

CreateResult World::createPolygon(std::span<const Vec2> points, const BodyOptions& options) {
  PolygonBuild build = buildPolygon(points, impl_->settings.shapeLimits);
  // A simple outline that is not convex becomes a body of convex pieces.
  if (build.error == ShapeError::NonConvex) return createConcavePolygon(points, options);
  if (build.error != ShapeError::None) return {{}, std::string(describe(build.error))};
  return createBody(makeBodyDef(Shape::makePolygon(build.polygon), build.centroid, options));
}

CreateResult World::createCapsule(const Vec2& center1, const Vec2& center2, Real radius,
                                  const BodyOptions& options) {
  const Vec2 middle = Real(0.5) * (center1 + center2);
  return createBody(makeBodyDef(Shape::makeCapsule(center1 - middle, center2 - middle, radius), middle, options));
}

CreateResult World::createSegment(const Vec2& point1, const Vec2& point2, const BodyOptions& options) {
  BodyDef def = makeBodyDef(Shape::makeSegment(Vec2::Zero(), point2 - point1), point1, options);
  def.properties.isStatic = !options.properties.isKinematic;
  return createBody(def);
}

CreateResult World::createChain(std::span<const Vec2> points, bool loop, const BodyOptions& options) {
  ChainBuild chain = buildChain(points, loop);
  if (chain.error != ShapeError::None) return {{}, std::string(describe(chain.error))};
  if (chain.segments.size() > std::size_t(kMaxShapesPerBody)) {
    return {{}, "a chain makes at most " + std::to_string(kMaxShapesPerBody) + " segments (" +
                    std::to_string(chain.segments.size()) + " asked)"};
  }
  // The segments stay where the points put them: the body's origin is the
  // first point, and a chain has no mass to centre.
  const Vec2 origin = points.front();
  auto segment = [&](std::size_t i) { return translated(Shape{chain.segments[i]}, -origin); };
  BodyDef def = makeBodyDef(segment(0), origin, options);
  def.properties.isStatic = !options.properties.isKinematic;
  for (std::size_t i = 1; i < chain.segments.size(); ++i) {
    def.extraShapes.push_back({segment(i), options.material, options.materialOverride, options.interaction});
  }
  return createBody(def);
}

CreateResult World::createConcavePolygon(std::span<const Vec2> points, const BodyOptions& options) {
  ConvexDecomposition split = decomposePolygon(points, impl_->settings.shapeLimits);
  if (split.error != ShapeError::None) return {{}, std::string(describe(split.error))};
  // The pieces are in the points' frame; the body starts at the first point
  // (inside the bounds check) and moves to the union's centroid.
  const Vec2 origin = points.front();
  auto piece = [&](std::size_t i) { return translated(Shape::makePolygon(split.pieces[i]), -origin); };
  BodyDef def = makeBodyDef(piece(0), origin, options);
  for (std::size_t i = 1; i < split.pieces.size(); ++i) {
    def.extraShapes.push_back({piece(i), options.material, options.materialOverride, options.interaction});
  }
  return createBody(def);
}

namespace {

// Removes a body with its contacts and joints.
bool removeBody(WorldData& w, BodyId id) {
  Body* body = w.find(id);
  if (body == nullptr) return false;
  std::int32_t slot = id.slot();
  destroyBodyJoints(w, slot);
  destroyBodyContacts(w, slot);
  while (body->shapeHead != kNullIndex) detachShape(w, body->shapeHead);
  if (body->awake) std::erase(w.awakeBodies, slot);
  body->alive = false;
  body->awake = false;
  ++body->generation;
  w.freeBodies.release(slot);
  --w.liveBodies;
  w.changes.mark(BodyChange::Destroyed, id);
  return true;
}

}  // namespace

bool World::destroyBody(BodyId id) { return removeBody(*impl_, id); }

void World::clear() {
  auto empty = std::make_unique<WorldData>();
  empty->settings = impl_->settings;
  empty->origin = impl_->origin;
  replaceContents(std::move(empty));
}

bool World::isValid(BodyId id) const { return impl_->find(id) != nullptr; }

std::optional<BodyState> World::bodyState(BodyId id) const {
  const Body* body = impl_->find(id);
  if (body == nullptr) return std::nullopt;
  return BodyState{id, body->transform.p, body->transform.q.angle(), body->linearVelocity,
                   body->angularVelocity, body->awake};
}

std::optional<BodyDescription> World::bodyDescription(BodyId id) const {
  const WorldData& w = *impl_;
  const Body* body = w.find(id);
  if (body == nullptr) return std::nullopt;
  BodyDescription out;
  out.id = id;
  w.forEachShape(id.slot(), [&](std::int32_t s) {
    const ShapeSlot& shape = w.shapes[s];
    out.shapes.push_back({w.shapeIdOf(s), shapeOf(shape.ref()), shape.material, shape.coefficients, shape.interaction});
  });
  const ShapeDescription& first = out.shapes.front();
  out.shape = first.shape;
  out.material = first.material;
  out.restitution = first.coefficients.restitution;
  out.staticFriction = first.coefficients.staticFriction;
  out.dynamicFriction = first.coefficients.dynamicFriction;
  out.rollingResistance = first.coefficients.rollingResistance;
  out.density = first.coefficients.density;
  out.properties = body->properties();
  out.mass = body->mass;
  return out;
}

std::optional<BodyId> World::shapeBody(ShapeId id) const {
  const ShapeSlot* shape = impl_->find(id);
  if (shape == nullptr) return std::nullopt;
  return impl_->idOf(shape->body);
}

std::optional<ShapeInteraction> World::shapeInteraction(ShapeId id) const {
  const ShapeSlot* shape = impl_->find(id);
  if (shape == nullptr) return std::nullopt;
  return shape->interaction;
}

InputResult World::setShapeInteraction(ShapeId id, const ShapeInteraction& interaction) {
  WorldData& w = *impl_;
  const ShapeSlot* shape = w.find(id);
  if (shape == nullptr) return {"no shape " + std::to_string(id.value)};
  const BodyId body = w.idOf(shape->body);
  changeShapeInteraction(w, id.slot(), interaction);
  w.changes.mark(BodyChange::Redescribed, body);
  return {};
}

int World::shapeCount() const { return impl_->liveShapes; }

std::vector<BodyId> World::bodyIds() const { return liveIds<BodyId>(impl_->bodies, impl_->liveBodies); }

int World::bodyCount() const { return impl_->liveBodies; }
int World::awakeBodyCount() const { return static_cast<int>(impl_->awakeBodies.size()); }
int World::contactCount() const { return static_cast<int>(impl_->contactByPair.size()); }
std::span<const BodyId> World::movedBodies() const { return impl_->movedBodies; }

InputResult World::setGravity(const Vec2& gravity) {
  if (std::string error = checkGravity(impl_->settings.inputLimits, gravity); !error.empty()) {
    return {error};
  }
  impl_->settings.gravity = gravity;
  // Resting bodies must feel the new gravity.
  wakeAll(*impl_);
  impl_->changes.mark(WorldChange::Settings);
  return {};
}

Vec2 World::gravity() const { return impl_->settings.gravity; }

InputResult World::setTaskSettings(const TaskSettings& tasks) {
  if (!(tasks.workerCount >= 1 && tasks.workerCount <= kMaxWorkers)) {
    return {"worker count " + std::to_string(tasks.workerCount) + " must be in [1, " + std::to_string(kMaxWorkers) +
            "]"};
  }
  if ((tasks.enqueueTask == nullptr) != (tasks.finishTask == nullptr)) {
    return {"enqueueTask and finishTask are given together or not at all"};
  }
  impl_->settings.tasks = tasks;
  return {};
}

TaskSettings World::taskSettings() const { return usableTaskSettings(impl_->settings.tasks); }

InputResult World::applyImpulse(BodyId id, const Vec2& impulse, std::optional<Vec2> point) {
  if (std::string error = checkImpulse(*impl_, id, impulse, point); !error.empty()) return {error};
  Body* body = impl_->find(id);
  wakeIsland(*impl_, id.slot());
  body->linearVelocity += body->invMass * impulse;
  if (point) body->angularVelocity += body->invInertia * cross(*point - body->transform.p, impulse);
  impl_->changes.mark(BodyChange::Moved, id);
  return {};
}

InputResult World::applyForce(BodyId id, const Vec2& force, std::optional<Vec2> point) {
  if (std::string error = checkForce(*impl_, id, force, point); !error.empty()) return {error};
  Body* body = impl_->find(id);
  wakeIsland(*impl_, id.slot());
  body->force += force;
  if (point) body->torque += cross(*point - body->transform.p, force);
  impl_->changes.mark(BodyChange::Moved, id);
  return {};
}

InputResult World::setVelocity(BodyId id, const Vec2& linear, Real angular) {
  if (std::string error = checkSetVelocity(*impl_, id, linear, angular); !error.empty()) {
    return {error};
  }
  Body* body = impl_->find(id);
  wakeIsland(*impl_, id.slot());
  body->linearVelocity = linear;
  body->angularVelocity = angular;
  impl_->changes.mark(BodyChange::Moved, id);
  return {};
}

InputResult World::setTargetTransform(BodyId id, const Vec2& position, Real angle, Real dt) {
  if (!(dt > 0) || !isFinite(dt)) return {"dt must be a positive number of seconds"};
  if (!isFinite(position) || !isFinite(angle)) return {"target position and angle must be finite numbers"};
  const Body* body = impl_->find(id);
  if (body == nullptr) return {"unknown body id " + std::to_string(id.value)};
  const Vec2 linear = (position - body->transform.p) / dt;
  // The shorter way round.
  const Real turn = relativeRotation(body->transform.q, Rot::fromAngle(angle)).angle();
  return setVelocity(id, linear, turn / dt);
}

void World::step(Real dt) {
  WorldData& w = *impl_;
  if (!(dt > 0) || !isFinite(dt)) return;
  const Clock::time_point start = Clock::now();
  w.tasks.configure(w.settings.tasks);
  w.tasks.stepBegins();
  // One clock reading per stage: its end is the next stage's start.
  Clock::time_point stageStart = start;
  for (const StepStage& stage : kStepStages) {
    if (stage.idle != nullptr && stage.idle(w)) {
      w.profile.*stage.time = 0;
      continue;
    }
    stage.run(w, dt);
    const Clock::time_point stageEnd = Clock::now();
    w.profile.*stage.time = millisecondsBetween(stageStart, stageEnd);
    stageStart = stageEnd;
  }
  guardStep(w, guard_);
  for (BodyId id : guard_.escaped) {
    removeBody(w, id);
    w.changes.mark(BodyChange::Escaped, id);
  }
  w.changes.stepped(w.movedBodies);
  publishEvents(w);

  w.profile.total = millisecondsBetween(start, Clock::now());
  ++w.stepCount;
  w.time += dt;
}

FieldId World::addField(std::shared_ptr<const ForceField> field) {
  if (!field) return {};
  FieldId id{impl_->nextFieldId++};
  impl_->fields.push_back({id, std::move(field)});
  wakeAll(*impl_);
  impl_->changes.mark(FieldChange::Added, id);
  return id;
}

bool World::removeField(FieldId id) {
  if (std::erase_if(impl_->fields, [&](const FieldSlot& slot) { return slot.id == id; }) == 0)
    return false;
  impl_->changes.mark(FieldChange::Removed, id);
  return true;
}

int World::fieldCount() const { return static_cast<int>(impl_->fields.size()); }

std::uint32_t World::nextFieldId() const { return impl_->nextFieldId; }

std::uint64_t World::nextCreationOrder() const { return impl_->nextCreationOrder; }

std::vector<FieldId> World::fieldIds() const {
  std::vector<FieldId> ids;
  for (const FieldSlot& slot : impl_->fields) ids.push_back(slot.id);
  return ids;
}

const ForceField* World::field(FieldId id) const {
  for (const FieldSlot& slot : impl_->fields) {
    if (slot.id == id) return slot.field.get();
  }
  return nullptr;
}

std::span<const BodyId> World::escapedBodies() const { return guard_.escaped; }
const StepEvents& World::events() const { return impl_->events; }
const StepGuardReport& World::guardReport() const { return guard_; }

const WorldSettings& World::settings() const { return impl_->settings; }

void World::setSettings(const WorldSettings& settings) {
  Vec2 previousGravity = impl_->settings.gravity;
  impl_->settings = settings;
  if (settings.gravity != previousGravity) setGravity(settings.gravity);
  impl_->changes.mark(WorldChange::Settings);
}

const StepProfile& World::profile() const { return impl_->profile; }
std::uint64_t World::stepCount() const { return impl_->stepCount; }
double World::simulatedTime() const { return impl_->time; }

std::uint64_t World::stateHash() const {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis
  for (std::size_t slot = 0; slot < impl_->bodies.size(); ++slot) {
    const Body& body = impl_->bodies[slot];
    if (!body.alive) continue;
    hashBits(hash, slot);
    hashBits(hash, body.transform.p.x());
    hashBits(hash, body.transform.p.y());
    hashBits(hash, body.transform.q.c);
    hashBits(hash, body.transform.q.s);
    hashBits(hash, body.linearVelocity.x());
    hashBits(hash, body.linearVelocity.y());
    hashBits(hash, body.angularVelocity);
    hashBits(hash, body.awake);
  }
  return hash;
}

}  // namespace impulse
