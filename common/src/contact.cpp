// Contact lifetime: creation from broad-phase pairs, manifold updates with
// warm-start matching, and destruction. Contacts live in one array with a
// free list and are threaded through both bodies' edge lists.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include "contact_events.h"
#include "counting_sort.h"
#include "manifold_internal.h"
#include "prefetch.h"
#include "world_data.h"

namespace impulse {

namespace {

// Threads the contact through both bodies' contact lists.
void linkContact(WorldData& world, std::int32_t index) {
  for (int side = 0; side < 2; ++side) {
    Body& body = world.bodies[world.contacts[index].edges.body(side)];
    linkEdge(world.contacts, body.contactHead, index, side);
  }
}

// A new contact's own fields, from its two shapes: writes nothing but the
// contact, so new contacts fill side by side.
void fillContact(const WorldData& world, Contact& contact, std::int32_t shapeA, std::int32_t shapeB) {
  // The collide table holds each pair of types in one order only.
  if (collideFunction(world.shapes[shapeA].type(), world.shapes[shapeB].type()) == nullptr) {
    std::swap(shapeA, shapeB);
  }
  const ShapeSlot& sa = world.shapes[shapeA];
  const ShapeSlot& sb = world.shapes[shapeB];
  const MaterialProperties& ma = sa.coefficients;
  const MaterialProperties& mb = sb.coefficients;
  contact = Contact{};
  contact.edges.bodyA = sa.body;
  contact.edges.bodyB = sb.body;
  setContactShapes(contact, shapeA, sa, shapeB, sb);
  contact.staticFriction = mixCoefficient(ma.staticFriction, mb.staticFriction);
  contact.dynamicFriction = mixCoefficient(ma.dynamicFriction, mb.dynamicFriction);
  contact.restitution = mixCoefficient(ma.restitution, mb.restitution);
  contact.rollingResistance = mixCoefficient(ma.rollingResistance, mb.rollingResistance) *
                              std::max(sa.rollingRadius, sb.rollingRadius);
  setContactEventFlags(world, contact);
}

// What a filled contact changes besides itself: its bodies' lists, the
// active contacts and the known pairs.
void enlistContact(WorldData& world, std::int32_t index) {
  linkContact(world, index);
  const Contact& contact = world.contacts[index];
  if (world.bodies[contact.edges.bodyA].awake || world.bodies[contact.edges.bodyB].awake) {
    world.activeContacts.insert(index);
  }
  world.contactByPair.insert(contact.pairKey);
}

// A point that persists (same feature id) keeps last step's impulses, so the
// solver starts from last step's answer.
void carryImpulses(const ManifoldPoint& old, ManifoldPoint& point) {
  point.normalImpulse = old.normalImpulse;
  point.tangentImpulse = old.tangentImpulse;
  point.supportImpulse = old.supportImpulse;
}

// carryImpulses for every point of the new manifold that persists, and the
// rolling impulse where it has points.
void matchWarmStart(const Manifold& previous, Manifold& next) {
  for (int i = 0; i < next.pointCount; ++i) {
    ManifoldPoint& point = next.points[i];
    for (int j = 0; j < previous.pointCount; ++j) {
      if (previous.points[j].id != point.id) continue;
      carryImpulses(previous.points[j], point);
      break;
    }
  }
  if (next.pointCount > 0) next.rollingImpulse = previous.rollingImpulse;
}

// B's pose in A's frame.
Transform relativePose(const Body& a, const Body& b) {
  return {a.transform.q.applyInverse(b.transform.p - a.transform.p), relativeRotation(a.transform.q, b.transform.q)};
}

// A contact's manifold is recomputed only once its bodies have moved relative
// to each other since it was computed: slid along the contact or turned by
// more than half a millimetre (at B's rim), or closed or opened by more than
// 5 mm (which stays well inside the 2 cm speculative band the narrow phase
// keeps points for). Until then the manifold's points are carried along with
// the bodies (refreshManifold), exact to first order: a resting or sinking
// stack, or touching bodies falling together, skip the narrow phase.
constexpr Real kSlideTolerance = Real(5e-4);
constexpr Real kApproachTolerance = Real(5e-3);

// A body many times heavier than the one it would land on (a tenth of its
// inverse mass) is stopped at that one's surface within a sub-step only by
// driving the lighter body into whatever holds it up; the soft contacts it
// compresses then throw both back (a box of 100 times the density of a
// pyramid's boxes bounced off it at 1.3 m/s and squeezed a box 18 cm out).
// Its landing is left to the overlap and the split-impulse push, which
// absorb it.
constexpr Real kReachMassRatio = 10;

bool muchHeavier(const Body& body, const Body& other) {
  return (int(other.invMass > 0) & int(body.invMass * kReachMassRatio < other.invMass)) != 0;
}

// How far the gap between two bodies may close within a step of dt. A body
// moving towards the other at all (along the line between their centres)
// may close it by its whole motion: the other may stop mid-step (the lower
// of two circles falling together lands), or a third body may turn its path
// towards the other. A body moving away adds nothing, nor does turning: a
// speculative point that far out on bodies sliding, swinging or rolling
// apart would only stand in their way. The narrow phase keeps points this
// much beyond the speculative distance, so such a closing meets a contact
// at the step's start instead of ending the step deep inside the other body.
// Against a body that cannot move (static or kinematic) nothing changes its
// path that way; there a point out at the reach meets the body a step before
// it lands and bounces it off the speed it had then (a dropped ball's
// rebound height 4.2 -> 6.1 cm off the closed form).
Real closingReach(const Body& a, const Body& b, Real dt) {
  if (a.invMass == 0 || b.invMass == 0) return 0;
  const Vec2 between = b.transform.apply(b.mass.center) - a.transform.apply(a.mass.center);
  // Both speeds, each weighed by 0 or 1, and no branch on which body
  // closes: in a crowd that is a coin toss per contact, and the mispredicted
  // branches were a fifth of the narrow phase's update loop (confined's
  // circles). A speed is finite (the solver caps it), so the weighing picks
  // it or zero exactly.
  const Real aCloses = Real(int(a.linearVelocity.dot(between) > 0) & int(!muchHeavier(a, b)));
  const Real bCloses = Real(int(b.linearVelocity.dot(between) < 0) & int(!muchHeavier(b, a)));
  return (aCloses * a.linearVelocity.norm() + bCloses * b.linearVelocity.norm()) * dt;
}

// A manifold without points says nothing about gaps beyond the distance it
// was computed with; once the pair may close by more than the approach
// tolerance in a step, it is computed afresh with its reach. (Only then is
// the reach worked out: a resting pile's carried manifolds have points.)
template <class Reach>
bool manifoldIsCurrent(const Contact& contact, const Body& a, const Body& b, Reach&& reach) {
  const ManifoldFrame& frame = contact.frame;
  if (!frame.computed) return false;
  if (contact.manifold.pointCount == 0 && reach() > kApproachTolerance) return false;
  Transform now = relativePose(a, b);
  Vec2 shift = now.p - frame.relative.p;
  Real approach = shift.dot(frame.localNormal);
  Real slide = (shift - approach * frame.localNormal).norm();
  // Chord a point of B at distance `extent` sweeps under the turn since.
  Real cosine = now.q.c * frame.relative.q.c + now.q.s * frame.relative.q.s;
  Real rimShift = b.extent * std::sqrt(std::max(2 - 2 * cosine, Real(0)));
  return std::abs(approach) <= kApproachTolerance && slide + rimShift <= kSlideTolerance;
}

void recordFrame(Contact& contact, const Body& a, const Body& b) {
  const Manifold& manifold = contact.manifold;
  ManifoldFrame& frame = contact.frame;
  frame.computed = true;
  frame.relative = relativePose(a, b);
  frame.localNormal = a.transform.q.applyInverse(manifold.normal);
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ManifoldPoint& point = manifold.points[i];
    frame.localPointA[i] = a.transform.q.applyInverse(point.anchorA);
    frame.localPointB[i] = b.transform.q.applyInverse(point.anchorB);
    Vec2 gap = (b.transform.p + point.anchorB) - (a.transform.p + point.anchorA);
    frame.offset[i] = point.separation - gap.dot(manifold.normal);
  }
}

// Moves the manifold's points with the bodies: each point's material points
// on A and B, their gap along A's rotated normal, the contact point midway.
void refreshManifold(Contact& contact, const Body& a, const Body& b) {
  Manifold& manifold = contact.manifold;
  const ManifoldFrame& frame = contact.frame;
  manifold.normal = a.transform.q.apply(frame.localNormal);
  for (int i = 0; i < manifold.pointCount; ++i) {
    ManifoldPoint& point = manifold.points[i];
    Vec2 onA = a.transform.p + a.transform.q.apply(frame.localPointA[i]);
    Vec2 onB = b.transform.p + b.transform.q.apply(frame.localPointB[i]);
    point.separation = (onB - onA).dot(manifold.normal) + frame.offset[i];
    point.point = Real(0.5) * (onA + onB);
    point.anchorA = point.point - a.transform.p;
    point.anchorB = point.point - b.transform.p;
  }
}

// Two circles' manifold is one distance and a normal: cheaper to compute
// than to check whether it is still current.
bool carriesManifold(const Contact& contact) {
  static const CollideFunction circles = collideFunction(ShapeType::Circle, ShapeType::Circle);
  return contact.collide != circles;
}

// Whether the broad phase's pair of shapes may become a contact.
bool pairMayTouch(const WorldData& world, const ProxyPair& pair) {
  const ShapeSlot& a = world.shapes[pair.first];
  const ShapeSlot& b = world.shapes[pair.second];
  if (a.body == b.body) return false;
  // Sensors see overlaps after the step (sensor.cpp); they never touch.
  if (a.interaction.isSensor || b.interaction.isSensor) return false;
  // Static and kinematic bodies push; only a dynamic body can be pushed.
  if (!world.bodies[a.body].isDynamic() && !world.bodies[b.body].isDynamic()) return false;
  if (!shapesCanCollide(a.type(), b.type())) return false;
  if (!shouldCollide(a.interaction.filter, b.interaction.filter)) return false;
  return !jointBlocksContact(world, a.body, b.body);
}

// What updating one contact found, for the serial pass that follows.
enum CollideOutcome : std::uint8_t {
  kKept = 0,
  kApart = 1,          // the fat boxes no longer overlap: the contact goes
  kRecomputed = 2,     // the manifold was computed afresh
  kTouchChanged = 4,   // it began or stopped touching
  kWakes = 8,          // it touches a body that sleeps (woken in the serial pass)
  kTouching = 16,      // it touches after the update (and stays)
  kHits = 32,          // it touches and reports hits
};

// Whether touching the body wakes it (wakeIsland's own test).
bool sleeps(const Body& body) { return !body.isStatic && !body.awake && body.alive; }

std::uint8_t wakeOutcome(const Contact& contact, const Body& a, const Body& b) {
  return contact.touching && (sleeps(a) || sleeps(b)) ? kWakes : kKept;
}

// Whether the two bodies' shapes are farther apart than `distance`
// everywhere: each body's shapes lie within its extent of its origin. A
// manifold keeps only points closer than its distance, and a point is never
// closer than the shapes are, so theirs would have none, and is not
// computed: in crowds tumbling in a drum, a third to a half of the manifolds
// computed afresh came back without points, and most of those so far apart.
bool apartBeyond(const Body& a, const Body& b, Real distance) {
  const Real reach = a.extent + b.extent + distance;
  return (b.transform.p - a.transform.p).squaredNorm() > reach * reach;
}

// The pair's manifold from its collide function, keeping the impulses of
// the points that persist.
void collideAfresh(const WorldData& world, Contact& contact, const Body& a, const Body& b, Real keptWithin) {
  Manifold next = apartBeyond(a, b, keptWithin)
                      ? Manifold{}
                      : contact.collide(world.shapes[contact.shapeA].ref().geometry, a.transform,
                                        world.shapes[contact.shapeB].ref().geometry, b.transform, keptWithin);
  if (world.settings.enableWarmStarting) matchWarmStart(contact.manifold, next);
  contact.manifold = next;
}

// Two circles' manifold computed in place: collideCircles' point, keeping the
// impulses matchWarmStart would carry over (a circle pair's one point always
// has id 0), without building a manifold to copy in. In a crowd of circles
// every pair is computed every step (carriesManifold).
void updateCircles(const WorldData& world, Contact& contact, const Body& a, const Body& b, Real keptWithin) {
  Manifold& manifold = contact.manifold;
  if (apartBeyond(a, b, keptWithin)) {
    manifold = Manifold{};
    return;
  }
  const narrow::CirclePoint pair =
      narrow::circlesInA(*static_cast<const Circle*>(world.shapes[contact.shapeA].ref().geometry), a.transform,
                         *static_cast<const Circle*>(world.shapes[contact.shapeB].ref().geometry), b.transform);
  if (pair.point.separation >= keptWithin) {
    manifold = Manifold{};
    return;
  }
  const bool carries = world.settings.enableWarmStarting && manifold.pointCount > 0;
  const ManifoldPoint last = manifold.points[0];
  manifold.points[0] = ManifoldPoint{};
  manifold.points[1] = ManifoldPoint{};
  narrow::placeInWorld(pair.point, a.transform, b.transform, manifold.points[0]);
  if (carries) {
    carryImpulses(last, manifold.points[0]);
  } else {
    manifold.rollingImpulse = 0;
  }
  manifold.normal = a.transform.q.apply(pair.normal);
  manifold.pointCount = 1;
}

// Reads the bodies and shapes, writes only this contact: contacts can be
// updated side by side.
std::uint8_t updateManifold(const WorldData& world, Contact& contact, Real dt) {
  if (!world.broadPhase.fatAABBsOverlap(contact.shapeA, contact.shapeB)) {
    return kApart;
  }
  const Body& a = world.bodies[contact.edges.bodyA];
  const Body& b = world.bodies[contact.edges.bodyB];
  const bool carried = carriesManifold(contact);
  // The closing reach, worked out at most once, and only where it is read.
  std::optional<Real> knownReach;
  auto reach = [&] {
    if (!knownReach) knownReach = closingReach(a, b, dt);
    return *knownReach;
  };
  if (carried && manifoldIsCurrent(contact, a, b, reach)) {
    refreshManifold(contact, a, b);
    return wakeOutcome(contact, a, b);
  }
  const Real keptWithin = kSpeculativeDistance + reach();
  if (carried) {
    collideAfresh(world, contact, a, b, keptWithin);
  } else {
    updateCircles(world, contact, a, b, keptWithin);
  }
  const bool wasTouching = contact.touching;
  contact.touching = contact.manifold.pointCount > 0;
  if (carried) recordFrame(contact, a, b);
  return std::uint8_t(kRecomputed | (contact.touching != wasTouching ? kTouchChanged : 0) | wakeOutcome(contact, a, b));
}

// Contacts per range of the parallel update: a manifold costs about a
// microsecond, a hand-off to a thread about as much.
constexpr std::int32_t kContactsPerRange = 64;

// The lowest slot among the contact's awake bodies.
std::int32_t firstAwakeBody(const WorldData& world, const Contact& contact) {
  const std::int32_t a = contact.edges.bodyA;
  const std::int32_t b = contact.edges.bodyB;
  if (!world.bodies[a].awake) return b;
  if (!world.bodies[b].awake) return a;
  return std::min(a, b);
}

// updateManifold's outcome with what the serial pass would otherwise read
// off the contact, and its key in the touching list (sortTouchingByBody):
// read here, side by side, the serial pass touches only the contacts whose
// outcome asks for it.
std::uint8_t collideOutcome(const WorldData& world, Contact& contact, Real dt, std::int32_t& touchingKey) {
  const std::uint8_t outcome = updateManifold(world, contact, dt);
  if ((outcome & kApart) != 0 || !contact.touching) return outcome;
  touchingKey = firstAwakeBody(world, contact);
  return std::uint8_t(outcome | kTouching | (contact.reportsHits ? kHits : kKept));
}

// Contacts ahead of the one being updated whose lines are fetched
// meanwhile: the list runs through memory in slot order, but with gaps.
// Then, once a contact's own lines are in, what it names: its bodies,
// shape slots and the shapes' fat boxes three contacts ahead. Each is
// otherwise a cache miss in a crowd: on v3's smash and washer the stage
// took a quarter more time without them. Not the shapes' geometry: most
// contacts never read it (carried manifolds, pairs apart beyond their
// reach), and finding it reads the slots, which waited on their lines
// (large_pyramid's perf totals 0.97 without it, no scene slower).
constexpr std::int32_t kContactPrefetchDistance = 6;
constexpr std::int32_t kBodyPrefetchDistance = 3;

// The lines of a body the update reads: its first (pose, linear velocity,
// inverse masses, extent, whether awake) and its second (its centre of
// mass, which the closing reach reads).
void fetchNarrowPhaseLines(const Body& body) {
  const auto* first = reinterpret_cast<const char*>(&body);
  const auto* center = reinterpret_cast<const char*>(&body.mass.center);
  fetchLines(first, std::size_t(center - first) + sizeof(Vec2));
}

void fetchContactInputs(const WorldData& world, const Contact& contact) {
  fetchNarrowPhaseLines(world.bodies[contact.edges.bodyA]);
  fetchNarrowPhaseLines(world.bodies[contact.edges.bodyB]);
  fetchLines(&world.shapes[contact.shapeA]);
  fetchLines(&world.shapes[contact.shapeB]);
  fetchLines(&world.broadPhase.fatAABBOfUser(contact.shapeA));
  fetchLines(&world.broadPhase.fatAABBOfUser(contact.shapeB));
}

void updateManifolds(WorldData& world, Real dt) {
  world.collideList.clear();
  world.contactsToCollide.forEachDescending([&](std::int32_t index) { world.collideList.push_back(index); });
  world.collideOutcomes.resize(world.collideList.size());
  world.collideKeys.resize(world.collideList.size());
  world.tasks.forRanges(std::int32_t(world.collideList.size()), kContactsPerRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          for (std::int32_t i = begin; i < end; ++i) {
                            const auto k = std::size_t(i);
                            if (i + kContactPrefetchDistance < end) {
                              fetchLines(&world.contacts[world.collideList[k + kContactPrefetchDistance]], sizeof(Contact));
                            }
                            if (i + kBodyPrefetchDistance < end) {
                              fetchContactInputs(world, world.contacts[world.collideList[k + kBodyPrefetchDistance]]);
                            }
                            world.collideOutcomes[k] = collideOutcome(world, world.contacts[world.collideList[k]], dt,
                                                                      world.collideKeys[k]);
                          }
                        });
}

