#include "contact_solver_wide.h"

#include <algorithm>
#include <array>
#include <bit>
#include <type_traits>

namespace impulse {

namespace {

using simd::F4;

constexpr int kLanes = 4;
constexpr int kColorCount = 64;  // one bit each in a per-body mask

// ---- colouring and packing -------------------------------------------------

// Lowest colour used by neither body; static bodies (state 0) never block.
int pickColor(std::vector<std::uint64_t>& used, std::int32_t a, std::int32_t b) {
  std::uint64_t taken = (a != 0 ? used[a] : 0) | (b != 0 ? used[b] : 0);
  if (taken == ~std::uint64_t(0)) return -1;
  int color = std::countr_one(taken);
  if (a != 0) used[a] |= std::uint64_t(1) << color;
  if (b != 0) used[b] |= std::uint64_t(1) << color;
  return color;
}

void setLane(F4& wide, int lane, float value) {
  wide.v[lane] = value;  // GCC/Clang vector subscript
}

void packPoint(WidePoint& w, int lane, const ConstraintPoint& p) {
  setLane(w.anchorAX, lane, p.anchorA.x());
  setLane(w.anchorAY, lane, p.anchorA.y());
  setLane(w.anchorBX, lane, p.anchorB.x());
  setLane(w.anchorBY, lane, p.anchorB.y());
  setLane(w.baseSeparation, lane, p.baseSeparation);
  setLane(w.normalImpulse, lane, p.normalImpulse);
  setLane(w.tangentImpulse, lane, p.tangentImpulse);
  setLane(w.totalNormalImpulse, lane, p.totalNormalImpulse);
  setLane(w.normalMass, lane, p.normalMass);
  setLane(w.tangentMass, lane, p.tangentMass);
  setLane(w.relativeVelocity, lane, p.relativeVelocity);
  setLane(w.friction, lane, p.friction);
  setLane(w.loadOverlap, lane, p.loadOverlap);
  setLane(w.pushCap, lane, p.pushCap);
}

void packLane(WideConstraint& w, int lane, const ContactConstraint& c, std::int32_t source) {
  w.stateA[lane] = c.stateA;
  w.stateB[lane] = c.stateB;
  w.source[lane] = source;
  setLane(w.normalX, lane, c.normal.x());
  setLane(w.normalY, lane, c.normal.y());
  setLane(w.invMassA, lane, c.invMassA);
  setLane(w.invInertiaA, lane, c.invInertiaA);
  setLane(w.invMassB, lane, c.invMassB);
  setLane(w.invInertiaB, lane, c.invInertiaB);
  setLane(w.biasRate, lane, c.softness.biasRate);
  setLane(w.massScale, lane, c.softness.massScale);
  setLane(w.impulseScale, lane, c.softness.impulseScale);
  setLane(w.restitution, lane, c.restitution);
  setLane(w.rollingResistance, lane, c.rollingResistance);
  setLane(w.rollingMass, lane, c.rollingMass);
  setLane(w.rollingImpulse, lane, c.rollingImpulse);
  // A one-point manifold leaves its second point at zero mass: it never acts.
  for (int j = 0; j < c.pointCount; ++j) packPoint(w.points[j], lane, c.points[j]);
}

// An all-zero bundle: padding lanes point at the static dummy with zero mass.
WideConstraint emptyBundle() {
  WideConstraint w{};
  std::fill(std::begin(w.source), std::end(w.source), -1);
  w.massScale = simd::splat(1);
  return w;
}

// ---- body gather and scatter -----------------------------------------------

struct WideBody {
  F4 vx, vy, w;
  F4 dpx, dpy, dqc, dqs;
};

// SolverState is eight floats: (vx, vy, w, dpx) then (dpy, dqc, dqs, pad).
// Four bodies' halves are loaded as rows and transposed into lanes.
static_assert(sizeof(SolverState) == 8 * sizeof(float) && std::is_standard_layout_v<SolverState>);

const float* floatsOf(const SolverState& state) { return reinterpret_cast<const float*>(&state); }
float* floatsOf(SolverState& state) { return reinterpret_cast<float*>(&state); }

[[gnu::always_inline]] inline WideBody gather(std::span<const SolverState> states, const std::int32_t index[kLanes]) {
  const float* s0 = floatsOf(states[index[0]]);
  const float* s1 = floatsOf(states[index[1]]);
  const float* s2 = floatsOf(states[index[2]]);
  const float* s3 = floatsOf(states[index[3]]);
  __m128 a0 = _mm_loadu_ps(s0), a1 = _mm_loadu_ps(s1), a2 = _mm_loadu_ps(s2), a3 = _mm_loadu_ps(s3);
  __m128 b0 = _mm_loadu_ps(s0 + 4), b1 = _mm_loadu_ps(s1 + 4), b2 = _mm_loadu_ps(s2 + 4),
         b3 = _mm_loadu_ps(s3 + 4);
  _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
  _MM_TRANSPOSE4_PS(b0, b1, b2, b3);
  return {{a0}, {a1}, {a2}, {a3}, {b0}, {b1}, {b2}};
}

// Writes velocities back (the first four floats, delta position unchanged).
// Lanes on the static dummy write the zeros they read (their inverse mass is
// zero), so repeated writes to state 0 are harmless.
[[gnu::always_inline]] inline void scatter(std::span<SolverState> states, const std::int32_t index[kLanes], const WideBody& body) {
  __m128 r0 = body.vx.v, r1 = body.vy.v, r2 = body.w.v, r3 = body.dpx.v;
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
  _mm_storeu_ps(floatsOf(states[index[0]]), r0);
  _mm_storeu_ps(floatsOf(states[index[1]]), r1);
  _mm_storeu_ps(floatsOf(states[index[2]]), r2);
  _mm_storeu_ps(floatsOf(states[index[3]]), r3);
}

// ---- rows --------------------------------------------------------------------

struct Relative {
  F4 vx, vy;
};

// Velocity of B's anchor relative to A's anchor.
Relative relativeVelocity(const WideBody& a, const WideBody& b, const WidePoint& p) {
  return {(b.vx - b.w * p.anchorBY) - (a.vx - a.w * p.anchorAY),
          (b.vy + b.w * p.anchorBX) - (a.vy + a.w * p.anchorAX)};
}

void applyWide(WideBody& a, WideBody& b, const WideConstraint& c, const WidePoint& p, F4 px, F4 py) {
  a.vx -= c.invMassA * px;
  a.vy -= c.invMassA * py;
  a.w -= c.invInertiaA * (p.anchorAX * py - p.anchorAY * px);
  b.vx += c.invMassB * px;
  b.vy += c.invMassB * py;
  b.w += c.invInertiaB * (p.anchorBX * py - p.anchorBY * px);
}

struct Bias {
  F4 bias, massScale, impulseScale;
};

// Speculative points close their gap exactly; overlapping ones are pushed
// out softly (with bias) or not at all (relaxation).
Bias contactBias(const WideConstraint& c, const WidePoint& p, F4 separation,
                 const ContactSolverContext& context, bool useBias) {
  F4 speculative = simd::greater(separation, simd::zero());
  F4 closeGap = separation * simd::splat(context.inverseSubStep);
  if (!useBias) return {simd::select(speculative, closeGap, simd::zero()), simd::splat(1), simd::zero()};
  F4 push = simd::max(c.biasRate * separation, -p.pushCap);
  return {simd::select(speculative, closeGap, push),
          simd::select(speculative, simd::splat(1), c.massScale),
          simd::select(speculative, simd::zero(), c.impulseScale)};
}

F4 currentSeparation(const WideBody& a, const WideBody& b, const WidePoint& p, F4 dpx, F4 dpy,
                     const WideConstraint& c) {
  F4 rotatedAX = a.dqc * p.anchorAX - a.dqs * p.anchorAY;
  F4 rotatedAY = a.dqs * p.anchorAX + a.dqc * p.anchorAY;
  F4 rotatedBX = b.dqc * p.anchorBX - b.dqs * p.anchorBY;
  F4 rotatedBY = b.dqs * p.anchorBX + b.dqc * p.anchorBY;
  F4 dx = dpx + rotatedBX - rotatedAX;
  F4 dy = dpy + rotatedBY - rotatedAY;
  return p.baseSeparation + dx * c.normalX + dy * c.normalY;
}

F4 solveNormal(WideConstraint& c, WidePoint& p, WideBody& a, WideBody& b, F4 dpx, F4 dpy,
               const ContactSolverContext& context, bool useBias) {
  Bias bias = contactBias(c, p, currentSeparation(a, b, p, dpx, dpy, c), context, useBias);
  Relative dv = relativeVelocity(a, b, p);
  F4 vn = dv.vx * c.normalX + dv.vy * c.normalY;
  F4 impulse = -(p.normalMass * bias.massScale * (vn + bias.bias)) - bias.impulseScale * p.normalImpulse;
  F4 accumulated = simd::max(p.normalImpulse + impulse, simd::zero());
  impulse = accumulated - p.normalImpulse;
  p.normalImpulse = accumulated;
  p.totalNormalImpulse += impulse;
  applyWide(a, b, c, p, impulse * c.normalX, impulse * c.normalY);
  return accumulated;
}

void solveFriction(WideConstraint& c, WidePoint& p, WideBody& a, WideBody& b) {
  F4 tx = c.normalY;  // right perpendicular of the normal
  F4 ty = -c.normalX;
  Relative dv = relativeVelocity(a, b, p);
  F4 vt = dv.vx * tx + dv.vy * ty;
  F4 limit = p.friction * p.normalImpulse;
  F4 accumulated = simd::clamp(p.tangentImpulse - p.tangentMass * vt, -limit, limit);
  F4 impulse = accumulated - p.tangentImpulse;
  p.tangentImpulse = accumulated;
  applyWide(a, b, c, p, impulse * tx, impulse * ty);
}

void solveRolling(WideConstraint& c, WideBody& a, WideBody& b, F4 totalNormalImpulse) {
  F4 limit = c.rollingResistance * totalNormalImpulse;
  F4 previous = c.rollingImpulse;
  c.rollingImpulse = simd::clamp(previous - c.rollingMass * (b.w - a.w), -limit, limit);
  F4 impulse = c.rollingImpulse - previous;
  a.w -= c.invInertiaA * impulse;
  b.w += c.invInertiaB * impulse;
}

ContactSolverContext overflowContext(const ContactSolverContext& context, WideContactSet& set) {
  ContactSolverContext overflow = context;
  overflow.constraints = set.overflow;
  return overflow;
}

}  // namespace

void buildWideContacts(std::span<const ContactConstraint> constraints, std::size_t stateCount,
                       WideContactSet& set) {
  set.usedColors.assign(stateCount, 0);
  set.colorOf.resize(constraints.size());
  // Counting sort by colour (overflow last), stable within a colour so the
  // row order stays deterministic; one pass to count, one to place.
  std::array<std::int32_t, kColorCount + 2> start{};
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    int color = pickColor(set.usedColors, constraints[i].stateA, constraints[i].stateB);
    set.colorOf[i] = color < 0 ? kColorCount : color;
    ++start[set.colorOf[i] + 1];
  }
  for (int color = 0; color <= kColorCount; ++color) start[color + 1] += start[color];
  set.order.resize(constraints.size());
  std::array<std::int32_t, kColorCount + 1> next{};
  std::copy(start.begin(), start.end() - 1, next.begin());
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    set.order[next[set.colorOf[i]]++] = static_cast<std::int32_t>(i);
  }

  set.bundles.clear();
  for (int color = 0; color < kColorCount; ++color) {
    for (std::int32_t k = start[color]; k < start[color + 1]; ++k) {
      int lane = (k - start[color]) % kLanes;
      if (lane == 0) set.bundles.push_back(emptyBundle());
      packLane(set.bundles.back(), lane, constraints[set.order[k]], set.order[k]);
    }
  }
  set.overflow.clear();
  set.overflowSource.clear();
  for (std::int32_t k = start[kColorCount]; k < start[kColorCount + 1]; ++k) {
    set.overflow.push_back(constraints[set.order[k]]);
    set.overflowSource.push_back(set.order[k]);
  }
}

