// Continuous collision for fast bodies against static geometry, and for
// bodies pressed into static chains.
//
// Speculative contacts stop bodies that the broad phase pairs in time, but a
// small body moving several of its own sizes per step can skip a thin wall
// before any contact exists. For each such body we sweep its shape from its
// start-of-step pose to its end pose against static shapes along the way and
// find the first time of impact by conservative advancement: advance by the
// current gap divided by the fastest possible approach speed, which can never
// step past the surface. The body is then placed at the impact pose, keeping
// its velocity; next step's speculative contact resolves the collision.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "prefetch.h"
#include "world_data.h"

namespace impulse {

namespace {

// A body is fast when it moves more than this fraction of its inner radius
// in one step (Box2D v3 uses the same safety factor).
constexpr Real kFastFraction = Real(0.5);
constexpr int kMaxAdvanceIterations = 30;
// Stop the sweep this far from the surface (inside speculative range).
constexpr Real kTargetSeparation = kLinearSlop;
constexpr Real kSeparationTolerance = Real(0.25) * kLinearSlop;
// The core circle swept for a body that starts a step touching: this
// fraction of its inner radius (Box2D v3's).
constexpr Real kCoreFraction = Real(0.25);
// Passes over the chain segments near a centre's path (keepCentreInFrontOfChains).
constexpr int kMaxChainPasses = 4;

struct Sweep {
  Vec2 c0, c1;
  Real a0, a1;

  Transform at(Real t) const {
    return {c0 + t * (c1 - c0), Rot::fromAngle(a0 + t * (a1 - a0))};
  }
};

Sweep sweepOf(const Body& body) {
  // Rotation over the step as a signed angle (less than a half turn thanks to
  // the solver's per-sub-step rotation cap).
  Real turned = relativeRotation(body.rotation0, body.transform.q).angle();
  Real a0 = body.rotation0.angle();
  return {body.center0, body.transform.p, a0, a0 + turned};
}

// The body's sweep, worked out (an atan2 for each angle) only once a static
// shape lies along its path: most fast bodies of a crowd in a drum meet none.
class LazySweep {
 public:
  explicit LazySweep(const Body& body) : body_(body) {}
  const Sweep& get() {
    if (!sweep_) sweep_ = sweepOf(body_);
    return *sweep_;
  }

 private:
  const Body& body_;
  std::optional<Sweep> sweep_;
};


// First time in (0, 1] at which the moving shape comes within the target
// separation of the static one; 0 when it starts the step that close
// already, 1 when it never comes close.
Real timeOfImpact(ShapeRef moving, const Sweep& sweep, Real extent, ShapeRef fixed,
                  const Transform& fixedTransform) {
  Real maxApproach = (sweep.c1 - sweep.c0).norm() + std::abs(sweep.a1 - sweep.a0) * extent;
  if (maxApproach <= 0) return 1;
  Real t = 0;
  for (int i = 0; i < kMaxAdvanceIterations; ++i) {
    Real gap = computeSeparation(moving, sweep.at(t), fixed, fixedTransform);
    if (gap < kTargetSeparation + kSeparationTolerance) return t;
    t += (gap - kTargetSeparation) / maxApproach;
    if (t >= 1) return 1;
  }
  return t;
}

// A shape that starts the step touching a wall has a speculative contact with
// it, but a fast spinning body can still rotate through it. Holding the whole
// shape at its start would freeze a body sliding along the wall, so (as Box2D
// v3 does) only a small core circle around the centroid is swept: the body
// may graze, but its centre never crosses.
Real timeOfImpactWithCore(ShapeRef moving, const Sweep& sweep, Real extent, Real innerRadius,
                          ShapeRef fixed, const Transform& fixedTransform) {
  Real t = timeOfImpact(moving, sweep, extent, fixed, fixedTransform);
  if (t > 0) return t;
  const Circle core{Vec2::Zero(), kCoreFraction * innerRadius};
  Real coreT = timeOfImpact({ShapeType::Circle, &core}, sweep, 0, fixed, fixedTransform);
  return coreT > 0 ? coreT : Real(1);
}

// A chain segment's line in the world: its first point, its unit tangent,
// its length and its front (the side it collides on). None for a segment
// too short to have a direction.
struct SegmentLine {
  Vec2 p1;
  Vec2 tangent;
  Real length;
  Vec2 front;