// Chunks of collideList per worker for the touching list's side-by-side
// compaction, and the fewest contacts a chunk takes (reading a contact's
// outcome is a few nanoseconds).
constexpr std::int32_t kCollideChunksPerWorker = 4;
constexpr std::size_t kContactsPerChunk = 256;

// How many chunks a side-by-side pass over `size` items is cut into: up to
// `perWorker` a worker, but `minItems` items each at least, so that a short
// list (a lone body's step has none) runs on the calling thread instead of
// waking a worker. Any count gives the same result: chunks join in order.
std::int32_t chunksFor(const WorldData& world, std::size_t size, std::int32_t perWorker, std::size_t minItems) {
  const auto byItems = std::int32_t(std::min(size / minItems, std::size_t(std::numeric_limits<std::int32_t>::max())));
  return std::clamp(byItems, 1, perWorker * world.tasks.workerCount());
}

// Chunk c of n covers [c * size / n, (c + 1) * size / n) of a list of `size`.
std::size_t chunkStart(std::size_t size, std::int32_t chunk, std::int32_t chunks) {
  return size * std::size_t(chunk) / std::size_t(chunks);
}

// Touching contacts from which their sort runs beside the narrow phase's
// serial pass: a contact's share of the sort is a few nanoseconds, and a
// shorter list costs less than a hand-off.
constexpr std::int32_t kTouchingSortedBeside = 4096;

