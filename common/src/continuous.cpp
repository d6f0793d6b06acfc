// Continuous collision for fast bodies against static geometry.
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

bool isFast(const Body& body) {
  Real travel = (body.transform.p - body.center0).norm() +
                std::abs(relativeRotation(body.rotation0, body.transform.q).angle()) * body.extent;
  return travel > kFastFraction * body.innerRadius;
}

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
  const Circle core{Vec2::Zero(), Real(0.25) * innerRadius};
  Real coreT = timeOfImpact({ShapeType::Circle, &core}, sweep, 0, fixed, fixedTransform);
  return coreT > 0 ? coreT : Real(1);
}

// The first time in (0, 1] at which one of the body's shapes comes within
// the target separation of a static shape.
Real firstStaticHit(const WorldData& world, const Body& body, const Sweep& sweep, std::int32_t shape) {
  const ShapeSlot& moving = world.shapes[shape];
  AABB start = computeAABB(moving.shape, {sweep.c0, body.rotation0});
  AABB swept = start.unite(computeAABB(moving.shape, body.transform));
  Real firstHit = 1;
  world.broadPhase.query(swept, [&](std::int32_t other) {
    const ShapeSlot& candidate = world.shapes[other];
    const Body& owner = world.bodies[candidate.body];
    if (owner.isStatic && shapesCanCollide(moving.type(), candidate.type())) {
      firstHit = std::min(firstHit, timeOfImpactWithCore(moving.ref(), sweep, body.extent, body.innerRadius,
                                                         candidate.ref(), owner.transform));
    }
    return true;
  });
  return firstHit;
}

void sweepAgainstStatics(WorldData& world, std::int32_t slot) {
  Body& body = world.bodies[slot];
  const Sweep sweep = sweepOf(body);
  Real firstHit = 1;
  world.forEachShape(slot, [&](std::int32_t s) { firstHit = std::min(firstHit, firstStaticHit(world, body, sweep, s)); });
  if (firstHit >= 1) return;
  body.transform = sweep.at(firstHit);
  moveBodyProxies(world, slot);
}

}  // namespace

void solveContinuous(WorldData& world, Real /*dt*/) {
  if (!world.settings.enableContinuous) return;
  for (std::int32_t slot : world.awakeBodies) {
    // Kinematic bodies go where their velocity takes them, walls or not.
    const Body& body = world.bodies[slot];
    if (body.isDynamic() && isFast(body)) sweepAgainstStatics(world, slot);
  }
}

}  // namespace impulse