  Real inFront(const Vec2& point) const { return front.dot(point - p1); }
};

std::optional<SegmentLine> lineOf(const Transform& chainTransform, const ChainSegment& chain) {
  const Vec2 p1 = chainTransform.apply(chain.segment.point1);
  const Vec2 edge = chainTransform.apply(chain.segment.point2) - p1;
  const Real length = edge.norm();
  if (length <= kLinearSlop) return std::nullopt;
  const Vec2 tangent = edge / length;
  return SegmentLine{p1, tangent, length, rightPerp(tangent)};
}

// Whether the body's centre path cannot take it through a chain segment,
// so no time of impact is needed (Box2D v3's early out): it started behind
// the one-sided segment, or it closed on the segment's line by less than its
// core's radius and ends more than that in front (sliding along a wall).
// Stopping such a body at its first graze would only make it pause on the
// wall; keepCentreInFrontOfChains still keeps its centre in front.
bool passesChainSegment(const Body& body, const Transform& chainTransform, const ChainSegment& chain) {
  const std::optional<SegmentLine> line = lineOf(chainTransform, chain);
  if (!line) return false;
  const Real before = line->inFront(body.center0);
  const Real after = line->inFront(body.transform.p);
  const Real core = kCoreFraction * body.innerRadius;
  return before < 0 || (before - after < core && after > core);
}

// The first time in (0, 1] at which one of the body's shapes comes within
// the target separation of a static shape.
Real firstStaticHit(const WorldData& world, const Body& body, LazySweep& sweep, std::int32_t shape) {
  const ShapeSlot& moving = world.shapes[shape];
  AABB start = computeAABB(moving.ref(), {body.center0, body.rotation0});
  AABB swept = start.unite(computeAABB(moving.ref(), body.transform));
  Real firstHit = 1;
  world.broadPhase.queryStatic(swept, [&](std::int32_t other) {
    const ShapeSlot& candidate = world.shapes[other];
    const Body& owner = world.bodies[candidate.body];
    const bool passes = candidate.type() == ShapeType::ChainSegment &&
                        passesChainSegment(body, owner.transform, geometryAs<ChainSegment>(candidate.ref()));
    if (!passes && shapesCanCollide(moving.type(), candidate.type())) {
      firstHit = std::min(firstHit, timeOfImpactWithCore(moving.ref(), sweep.get(), body.extent, body.innerRadius,
                                                         candidate.ref(), owner.transform));
    }
    return true;
  });
  return firstHit;
}

// A chain segment collides on its front only, so a body whose centre gets
// behind one is let go for good. A time of impact cannot stop a centre that
// crosses while the body already overlaps the segment (a body pressed deep
// into a wall by a crowd as it slides along it: the sweep starts touching),
// so the centre's path is checked on its own: when it crosses the segment's
// line from the front within the segment, the centre is put back in front
// along the segment's normal. The motion along the wall is kept, so a body
// sliding past does not pause. Returns whether the centre moved.
bool keepCentreInFront(const Transform& chainTransform, const ChainSegment& chain, const Vec2& start, Vec2& end) {
  const std::optional<SegmentLine> line = lineOf(chainTransform, chain);
  if (!line) return false;
  const Real before = line->inFront(start);
  const Real after = line->inFront(end);
  if (before < 0 || after >= 0) return false;
  const Vec2 crossing = start + (before / (before - after)) * (end - start);
  const Real along = line->tangent.dot(crossing - line->p1);
  if (along < 0 || along > line->length) return false;
  end += (kLinearSlop - after) * line->front;
  return true;
}

// keepCentreInFront against every static chain segment near the centre's
// path. Put back in front of one segment past its end, the centre may lie
// behind the next one (a wall turning towards the body, as inside a drum):
// the segments are looked at again until none moves it.
bool keepCentreInFrontOfChains(const WorldData& world, Body& body) {
  const Vec2 start = body.center0;
  Vec2 end = body.transform.p;
  bool moved = false;
  for (int pass = 0; pass < kMaxChainPasses; ++pass) {
    bool movedThisPass = false;
    const AABB path{start.cwiseMin(end), start.cwiseMax(end)};
    world.broadPhase.queryStatic(path, [&](std::int32_t other) {
      const ShapeSlot& candidate = world.shapes[other];
      const Body& owner = world.bodies[candidate.body];
      if (candidate.type() == ShapeType::ChainSegment) {
        movedThisPass = keepCentreInFront(owner.transform,
                                          geometryAs<ChainSegment>(candidate.ref()), start, end) ||
                        movedThisPass;
      }
      return true;
    });
    if (!movedThisPass) break;
    moved = true;
  }
  body.transform.p = end;
  return moved;
}

// Reads only the static world and writes only this body, so fast bodies
// sweep side by side. Returns whether the body's pose changed.
bool sweepAgainstStatics(WorldData& world, std::int32_t slot) {
  Body& body = world.bodies[slot];
  LazySweep sweep(body);
  Real firstHit = 1;
  world.forEachShape(slot, [&](std::int32_t s) { firstHit = std::min(firstHit, firstStaticHit(world, body, sweep, s)); });
  if (firstHit < 1) body.transform = sweep.get().at(firstHit);
  const bool heldInFront = keepCentreInFrontOfChains(world, body);
  return firstHit < 1 || heldInFront;
}

// Whether the body of `shape`, touching `chainShape`, is a slow dynamic body
// on a static chain's segment.
bool pressedOnChain(const WorldData& world, std::int32_t shape, std::int32_t chainShape) {
  const Body& body = world.bodies[world.shapes[shape].body];
  return world.shapes[chainShape].type() == ShapeType::ChainSegment && body.isDynamic() && !movedFast(body) &&
         world.bodies[world.shapes[chainShape].body].isStatic;
}

// Touching contacts per range of the search for pressed bodies: a contact's
// check is a few cache misses.
constexpr std::int32_t kContactsPerPressRange = 512;

// How far ahead of its check a touching contact's line is fetched and,
// half as far, the shape slots of one on a chain: the list is in the
// contacts' order in memory, but with gaps, and on v3's spinner (25 000
// touching contacts, one static chain) two thirds of the search's time had
// gone to loading the contacts' shape slots. A check is a few nanoseconds:
// at 16 ahead most loads still waited, at 128 the search takes 0.4 of its
// time.
constexpr std::size_t kPressContactAhead = 128;
constexpr std::size_t kPressShapeAhead = kPressContactAhead / 2;

void fetchForPressCheck(const WorldData& world, const std::vector<std::int32_t>& touching, std::size_t i,
                        std::size_t end) {
  if (i + kPressContactAhead < end) fetchLines(&world.contacts[std::size_t(touching[i + kPressContactAhead])].shapeA);
  if (i + kPressShapeAhead < end) {
    const Contact& ahead = world.contacts[std::size_t(touching[i + kPressShapeAhead])];
    if (!ahead.onChain) return;
    fetchLines(&world.shapes[ahead.shapeA]);
    fetchLines(&world.shapes[ahead.shapeB]);
  }
}

// Which of the contact's bodies lies pressed on a static chain's segment:
// bit 0 A's, bit 1 B's. Only a contact on a chain (Contact::onChain) reads
// its shapes: in a drum most touching contacts are between its bodies.
std::uint8_t pressesOf(const WorldData& world, const Contact& contact) {
  if (!contact.onChain) return 0;
  return std::uint8_t((pressedOnChain(world, contact.shapeA, contact.shapeB) ? 1 : 0) |
                      (pressedOnChain(world, contact.shapeB, contact.shapeA) ? 2 : 0));
}

// A body slow for its size can still be pushed across a chain segment it is
// pressed into: a crowd, or a pusher that does not give way, presses it
// deeper than the segment's soft contact gives back within one solve (the
// spinner's overlapping crowd at one sub-step), and its centre ends behind
// the segment's line, where the one-sided segment lets it go for good. Such
// a body touches the segment, so the dynamic bodies touching a static chain
// segment have their centre's path held in front as the fast ones do. They
// are appended to `bodies` once each, in slot order; fast ones are there
// already. The contacts are read in the order memory holds them, side by
// side: each marks which of its bodies lies pressed (world.chainPresses, bit
// 0 A's, bit 1 B's), and a walk of the marks lists those bodies.
void addSlowBodiesOnChains(WorldData& world, std::vector<std::int32_t>& bodies) {
  const std::size_t first = bodies.size();
  const std::vector<std::int32_t>& touching = world.touchingUnsorted;
  std::vector<std::uint8_t>& presses = world.chainPresses;
  presses.resize(touching.size());
  world.tasks.forRanges(std::int32_t(touching.size()), kContactsPerPressRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          for (auto i = std::size_t(begin); i < std::size_t(end); ++i) {
                            fetchForPressCheck(world, touching, i, std::size_t(end));
                            presses[i] = pressesOf(world, world.contacts[std::size_t(touching[i])]);
                          }
                        });
  for (std::size_t i = 0; i < touching.size(); ++i) {
    if (presses[i] == 0) continue;
    const Contact& contact = world.contacts[std::size_t(touching[i])];
    if ((presses[i] & 1) != 0) bodies.push_back(world.shapes[contact.shapeA].body);
    if ((presses[i] & 2) != 0) bodies.push_back(world.shapes[contact.shapeB].body);
  }
  // Each once: the bodies are moved side by side.
  std::sort(bodies.begin() + std::ptrdiff_t(first), bodies.end());
  bodies.erase(std::unique(bodies.begin() + std::ptrdiff_t(first), bodies.end()), bodies.end());
}

// Fast bodies per range of the side-by-side sweep: a sweep costs several
// microseconds.
constexpr std::int32_t kFastBodiesPerRange = 8;
// The awake bodies that moved fast this step (WorldData::awakeBodyFast), in
// awake order.
void findFastBodies(const WorldData& world, std::vector<std::int32_t>& bodies) {
  const std::vector<std::int32_t>& awake = world.awakeBodies;
  for (std::size_t i = 0; i < awake.size(); ++i) {
    if (world.awakeBodyFast[i] != 0) bodies.push_back(awake[i]);
  }
}

}  // namespace