bool isEventful(std::uint8_t outcome) { return (outcome & (kApart | kTouchChanged | kHits | kWakes)) != 0; }

// The touching contacts (with their keys) and the eventful entries in the
// visiting order, and the count of recomputed manifolds: each chunk counts,
// then writes its part at its offsets, side by side.
void listTouching(WorldData& world) {
  const std::size_t size = world.collideList.size();
  const std::int32_t chunks = chunksFor(world, size, kCollideChunksPerWorker, kContactsPerChunk);
  std::vector<CollideTally>& tallies = world.collideTallies;
  tallies.assign(std::size_t(chunks), {});
  world.tasks.forRanges(chunks, 1, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t chunk = begin; chunk < end; ++chunk) {
      CollideTally& tally = tallies[std::size_t(chunk)];
      for (std::size_t i = chunkStart(size, chunk, chunks); i < chunkStart(size, chunk + 1, chunks); ++i) {
        const std::uint8_t outcome = world.collideOutcomes[i];
        tally.touching += (outcome & kTouching) != 0 ? 1 : 0;
        tally.recomputed += (outcome & kRecomputed) != 0 ? 1 : 0;
        tally.eventful += isEventful(outcome) ? 1 : 0;
      }
    }
  });
  std::int32_t touching = 0;
  std::int32_t eventful = 0;
  world.profile.manifoldUpdates = 0;
  for (CollideTally& tally : tallies) {
    tally.firstTouching = touching;
    touching += tally.touching;
    tally.firstEventful = eventful;
    eventful += tally.eventful;
    world.profile.manifoldUpdates += tally.recomputed;
  }
  world.touchingContacts.resize(std::size_t(touching));
  world.touchingKeys.resize(std::size_t(touching));
  world.eventfulEntries.resize(std::size_t(eventful));
  // Every entry writes its slots and only a touching (an eventful) one
  // keeps them, so that the loop does not branch on whether a crowd's
  // contact touches, a coin toss; a chunk whose slots are all taken writes
  // into a sink of its own, never into the next chunk's.
  world.tasks.forRanges(chunks, 1, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t chunk = begin; chunk < end; ++chunk) {
      const CollideTally& tally = tallies[std::size_t(chunk)];
      auto at = std::size_t(tally.firstTouching);
      auto eventfulAt = std::size_t(tally.firstEventful);
      const std::size_t touchingEnd = at + std::size_t(tally.touching);
      const std::size_t eventfulEnd = eventfulAt + std::size_t(tally.eventful);
      std::int32_t sink = 0;
      const auto slot = [&](std::vector<std::int32_t>& list, std::size_t position, std::size_t slotsEnd) {
        return position < slotsEnd ? list.data() + position : &sink;
      };
      for (std::size_t i = chunkStart(size, chunk, chunks); i < chunkStart(size, chunk + 1, chunks); ++i) {
        const std::uint8_t outcome = world.collideOutcomes[i];
        *slot(world.touchingContacts, at, touchingEnd) = world.collideList[i];
        *slot(world.touchingKeys, at, touchingEnd) = world.collideKeys[i];
        *slot(world.eventfulEntries, eventfulAt, eventfulEnd) = std::int32_t(i);
        at += (outcome & kTouching) != 0 ? 1 : 0;
        eventfulAt += isEventful(outcome) ? 1 : 0;
      }
    }
  });
}