void warmStartWide(const ContactSolverContext& context, WideContactSet& set) {
  for (WideConstraint& c : set.bundles) {
    WideBody a = gather(context.states, c.stateA);
    WideBody b = gather(context.states, c.stateB);
    F4 tx = c.normalY;
    F4 ty = -c.normalX;
    for (WidePoint& p : c.points) {
      p.totalNormalImpulse += p.normalImpulse;
      applyWide(a, b, c, p, p.normalImpulse * c.normalX + p.tangentImpulse * tx,
                p.normalImpulse * c.normalY + p.tangentImpulse * ty);
    }
    a.w -= c.invInertiaA * c.rollingImpulse;
    b.w += c.invInertiaB * c.rollingImpulse;
    scatter(context.states, c.stateA, a);
    scatter(context.states, c.stateB, b);
  }
  warmStartContacts(overflowContext(context, set));
}

void solveWide(const ContactSolverContext& context, WideContactSet& set, bool useBias) {
  for (WideConstraint& c : set.bundles) {
    WideBody a = gather(context.states, c.stateA);
    WideBody b = gather(context.states, c.stateB);
    F4 dpx = b.dpx - a.dpx;
    F4 dpy = b.dpy - a.dpy;
    F4 totalNormalImpulse = simd::zero();
    for (WidePoint& p : c.points) {
      totalNormalImpulse += solveNormal(c, p, a, b, dpx, dpy, context, useBias);
    }
    for (WidePoint& p : c.points) solveFriction(c, p, a, b);
    solveRolling(c, a, b, totalNormalImpulse);
    scatter(context.states, c.stateA, a);
    scatter(context.states, c.stateB, b);
  }
  solveContacts(overflowContext(context, set), useBias);
}