bool movedFast(const Body& body) {
  // Kinematic bodies go where their velocity takes them, walls or not.
  if (!body.isDynamic()) return false;
  const Real threshold = kFastFraction * body.innerRadius;
  const Real moved = (body.transform.p - body.center0).norm();
  // Moving that far is fast whatever the turn adds: its atan2 is spared.
  if (moved > threshold) return true;
  const Rot turn = relativeRotation(body.rotation0, body.transform.q);
  // Nor is it needed where the turn is under a quarter and even pi/2 times
  // its sine (at least the angle there) leaves the body slow: most bodies.
  if (turn.c >= 0 && moved + std::numbers::pi_v<Real> / 2 * std::abs(turn.s) * body.extent <= threshold) return false;
  return moved + std::abs(turn.angle()) * body.extent > threshold;
}

void solveContinuous(WorldData& world, Real dt) {
  if (!world.settings.enableContinuous) return;
  // The fast bodies, to sweep, then the slow ones on chains, to hold.
  std::vector<std::int32_t>& bodies = world.fastBodies;
  bodies.clear();
  bodies.reserve(world.awakeBodies.size());  // the first fast body allocates nothing mid-game
  findFastBodies(world, bodies);
  const std::size_t fastCount = bodies.size();
  if (world.shapeGeometries.liveCount<ChainSegment>() > 0) addSlowBodiesOnChains(world, bodies);
  std::vector<std::uint8_t>& moved = world.fastBodyMoved;
  moved.reserve(world.awakeBodies.size());
  moved.resize(bodies.size());
  world.tasks.forRanges(static_cast<std::int32_t>(bodies.size()), kFastBodiesPerRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          for (std::int32_t i = begin; i < end; ++i) {
                            const std::size_t at = std::size_t(i);
                            const std::int32_t slot = bodies[at];
                            const bool held = at < fastCount
                                                  ? sweepAgainstStatics(world, slot)
                                                  : keepCentreInFrontOfChains(world, world.bodies[slot]);
                            moved[at] = held ? 1 : 0;
                          }
                        });
  // The tree is shared: the moved bodies' proxies follow one by one.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (moved[i] != 0) moveBodyProxies(world, bodies[i], dt);
  }
}

}  // namespace impulse