// The solver colours the touching contacts in list order, and in a stack
// the order shows: taken body by body from the lowest slot (scenes are
// mostly built from the ground up), a 100-row pyramid's top drifts 1 mm in
// 10 s and a heavy box on a pyramid creeps under 4 cm; taken by contact slot
// alone, 17 mm and 6 cm, always one way. So the list is sorted by body, in
// linear time (a counting sort; ties keep the walk's order). The keys come
// with the list (collideOutcome), unless a body woke since they were read.
void sortTouchingByBody(WorldData& world, bool keysStale) {
  std::vector<std::int32_t>& list = world.touchingContacts;
  std::vector<std::int32_t>& keys = world.touchingKeys;
  if (list.empty()) {
    world.touchingUnsorted.clear();
    world.touchingOrder.clear();
    return;
  }
  if (keysStale) {
    keys.clear();
    for (std::int32_t index : list) keys.push_back(firstAwakeBody(world, world.contacts[index]));
  }
  const std::int32_t lastKey = *std::max_element(keys.begin(), keys.end());
  // Keys up to the highest only: a sleeping crowd costs nothing here.
  world.touchingStarts.resize(static_cast<std::size_t>(lastKey) + 2);
  countingSort(keys, world.touchingStarts, world.touchingOrder);
  world.touchingUnsorted.swap(list);
  list.clear();
  for (std::int32_t position : world.touchingOrder) list.push_back(world.touchingUnsorted[std::size_t(position)]);
}

}  // namespace

