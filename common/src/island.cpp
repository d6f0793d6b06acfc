// Islands and sleeping. An island is a set of dynamic bodies linked by
// constraints (static bodies do not link). When every body of an island
// has been slow for timeToSleep, the whole island sleeps: it leaves the awake
// list, so it costs nothing per step until something touches or pushes it.

#include <algorithm>

#include "world_data.h"

namespace impulse {

namespace {

// The island graph: calls goOn(other) for the bodies joined to `slot` by a
// constraint that links islands (touching contacts and joints) until it
// returns false; returns whether every one was visited. Kinematic bodies
// link nothing, as static ones: a platform would otherwise join all it
// carries into one island (they stay awake by moving with it).
template <class GoOn>
bool forEachLinkedBodyWhile(const WorldData& world, std::int32_t slot, GoOn&& goOn) {
  if (world.bodies[slot].isKinematic) return true;
  auto goOnDynamic = [&](std::int32_t other) { return world.bodies[other].isKinematic || goOn(other); };
  const bool contactsDone =
      forEachEdgeWhile(world.contacts, world.bodies[slot].contactHead, [&](std::int32_t key, const Contact& contact) {
        return !contact.touching || goOnDynamic(contact.edges.otherBody(key));
      });
  // A joint to the world has no body on its other side.
  return contactsDone &&
         forEachEdgeWhile(world.joints, world.bodies[slot].jointHead, [&](std::int32_t key, const Joint& joint) {
           return joint.edges.otherBody(key) == kNullIndex || goOnDynamic(joint.edges.otherBody(key));
         });
}

// Calls visit(other) for every body joined to `slot`, as forEachLinkedBodyWhile.
template <class Visit>
void forEachLinkedBody(const WorldData& world, std::int32_t slot, Visit&& visit) {
  forEachLinkedBodyWhile(world, slot, [&](std::int32_t other) {
    visit(other);
    return true;
  });
}

Real sleepVelocity(const Body& body) {
  // The fastest point of the body: centre speed or rim speed.
  return std::max(body.linearVelocity.norm(), body.extent * std::abs(body.angularVelocity));
}

// Bodies per range of the per-body sleep passes, which run side by side.
constexpr std::int32_t kBodiesPerSleepRange = 1024;

// Each awake body's sleep time, and whether it has been slow long enough
// for its island to be walked (world.sleepCandidates, by awake position).
void updateSleepTimes(WorldData& world, Real dt) {
  const Real tolerance = world.settings.linearSleepTolerance;
  const Real timeToSleep = world.settings.timeToSleep;
  const std::vector<std::int32_t>& awake = world.awakeBodies;
  world.sleepCandidates.resize(awake.size());
  world.tasks.forRanges(static_cast<std::int32_t>(awake.size()), kBodiesPerSleepRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          for (std::int32_t i = begin; i < end; ++i) {
                            Body& body = world.bodies[awake[std::size_t(i)]];
                            body.sleepTime = sleepVelocity(body) > tolerance ? Real(0) : body.sleepTime + dt;
                            world.sleepCandidates[std::size_t(i)] = body.sleepTime >= timeToSleep ? 1 : 0;
                          }
                        });
}

// Every awake body moved this step: appended to the moved list (after the
// bodies that just fell asleep).
void listMovedBodies(WorldData& world) {
  const std::vector<std::int32_t>& awake = world.awakeBodies;
  const std::size_t first = world.movedBodies.size();
  world.movedBodies.resize(first + awake.size());
  world.tasks.forRanges(static_cast<std::int32_t>(awake.size()), kBodiesPerSleepRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          for (std::int32_t i = begin; i < end; ++i) {
                            world.movedBodies[first + std::size_t(i)] = world.idOf(awake[std::size_t(i)]);
                          }
                        });
}