void pushWide(const ContactSolverContext& context, WideContactSet& set) {
  const F4 maxPush = simd::splat(-context.maxPushSpeed);
  for (WideConstraint& c : set.bundles) {
    WideBody a = gather(context.states, c.stateA);
    WideBody b = gather(context.states, c.stateB);
    F4 dpx = b.dpx - a.dpx;
    F4 dpy = b.dpy - a.dpy;
    for (WidePoint& p : c.points) {
      F4 intrusion = currentSeparation(a, b, p, dpx, dpy, c) + p.loadOverlap;
      F4 bias = simd::max(c.biasRate * intrusion, maxPush);
      Relative dv = relativeVelocity(a, b, p);
      F4 vn = dv.vx * c.normalX + dv.vy * c.normalY;
      F4 impulse = simd::max(-(p.normalMass * c.massScale * (vn + bias)), simd::zero());
      impulse = simd::select(simd::less(intrusion, simd::zero()), impulse, simd::zero());
      applyWide(a, b, c, p, impulse * c.normalX, impulse * c.normalY);
    }
    scatter(context.states, c.stateA, a);
    scatter(context.states, c.stateB, b);
  }
  pushOverlap(overflowContext(context, set));
}

void restitutionWide(const ContactSolverContext& context, WideContactSet& set) {
  const F4 threshold = simd::splat(-context.restitutionThreshold);
  // Same rule as the scalar pass: only points that approached fast and
  // pushed, on contacts that bounce at all.
  auto bouncing = [&](const WideConstraint& c, const WidePoint& p) {
    return simd::both(simd::less(p.relativeVelocity, threshold),
                      simd::both(simd::notEqual(p.totalNormalImpulse, simd::zero()),
                                 simd::notEqual(c.restitution, simd::zero())));
  };
  for (WideConstraint& c : set.bundles) {
    // Resting contacts never bounce: skip their bodies entirely.
    if (!simd::any(bouncing(c, c.points[0])) && !simd::any(bouncing(c, c.points[1]))) continue;
    WideBody a = gather(context.states, c.stateA);
    WideBody b = gather(context.states, c.stateB);
    for (WidePoint& p : c.points) {
      F4 bounces = bouncing(c, p);
      Relative dv = relativeVelocity(a, b, p);
      F4 vn = dv.vx * c.normalX + dv.vy * c.normalY;
      F4 impulse = -(p.normalMass * (vn + c.restitution * p.relativeVelocity));
      F4 accumulated = simd::max(p.normalImpulse + impulse, simd::zero());
      impulse = simd::select(bounces, accumulated - p.normalImpulse, simd::zero());
      p.normalImpulse += impulse;
      p.totalNormalImpulse += impulse;
      applyWide(a, b, c, p, impulse * c.normalX, impulse * c.normalY);
    }
    scatter(context.states, c.stateA, a);
    scatter(context.states, c.stateB, b);
  }
  applyRestitution(overflowContext(context, set));
}

void unpackWideContacts(const WideContactSet& set, std::span<ContactConstraint> constraints) {
  for (const WideConstraint& w : set.bundles) {
    alignas(16) float rolling[kLanes];
    alignas(16) float normal[2][kLanes], tangent[2][kLanes], total[2][kLanes];
    simd::store(rolling, w.rollingImpulse);
    for (int j = 0; j < 2; ++j) {
      simd::store(normal[j], w.points[j].normalImpulse);
      simd::store(tangent[j], w.points[j].tangentImpulse);
      simd::store(total[j], w.points[j].totalNormalImpulse);
    }
    for (int lane = 0; lane < kLanes; ++lane) {
      if (w.source[lane] < 0) continue;
      ContactConstraint& c = constraints[w.source[lane]];
      c.rollingImpulse = rolling[lane];
      for (int j = 0; j < c.pointCount; ++j) {
        c.points[j].normalImpulse = normal[j][lane];
        c.points[j].tangentImpulse = tangent[j][lane];
        c.points[j].totalNormalImpulse = total[j][lane];
      }
    }
  }
  for (std::size_t k = 0; k < set.overflow.size(); ++k) {
    constraints[set.overflowSource[k]] = set.overflow[k];
  }
}

}  // namespace impulse