namespace {

// Chunks of the pair search per worker: each chunk queries a slice of the
// queued proxies into its own list, so chunks run side by side and join in
// chunk order. The lists are kept when fewer chunks run (a steady step
// allocates nothing). A proxy's query takes about a microsecond.
constexpr std::int32_t kPairChunksPerWorker = 4;
constexpr std::size_t kQueriesPerChunk = 16;
// Parts per worker of a walk of the movable tree against itself
// (BroadPhase::queuedProxies) where there are several: its parts differ in
// size (a subtree against itself, two neighbouring ones), so more of them
// than chunks of queries. One thread walks it whole: each part costs a
// batch of known-pair lookups of its own.
constexpr std::size_t kWalkPartsPerWorker = 16;

std::size_t walkPartsFor(const WorldData& world) {
  const auto workers = std::size_t(world.tasks.workerCount());
  return workers == 1 ? 1 : kWalkPartsPerWorker * workers;
}

// The broad phase's new pairs that may touch: the queued proxies' queries
// side by side (the world is only read), then joined and sorted. A pair
// that never may (shapes of one body, or of two a joint keeps apart) is
// passed over like a known one, so a jointed body that keeps moving out of
// its box does not list its neighbours again every step.
void searchNewPairs(WorldData& world) {
  const BroadPhase::KnownPairs known = [&](std::span<ProxyPair> candidates, std::span<const ProxyPair> next) {
    for (const ProxyPair& pair : next) world.contactByPair.prefetch(contactPairKey(pair.first, pair.second));
    const auto unknown = std::remove_if(candidates.begin(), candidates.end(), [&](const ProxyPair& pair) {
      return world.contactByPair.contains(contactPairKey(pair.first, pair.second)) || !pairMayTouch(world, pair);
    });
    return std::size_t(unknown - candidates.begin());
  };
  const std::span<const std::int32_t> queued =
      world.broadPhase.queuedProxies(walkPartsFor(world));
  const std::int32_t queryChunks = chunksFor(world, queued.size(), kPairChunksPerWorker, kQueriesPerChunk);
  // The queries' chunks, then the parts of the walk of the movable tree
  // (BroadPhase::queuedProxies), if any.
  const std::int32_t chunks = queryChunks + std::int32_t(world.broadPhase.walkPartCount());
  if (world.pairChunks.size() < std::size_t(chunks)) world.pairChunks.resize(std::size_t(chunks));
  world.tasks.forRanges(chunks, 1, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t chunk = begin; chunk < end; ++chunk) {
      std::vector<ProxyPair>& found = world.pairChunks[std::size_t(chunk)];
      found.clear();
      if (chunk >= queryChunks) {
        world.broadPhase.walkPairs(std::size_t(chunk - queryChunks), known, found);
        continue;
      }
      const std::size_t first = chunkStart(queued.size(), chunk, queryChunks);
      const std::size_t last = chunkStart(queued.size(), chunk + 1, queryChunks);
      world.broadPhase.queryPairs(queued.subspan(first, last - first), known, found);
    }
  });
  world.newPairs.clear();
  for (std::int32_t chunk = 0; chunk < chunks; ++chunk) {
    const std::vector<ProxyPair>& found = world.pairChunks[std::size_t(chunk)];
    world.newPairs.insert(world.newPairs.end(), found.begin(), found.end());
  }
  world.broadPhase.finishPairSearch(world.newPairs);
}