// Collects the island of `seed` (a body slow for timeToSleep; the island:
// awake dynamic bodies joined by touching constraints) into
// world.islandBodies; true when every body in it has been slow for
// timeToSleep. A walk stops at the first body it meets that has not, or
// that an earlier walk of this step stopped in (walks from `firstWalk` on):
// that island stays awake, and what was walked stays marked, so no later
// walk of the step repeats it. A pile in motion is given up on near where it
// moves. It stops as soon as it meets such a body, not once it would take
// it from the stack: walking on (through the rest of a body's contacts, and
// down its other neighbours first) had read half as many contacts again in
// v3's junkyard (4 200 a step against 2 800 late in its run), whose settled
// piles hold a few moving bodies.
bool collectSleepyIsland(WorldData& world, std::int32_t seed, std::uint64_t firstWalk) {
  const std::uint64_t walk = ++world.islandStamp;
  const Real timeToSleep = world.settings.timeToSleep;
  world.islandBodies.clear();
  world.islandStack.clear();
  world.islandStack.push_back(seed);
  world.bodies[seed].islandMark = walk;
  const auto walkOnTo = [&](std::int32_t linked) {
    Body& other = world.bodies[linked];
    if (!other.awake || other.islandMark == walk) return true;
    if (other.islandMark >= firstWalk || other.sleepTime < timeToSleep) return false;
    other.islandMark = walk;
    world.islandStack.push_back(linked);
    return true;
  };
  while (!world.islandStack.empty()) {
    const std::int32_t slot = world.islandStack.back();
    world.islandStack.pop_back();
    world.islandBodies.push_back(slot);
    if (!forEachLinkedBodyWhile(world, slot, walkOnTo)) return false;
  }
  return true;
}

void putIslandToSleep(WorldData& world) {
  for (std::int32_t slot : world.islandBodies) {
    Body& body = world.bodies[slot];
    body.awake = false;
    body.linearVelocity.setZero();
    body.angularVelocity = 0;
    world.movedBodies.push_back(world.idOf(slot));
  }
  // Once the whole island sleeps: a contact inside it has no awake body.
  for (std::int32_t slot : world.islandBodies) deactivateBodyContacts(world, slot);
}

// Slot order, so the solver's row order does not depend on traversal. The
// bodies woken since the last step were appended to the sorted rest: they
// are sorted alone and merged in (sorting the whole list had taken Box2D
// v3's smash, waking a few bodies a step among 6 000, tens of microseconds
// a step on the calling thread).
void restoreSlotOrder(WorldData& world) {
  std::vector<std::int32_t>& awake = world.awakeBodies;
  const auto woken = std::is_sorted_until(awake.begin(), awake.end());
  if (woken == awake.end()) return;
  std::sort(woken, awake.end());
  world.awakeMerge.resize(awake.size());
  std::merge(awake.begin(), woken, woken, awake.end(), world.awakeMerge.begin());
  awake.swap(world.awakeMerge);
}

}  // namespace

void updateSleep(WorldData& world, Real dt) {
  world.movedBodies.clear();
  if (!world.settings.enableSleep) {
    listMovedBodies(world);
    return;
  }
  updateSleepTimes(world, dt);
  // An island sleeps only when every body in it has been slow long enough,
  // so only such bodies need their island walked: a scene in motion walks
  // nothing.
  const std::uint64_t firstWalk = world.islandStamp + 1;
  bool anyAsleep = false;
  for (std::size_t i = 0; i < world.awakeBodies.size(); ++i) {
    const std::int32_t slot = world.awakeBodies[i];
    if (world.sleepCandidates[i] == 0 || world.bodies[slot].islandMark >= firstWalk) continue;
    if (collectSleepyIsland(world, slot, firstWalk)) {
      putIslandToSleep(world);
      anyAsleep = true;
    }
  }
  if (anyAsleep) std::erase_if(world.awakeBodies, [&](std::int32_t slot) { return !world.bodies[slot].awake; });
  restoreSlotOrder(world);
  listMovedBodies(world);
}

void wakeIsland(WorldData& world, std::int32_t seed) {
  const Body& first = world.bodies[seed];
  if (first.isStatic || first.awake || !first.alive) return;
  world.islandStack.clear();
  world.islandStack.push_back(seed);
  while (!world.islandStack.empty()) {
    std::int32_t slot = world.islandStack.back();
    world.islandStack.pop_back();
    Body& body = world.bodies[slot];
    if (body.awake) continue;
    body.awake = true;
    body.sleepTime = 0;
    world.awakeBodies.push_back(slot);
    activateBodyContacts(world, slot);
    forEachLinkedBody(world, slot, [&](std::int32_t linked) {
      const Body& neighbour = world.bodies[linked];
      if (!neighbour.isStatic && !neighbour.awake) world.islandStack.push_back(linked);
    });
  }
}

}  // namespace impulse