// The slot each new pair's contact takes (world.newContactSlots), in the
// pairs' order: freed slots last freed first, then new ones at the end of
// the array, which grows once.
void takeContactSlots(WorldData& world) {
  std::vector<std::int32_t>& slots = world.newContactSlots;
  slots.resize(world.newPairs.size());
  std::size_t size = world.contacts.size();
  for (std::int32_t& slot : slots) {
    slot = world.freeContacts.acquire(size);
    if (std::size_t(slot) == size) ++size;
  }
  world.contacts.resize(size);
}

// New contacts per range of their fill: a fill is a few cache misses.
constexpr std::int32_t kNewContactsPerRange = 32;

// Pairs ahead of the one whose contact is being filled, or enlisted, whose
// lines are fetched meanwhile: their shapes (then their bodies) twice this
// far ahead, the contact slot once. Each is otherwise a chain of cache
// misses, one pair at a time.
constexpr std::size_t kNewContactFetchDistance = 4;

void fetchFillAhead(WorldData& world, std::size_t k) {
  const std::vector<ProxyPair>& pairs = world.newPairs;
  if (k + 2 * kNewContactFetchDistance < pairs.size()) {
    const ProxyPair& ahead = pairs[k + 2 * kNewContactFetchDistance];
    fetchLines(&world.shapes[ahead.first]);
    fetchLines(&world.shapes[ahead.second]);
  }
  if (k + kNewContactFetchDistance < pairs.size()) {
    fetchLinesForWrite(&world.contacts[std::size_t(world.newContactSlots[k + kNewContactFetchDistance])],
                       sizeof(Contact));
  }
}

void fetchEnlistAhead(const WorldData& world, std::size_t k) {
  const std::vector<ProxyPair>& pairs = world.newPairs;
  if (k + 2 * kNewContactFetchDistance < pairs.size()) {
    const ProxyPair& ahead = pairs[k + 2 * kNewContactFetchDistance];
    fetchLines(&world.bodies[world.shapes[ahead.first].body]);
    fetchLines(&world.bodies[world.shapes[ahead.second].body]);
  }
  if (k + kNewContactFetchDistance < pairs.size()) {
    fetchLines(&world.contacts[std::size_t(world.newContactSlots[k + kNewContactFetchDistance])].edges);
  }
}

}  // namespace

// New pairs become contacts: each takes its slot in the pairs' order, the
// contacts fill side by side, then join their bodies' lists and the sets
// one by one in that order (the lists' order is the pairs').
void updatePairs(WorldData& world, Real /*dt*/) {
  searchNewPairs(world);
  takeContactSlots(world);
  world.tasks.forRanges(std::int32_t(world.newPairs.size()), kNewContactsPerRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          for (auto k = std::size_t(begin); k < std::size_t(end); ++k) {
                            fetchFillAhead(world, k);
                            const ProxyPair& pair = world.newPairs[k];
                            fillContact(world, world.contacts[std::size_t(world.newContactSlots[k])], pair.first,
                                        pair.second);
                          }
                        });
  for (std::size_t k = 0; k < world.newPairs.size(); ++k) {
    fetchEnlistAhead(world, k);
    enlistContact(world, world.newContactSlots[k]);
  }
}

namespace {

// A kept contact's touch and hit reports, and the wake of a sleeping body it
// touches, with its island. A body found asleep may have been woken since,
// and waking it again does nothing; one found awake stays so.
void applyCollideEvents(WorldData& world, Contact& contact, std::uint8_t outcome, Real dt) {
  if (outcome & kTouchChanged) reportTouchChange(world, contact);
  if (outcome & kHits) reportHit(world, contact, dt);
  if (outcome & kWakes) {
    wakeIsland(world, contact.edges.bodyA);
    wakeIsland(world, contact.edges.bodyB);
  }
}

// Eventful entries ahead of the one being applied whose lines are fetched
// meanwhile: the contact twice this far ahead, then what destroying it
// touches (its pair's slot in the known pairs, its bodies, its neighbours
// in their lists). Applying is otherwise a chain of cache misses, one
// contact at a time, on one thread.
constexpr std::size_t kEventfulFetchDistance = 4;

void fetchOutcomeAhead(const WorldData& world, std::size_t k) {
  const std::vector<std::int32_t>& entries = world.eventfulEntries;
  if (k + 2 * kEventfulFetchDistance < entries.size()) {
    const std::size_t i = std::size_t(entries[k + 2 * kEventfulFetchDistance]);
    const Contact& contact = world.contacts[std::size_t(world.collideList[i])];
    fetchLines(&contact.edges);
    fetchLines(&contact.pairKey);
  }
  if (k + kEventfulFetchDistance >= entries.size()) return;
  const std::size_t i = std::size_t(entries[k + kEventfulFetchDistance]);
  if ((world.collideOutcomes[i] & kApart) == 0) return;
  const Contact& contact = world.contacts[std::size_t(world.collideList[i])];
  world.contactByPair.prefetch(contact.pairKey);
  for (int side = 0; side < 2; ++side) {
    fetchLines(&world.bodies[contact.edges.body(side)].contactHead);
    for (const std::int32_t key : {contact.edges.prev[side], contact.edges.next[side]}) {
      if (key != kNullIndex) fetchLines(&world.contacts[std::size_t(edgeElement(key))].edges);
    }
  }
}

// What changes lists and other bodies (contacts that went apart, touch and
// hit events, wakes) runs in the visiting order, over the eventful entries.
void applyCollideOutcomes(WorldData& world, Real dt) {
  const std::vector<std::int32_t>& entries = world.eventfulEntries;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    fetchOutcomeAhead(world, k);
    const auto i = std::size_t(entries[k]);
    const std::uint8_t outcome = world.collideOutcomes[i];
    const std::int32_t index = world.collideList[i];
    if ((outcome & kApart) != 0) {
      destroyContact(world, index);
    } else {
      applyCollideEvents(world, world.contacts[index], outcome, dt);
    }
  }
}

}  // namespace

void collideContacts(WorldData& world, Real dt) {
  const std::size_t awakeCount = world.awakeBodies.size();
  // A copy: contacts that a wake below activates wait for the next step's
  // manifold update (their bodies were resting as they are now).
  world.contactsToCollide.assign(world.activeContacts);
  updateManifolds(world, dt);
  listTouching(world);
  // The serial pass writes nothing the sort reads or writes (the touching
  // lists and their keys): the two go side by side, the sort betting that
  // no body wakes.
  world.tasks.bothAtOnce(
      std::int32_t(world.touchingContacts.size()), kTouchingSortedBeside, [&] { applyCollideOutcomes(world, dt); },
      [&] { sortTouchingByBody(world, false); });
  // Woken bodies' touching contacts are solved this step all the same; the
  // wakes changed keys, so the list is sorted again from where it was.
  if (world.awakeBodies.size() != awakeCount) {
    world.touchingContacts.swap(world.touchingUnsorted);
    world.activeContacts.forEachDescendingExcept(world.contactsToCollide, [&](std::int32_t index) {
      if (world.contacts[index].touching) world.touchingContacts.push_back(index);
    });
    sortTouchingByBody(world, true);
  }
}

bool hasTouchingContact(const WorldData& world, std::int32_t body) {
  for (std::int32_t key = world.bodies[body].contactHead; key != kNullIndex;) {
    const Contact& contact = world.contacts[edgeElement(key)];
    if (contact.touching) return true;
    key = contact.edges.next[edgeSide(key)];
  }
  return false;
}

void destroyContact(WorldData& world, std::int32_t index) {
  Contact& contact = world.contacts[index];
  if (contact.touching) {
    contact.touching = false;
    reportTouchChange(world, contact);
  }
  for (int side = 0; side < 2; ++side) {
    Body& body = world.bodies[world.contacts[index].edges.body(side)];
    unlinkEdge(world.contacts, body.contactHead, index, side);
  }
  world.contactByPair.erase(world.contacts[index].pairKey);
  world.activeContacts.erase(index);
  world.freeContacts.release(index);
}

void activateBodyContacts(WorldData& world, std::int32_t body) {
  forEachEdge(world.contacts, world.bodies[body].contactHead,
              [&](std::int32_t key, const Contact&) { world.activeContacts.insert(edgeElement(key)); });
}

void deactivateBodyContacts(WorldData& world, std::int32_t body) {
  forEachEdge(world.contacts, world.bodies[body].contactHead, [&](std::int32_t key, const Contact& contact) {
    if (!world.bodies[contact.edges.otherBody(key)].awake) world.activeContacts.erase(edgeElement(key));
  });
}

namespace {

// Calls visit(edge key, contact) for each of the shape's contacts; visit may
// destroy the contact it is given.
template <typename Visit>
void forEachShapeContact(WorldData& world, std::int32_t shape, Visit&& visit) {
  std::int32_t key = world.bodies[world.shapes[shape].body].contactHead;
  while (key != kNullIndex) {
    Contact& contact = world.contacts[edgeElement(key)];
    const std::int32_t next = contact.edges.next[edgeSide(key)];
    if (contact.shapeA == shape || contact.shapeB == shape) visit(key, contact);
    key = next;
  }
}

void destroyWakingOther(WorldData& world, std::int32_t key, const Contact& contact) {
  if (contact.touching) wakeIsland(world, contact.edges.otherBody(key));
  destroyContact(world, edgeElement(key));
}

}  // namespace

void destroyShapeContacts(WorldData& world, std::int32_t shape) {
  forEachShapeContact(world, shape,
                      [&](std::int32_t key, const Contact& contact) { destroyWakingOther(world, key, contact); });
}

void refilterShapeContacts(WorldData& world, std::int32_t shape) {
  forEachShapeContact(world, shape, [&](std::int32_t key, Contact& contact) {
    if (pairMayTouch(world, {contact.shapeA, contact.shapeB})) {
      setContactEventFlags(world, contact);
    } else {
      destroyWakingOther(world, key, contact);
    }
  });
}

void forgetManifoldFrames(WorldData& world, std::int32_t body) {
  forEachEdge(world.contacts, world.bodies[body].contactHead,
              [&](std::int32_t key, const Contact&) { world.contacts[edgeElement(key)].frame.computed = false; });
}

void destroyBodyContacts(WorldData& world, std::int32_t body) {
  while (world.bodies[body].contactHead != kNullIndex) {
    std::int32_t key = world.bodies[body].contactHead;
    const Contact& contact = world.contacts[edgeElement(key)];
    if (contact.touching) wakeIsland(world, contact.edges.otherBody(key));
    destroyContact(world, edgeElement(key));
  }
}

}  // namespace impulse
