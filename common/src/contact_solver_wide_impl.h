#pragma once
// The contact solver's passes, several constraints at a time, written once
// for any lane type F (simd::F4 on SSE2, simd::F8 on AVX2). Included by
// exactly two files, each instantiating it for its width in its own
// anonymous namespace (contact_solver_wide_sse2.cpp, _avx2.cpp), after the
// lane operations for F.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <span>
#include <type_traits>

#include "contact_solver_wide.h"
#include "counting_sort.h"
#include "prefetch.h"

namespace impulse {
namespace {

// ---- body gather and scatter -----------------------------------------------

template <class F>
struct WideBody {
  F vx, vy, w;
  F dpx, dpy, dqc, dqs;
};

// SolverState is eight floats: (vx, vy, w, dpx, dpy, dqc, dqs, pad). The
// lanes' bodies are loaded as rows and transposed into columns.
static_assert(sizeof(SolverState) == 8 * sizeof(float) && std::is_standard_layout_v<SolverState>);

const float* floatsOf(const SolverState& state) { return reinterpret_cast<const float*>(&state); }
float* floatsOf(SolverState& state) { return reinterpret_cast<float*>(&state); }

// The lanes' states, given as rows, as columns.
template <class F>
[[gnu::always_inline]] inline WideBody<F> bodyOfRows(const float* const rows[F::kLanes]) {
  F columns[8];
  simd::loadColumns(rows, columns);
  return {columns[0], columns[1], columns[2], columns[3], columns[4], columns[5], columns[6]};
}

template <class F>
[[gnu::always_inline]] inline WideBody<F> gather(std::span<const SolverState> states,
                                                 const std::int32_t index[F::kLanes]) {
  const float* rows[F::kLanes];
  for (int lane = 0; lane < F::kLanes; ++lane) rows[lane] = floatsOf(states[index[lane]]);
  return bodyOfRows<F>(rows);
}

// Writes velocities back (the first four floats, delta position unchanged)
// through `rows`, one per lane.
template <class F>
[[gnu::always_inline]] inline void storeVelocities(float* const (&rows)[F::kLanes], const WideBody<F>& body) {
  const F columns[4] = {body.vx, body.vy, body.w, body.dpx};
  simd::storeColumns(columns, rows);
}

// Every lane but those on the static dummy, which write into a sink: their
// inverse mass is zero, so they would write the zeros they read, but
// bundles of one colour run on several threads and must not write one
// state together.
template <class F>
[[gnu::always_inline]] inline void scatter(std::span<SolverState> states, const std::int32_t index[F::kLanes],
                                           const WideBody<F>& body) {
  float* rows[F::kLanes];
  alignas(32) float sink[8];
  for (int lane = 0; lane < F::kLanes; ++lane) rows[lane] = index[lane] != 0 ? floatsOf(states[index[lane]]) : sink;
  storeVelocities<F>(rows, body);
}

// One side of a contact bundle that reads a body it does not move: only the
// lanes of `moves` (BundleTraits::movesA or movesB), the others into a sink.
template <class F>
[[gnu::always_inline]] inline void scatterMoving(std::span<SolverState> states, const std::int32_t index[F::kLanes],
                                                 std::uint8_t moves, const WideBody<F>& body) {
  float* rows[F::kLanes];
  alignas(32) float sink[8];
  for (int lane = 0; lane < F::kLanes; ++lane) {
    rows[lane] = (moves >> lane & 1u) != 0 ? floatsOf(states[index[lane]]) : sink;
  }
  storeVelocities<F>(rows, body);
}

// Writes a contact bundle's bodies back: as scatter, or, in a bundle that
// reads a body contacts do not move (BundleTraits::readsOnly), only the
// lanes whose body it moves. (Testing every bundle's lanes for it made the
// warm start of v3's many_pyramids, with no such body, a tenth slower.)
template <class F>
[[gnu::always_inline]] inline void scatterBundle(std::span<SolverState> states, const WideConstraint<F>& c,
                                                 const BundleTraits& traits, const WideBody<F>& a,
                                                 const WideBody<F>& b) {
  if (!traits.readsOnly) {
    scatter<F>(states, c.stateA, a);
    scatter<F>(states, c.stateB, b);
    return;
  }
  scatterMoving<F>(states, c.stateA, traits.movesA, a);
  scatterMoving<F>(states, c.stateB, traits.movesB, b);
}

template <class F>
struct Relative {
  F vx, vy;
};

// Velocity of B's anchor relative to A's anchor (P: a contact's or a
// support row's point, C: its constraint or row).
template <class F, class P>
Relative<F> relativeVelocity(const WideBody<F>& a, const WideBody<F>& b, const P& p) {
  return {(b.vx - b.w * p.anchorBY) - (a.vx - a.w * p.anchorAY),
          (b.vy + b.w * p.anchorBX) - (a.vy + a.w * p.anchorAX)};
}

// The part of that velocity along the contact normal (positive: separating).
template <class F, class C, class P>
F normalVelocity(const WideBody<F>& a, const WideBody<F>& b, const C& c, const P& p) {
  Relative<F> dv = relativeVelocity(a, b, p);
  return dv.vx * c.normalX + dv.vy * c.normalY;
}

/// The inverse masses and inertias of a lane's two bodies.
template <class F>
struct WidePair {
  F invMassA, invInertiaA, invMassB, invInertiaB;
};

/// An impulse (px, py) on B at the arm (armBX, armBY) from its centre, and
/// its opposite on A at (armAX, armAY): a contact point's or a pin's.
template <class F>
void applyPointImpulse(WideBody<F>& a, WideBody<F>& b, const WidePair<F>& m, F armAX, F armAY, F armBX, F armBY, F px,
                       F py) {
  a.vx -= m.invMassA * px;
  a.vy -= m.invMassA * py;
  a.w -= m.invInertiaA * (armAX * py - armAY * px);
  b.vx += m.invMassB * px;
  b.vy += m.invMassB * py;
  b.w += m.invInertiaB * (armBX * py - armBY * px);
}

template <class F>
void applyWide(WideBody<F>& a, WideBody<F>& b, const WideConstraint<F>& c, const WidePoint<F>& p, F px, F py) {
  applyPointImpulse(a, b, {c.invMassA, c.invInertiaA, c.invMassB, c.invInertiaB}, p.anchorAX, p.anchorAY, p.anchorBX,
                    p.anchorBY, px, py);
}

template <class F>
struct Bias {
  F bias, massScale, impulseScale;
};

// Speculative points close their gap exactly; overlapping ones are pushed
// out softly (with bias) or not at all (relaxation).
template <class F>
Bias<F> contactBias(const WideConstraint<F>& c, const WidePoint<F>& p, F separation,
                 const ContactSolverContext& context, bool useBias) {
  F speculative = simd::greater(separation, simd::broadcast<F>(0));
  F closeGap = separation * simd::broadcast<F>(context.inverseSubStep);
  if (!useBias) return {simd::select(speculative, closeGap, simd::broadcast<F>(0)), simd::broadcast<F>(1), simd::broadcast<F>(0)};
  F push = simd::max(c.biasRate * separation, -p.pushCap) - p.holdSpeed;
  return {simd::select(speculative, closeGap, push),
          simd::select(speculative, simd::broadcast<F>(1), c.massScale),
          simd::select(speculative, simd::broadcast<F>(0), c.impulseScale)};
}

template <class F, class C, class P>
F currentSeparation(const WideBody<F>& a, const WideBody<F>& b, const P& p, F dpx, F dpy,
                    const C& c) {
  F rotatedAX = a.dqc * p.anchorAX - a.dqs * p.anchorAY;
  F rotatedAY = a.dqs * p.anchorAX + a.dqc * p.anchorAY;
  F rotatedBX = b.dqc * p.anchorBX - b.dqs * p.anchorBY;
  F rotatedBY = b.dqs * p.anchorBX + b.dqc * p.anchorBY;
  F dx = dpx + rotatedBX - rotatedAX;
  F dy = dpy + rotatedBY - rotatedAY;
  return p.baseSeparation + dx * c.normalX + dy * c.normalY;
}

template <class F>
[[gnu::always_inline]] inline F solveNormal(WideConstraint<F>& c, WidePoint<F>& p, WideBody<F>& a, WideBody<F>& b,
                                            F dpx, F dpy, const ContactSolverContext& context, bool useBias) {
  Bias<F> bias = contactBias(c, p, currentSeparation(a, b, p, dpx, dpy, c), context, useBias);
  F vn = normalVelocity(a, b, c, p);
  F impulse = -(p.normalMass * bias.massScale * (vn + bias.bias)) - bias.impulseScale * p.normalImpulse;
  F accumulated = simd::max(p.normalImpulse + impulse, simd::broadcast<F>(0));
  impulse = accumulated - p.normalImpulse;
  p.normalImpulse = accumulated;
  p.totalNormalImpulse += impulse;
  applyWide(a, b, c, p, impulse * c.normalX, impulse * c.normalY);
  return accumulated;
}

template <class F>
[[gnu::always_inline]] inline void solveFriction(WideConstraint<F>& c, WidePoint<F>& p, WideBody<F>& a,
                                                WideBody<F>& b) {
  F tx = c.normalY;  // right perpendicular of the normal
  F ty = -c.normalX;
  Relative<F> dv = relativeVelocity(a, b, p);
  F vt = dv.vx * tx + dv.vy * ty;
  F limit = p.friction * (p.normalImpulse + p.supportImpulse);
  F accumulated = simd::clamp(p.tangentImpulse - p.tangentMass * vt, -limit, limit);
  F impulse = accumulated - p.tangentImpulse;
  p.tangentImpulse = accumulated;
  applyWide(a, b, c, p, impulse * tx, impulse * ty);
}

// Whether any lane of the bundle resists rolling: most scenes have none, and
// a lane without it holds no rolling impulse to warm start or solve.
template <class F>
bool anyRolling(const WideConstraint<F>& c) {
  return simd::any(simd::notEqual(c.rollingResistance, simd::broadcast<F>(0)));
}

template <class F>
void solveRolling(WideConstraint<F>& c, WideBody<F>& a, WideBody<F>& b, F totalNormalImpulse) {
  if (!anyRolling(c)) return;
  F limit = c.rollingResistance * totalNormalImpulse;
  F previous = c.rollingImpulse;
  c.rollingImpulse = simd::clamp(previous - c.rollingMass * (b.w - a.w), -limit, limit);
  F impulse = c.rollingImpulse - previous;
  a.w -= c.invInertiaA * impulse;
  b.w += c.invInertiaB * impulse;
}

ContactSolverContext overflowContext(const ContactSolverContext& context, WideContactSet& set) {
  ContactSolverContext overflow = context;
  overflow.constraints = set.overflow;
  return overflow;
}

// Bundles per range when filling them side by side.
constexpr std::int32_t kBundlesPerFillRange = 16;

// Bundles ahead of the one being filled or stored whose contacts are
// fetched into the cache meanwhile: a colour's contacts lie scattered in
// memory, and asking for the next bundles' lines early overlaps their
// misses with the work on this one. Since the fill also asks for each
// bundle's own 25 lines, fewer bundles in flight wait less for room to miss
// in (v3's many_pyramids: the fill's samples fell by about a quarter at 4
// against 6; at 2 or 3 the store's rose).
constexpr std::int32_t kPrefetchBundles = 4;

// visit(b) for each bundle b of [begin, end), fetch(b) having been asked
// kPrefetchBundles bundles before.
template <class Fetch, class Visit>
void visitFetchingAhead(std::int32_t begin, std::int32_t end, Fetch&& fetch, Visit&& visit) {
  for (std::int32_t b = begin; b < std::min(begin + kPrefetchBundles, end); ++b) fetch(b);
  for (std::int32_t b = begin; b < end; ++b) {
    if (b + kPrefetchBundles < end) fetch(b + kPrefetchBundles);
    visit(b);
  }
}

// Bundles per range of a colour run side by side: a bundle's pass costs
// tens of nanoseconds, a hand-off to a thread about a microsecond.
constexpr std::int32_t kBundlesPerRange = 64;
// The same for the sub-steps' passes over a colour (warm start, solve,
// relax, push, restitution), a bundle's 50 to 150 ns: shorter ranges, since
// a colour under two ranges runs on one thread while the other waits, and
// a crowd around one body (a tumbler's box, a drum) leaves many colours of
// 20 to 120 bundles (with 64 a range, all of the tumbler's ran on one).
constexpr std::int32_t kBundlesPerColorRange = 16;

// ---- passes ------------------------------------------------------------------

// What preparing a bundle needs besides the constraint's own fields.
template <class F>
struct BundleInputs {
  F present[2];  ///< all-ones where the manifold has the point
  F separation[2];  ///< the manifold's
  F staticFriction, dynamicFriction;
  F bothMove;  ///< all-ones where neither body is the static dummy
  /// All-ones where the contact may hold as a wedge's: off level
  /// (ConstraintRef::facing 0), between two moving bodies without joints.
  F mayHold;
  /// All-ones where a body hangs (ConstraintRef::hangs): kHangingHold's ramp.
  F hangs;
};

// ---- gathering a bundle's lanes -----------------------------------------------

// A bundle's lanes are read as rows of eight floats from each lane's ref
// and contact and turned into columns (simd::loadColumns): a field's
// column is the float at its offset in the record. Lane by lane, the
// fill's stores and the vector loads of finishBundle behind them had cost
// a forwarding stall per field.
constexpr std::size_t floatAt(std::size_t byteOffset) { return byteOffset / sizeof(float); }

// Floats read of each lane's contact: its ContactSolverPart, which fills
// the first two lines of its aligned Contact (so reading both whole stays
// within it).
constexpr std::size_t kContactFloats = 32;
static_assert(sizeof(ContactSolverPart) <= kContactFloats * sizeof(float) &&
              sizeof(Contact) >= kContactFloats * sizeof(float));
// Floats read of each lane's ref: its contact, states and inverse masses.
constexpr std::size_t kRefFloats = 8;
static_assert(offsetof(ConstraintRef, invInertiaB) < kRefFloats * sizeof(float) &&
              sizeof(ConstraintRef) >= kRefFloats * sizeof(float));
static_assert(std::is_standard_layout_v<ContactSolverPart> && std::is_standard_layout_v<ConstraintRef>);

// The column of manifold point j's field at `pointOffset`.
constexpr std::size_t pointColumn(int j, std::size_t pointOffset) {
  return floatAt(offsetof(ContactSolverPart, manifold) + offsetof(Manifold, points) +
                 std::size_t(j) * sizeof(ManifoldPoint) + pointOffset);
}

// Columns of `count` floats (a multiple of 8) from each lane's record.
template <class F>
void loadRecordColumns(const void* const records[F::kLanes], std::size_t count, F* columns) {
  for (std::size_t row = 0; row < count; row += 8) {
    const float* rows[F::kLanes];
    for (int lane = 0; lane < F::kLanes; ++lane) rows[lane] = static_cast<const float*>(records[lane]) + row;
    simd::loadColumns(rows, columns + row);
  }
}

// The inverse: `count` floats (a multiple of 4) of each lane's record from
// its columns.
template <class F>
void storeRecordColumns(const F* columns, std::size_t count, void* const records[F::kLanes]) {
  for (std::size_t row = 0; row < count; row += 4) {
    float* rows[F::kLanes];
    for (int lane = 0; lane < F::kLanes; ++lane) rows[lane] = static_cast<float*>(records[lane]) + row;
    simd::storeColumns(columns + row, rows);
  }
}

}  // namespace
}  // namespace impulse

// The support pass's kernels, on the body gather and scatter and the record
// columns above; the contacts fill its lanes' records as they are prepared.
#include "support_pass_wide_impl.h"

namespace impulse {
namespace {

// What a padding lane reads: no contact (source -1), the static dummy's
// state, zero masses, and a manifold of no points.
const ConstraintRef kPaddingRef{};
alignas(64) constexpr float kPaddingContact[kContactFloats] = {};

// The lane flags read off the refs' bytes: whether a lane's contact holds
// its body up (its support impulse counts) and whether it may hold as a
// wedge's.
struct RefFlags {
  std::uint8_t holdsUp = 0;
  std::uint8_t mayHold = 0;
  std::uint8_t hangs = 0;
};

RefFlags refFlags(std::span<const ConstraintRef* const> refs) {
  RefFlags flags;
  for (std::size_t lane = 0; lane < refs.size(); ++lane) {
    if (refs[lane]->holdsUp) flags.holdsUp = std::uint8_t(flags.holdsUp | (1u << lane));
    if (mayHoldAsWedge(*refs[lane])) flags.mayHold = std::uint8_t(flags.mayHold | (1u << lane));
    if (refs[lane]->hangs) flags.hangs = std::uint8_t(flags.hangs | (1u << lane));
  }
  return flags;
}

// The lanes' bodies off their refs' columns: states, source contacts,
// inverse masses, and the softness of a contact on the static world or
// between two moving bodies (a padding lane takes the static world's: with
// no mass and no points it moves nothing whatever its softness).
template <class F>
void gatherBodies(const F (&ref)[kRefFloats], const ContactSoftness& softness, WideConstraint<F>& w,
                  WideContactCold<F>& cold, BundleInputs<F>& in) {
  const auto field = [&](std::size_t offset) { return ref[floatAt(offset)]; };
  simd::storeInts(w.stateA, field(offsetof(ConstraintRef, stateA)));
  simd::storeInts(w.stateB, field(offsetof(ConstraintRef, stateB)));
  simd::storeInts(cold.source, field(offsetof(ConstraintRef, contact)));
  w.invMassA = field(offsetof(ConstraintRef, invMassA));
  w.invInertiaA = field(offsetof(ConstraintRef, invInertiaA));
  w.invMassB = field(offsetof(ConstraintRef, invMassB));
  w.invInertiaB = field(offsetof(ConstraintRef, invInertiaB));
  in.bothMove = simd::both(simd::intGreater(field(offsetof(ConstraintRef, stateA)), 0),
                           simd::intGreater(field(offsetof(ConstraintRef, stateB)), 0));
  const auto soft = [&](Real Softness::*term) {
    return simd::select(in.bothMove, simd::broadcast<F>(softness.dynamic.*term),
                        simd::broadcast<F>(softness.statics.*term));
  };
  w.biasRate = soft(&Softness::biasRate);
  w.massScale = soft(&Softness::massScale);
  w.impulseScale = soft(&Softness::impulseScale);
}

// The lanes' manifolds and coefficients off their contacts' columns; a point
// a manifold does not have is all zero, so it never acts.
template <class F>
void gatherManifolds(const F (&part)[kContactFloats], RefFlags flags, F startImpulse, WideConstraint<F>& w,
                     WideContactCold<F>& cold, BundleInputs<F>& in) {
  const std::size_t manifold = offsetof(ContactSolverPart, manifold);
  w.normalX = part[floatAt(manifold + offsetof(Manifold, normal))];
  w.normalY = part[floatAt(manifold + offsetof(Manifold, normal)) + 1];
  w.rollingImpulse = part[floatAt(manifold + offsetof(Manifold, rollingImpulse))];
  cold.restitution = part[floatAt(offsetof(ContactSolverPart, restitution))];
  w.rollingResistance = part[floatAt(offsetof(ContactSolverPart, rollingResistance))];
  in.staticFriction = part[floatAt(offsetof(ContactSolverPart, staticFriction))];
  in.dynamicFriction = part[floatAt(offsetof(ContactSolverPart, dynamicFriction))];
  in.mayHold = simd::maskOfBits<F>(flags.mayHold);
  in.hangs = simd::maskOfBits<F>(flags.hangs);
  const F holdsUp = simd::maskOfBits<F>(flags.holdsUp);
  const F pointCount = part[floatAt(manifold + offsetof(Manifold, pointCount))];
  const F zero = simd::broadcast<F>(0);
  for (int j = 0; j < 2; ++j) {
    const F present = simd::intGreater(pointCount, j);
    const auto field = [&](std::size_t offset) { return simd::select(present, part[pointColumn(j, offset)], zero); };
    WidePoint<F>& p = w.points[j];
    p.anchorAX = field(offsetof(ManifoldPoint, anchorA));
    p.anchorAY = field(offsetof(ManifoldPoint, anchorA) + sizeof(float));
    p.anchorBX = field(offsetof(ManifoldPoint, anchorB));
    p.anchorBY = field(offsetof(ManifoldPoint, anchorB) + sizeof(float));
    // A new contact's touching points start from its estimated load.
    const F touches = simd::both(present, simd::atLeast(simd::broadcast<F>(kStartTouch),
                                                        field(offsetof(ManifoldPoint, separation))));
    p.normalImpulse = field(offsetof(ManifoldPoint, normalImpulse)) + simd::select(touches, startImpulse, zero);
    p.tangentImpulse = field(offsetof(ManifoldPoint, tangentImpulse));
    p.supportImpulse = simd::select(holdsUp, field(offsetof(ManifoldPoint, supportImpulse)), zero);
    p.totalNormalImpulse = zero;
    in.separation[j] = field(offsetof(ManifoldPoint, separation));
    in.present[j] = present;
  }
}

// Copies the lanes' contacts into the bundle (every field but those
// finishBundle derives) and fills `in`. `refs` holds a short bundle's lanes
// in use; the others read the padding records.
template <class F>
void gatherLanes(std::span<const ConstraintRef* const> refs, const WorldData& world, const ContactSoftness& softness,
                 F startImpulse, WideConstraint<F>& w, WideContactCold<F>& cold, BundleInputs<F>& in) {
  const void* refRows[F::kLanes];
  const void* contactRows[F::kLanes];
  for (int lane = 0; lane < F::kLanes; ++lane) {
    const bool used = std::size_t(lane) < refs.size();
    refRows[lane] = used ? refs[std::size_t(lane)] : &kPaddingRef;
    contactRows[lane] = used ? static_cast<const void*>(&world.contacts[refs[std::size_t(lane)]->contact])
                             : kPaddingContact;
  }
  F ref[kRefFloats];
  F part[kContactFloats];
  loadRecordColumns<F>(refRows, kRefFloats, ref);
  loadRecordColumns<F>(contactRows, kContactFloats, part);
  gatherBodies(ref, softness, w, cold, in);
  gatherManifolds(part, refFlags(refs), startImpulse, w, cold, in);
}

// A ref's start impulse (SupportPass::startImpulses: empty in a step that
// starts no contact).
Real startImpulseOf(std::span<const Real> starts, std::int32_t entry) {
  return starts.empty() ? Real(0) : starts[std::size_t(entry)];
}

// The lanes' start impulses, read only in a step that starts some contact.
template <class F>
F startImpulsesOf(std::span<const Real> starts, std::span<const std::int32_t> entries) {
  if (starts.empty()) return simd::broadcast<F>(0);
  alignas(32) float lanes[F::kLanes] = {};
  for (std::size_t lane = 0; lane < entries.size(); ++lane) lanes[lane] = startImpulseOf(starts, entries[lane]);
  return simd::load<F>(lanes);
}

// 1 / k where k > 0, else 0 (the quotient of the other lanes is dropped).
template <class F>
F inverseOrZero(F k) {
  const F zero = simd::broadcast<F>(0);
  return simd::select(simd::greater(k, zero), simd::broadcast<F>(1) / k, zero);
}

// The response of the pair along direction (dx, dy) at a point, inverted.
template <class F>
F effectiveMass(const WideConstraint<F>& c, const WidePoint<F>& p, F dx, F dy) {
  const F ra = p.anchorAX * dy - p.anchorAY * dx;
  const F rb = p.anchorBX * dy - p.anchorBY * dx;
  return inverseOrZero(c.invMassA + c.invMassB + c.invInertiaA * ra * ra + c.invInertiaB * rb * rb);
}

// holdSpeedFor, lane by lane, on the lanes of `mayHold` (kHold).
template <class F>
F holdSpeedOf(const WideConstraint<F>& c, F loadOverlap, F load, F mayHold, F hangs, Real weightPerMass) {
  const F zero = simd::broadcast<F>(0);
  if (weightPerMass == 0 || !simd::any(mayHold)) return zero;
  const auto ramp = [&](Real HoldRamp::*term) {
    return simd::select(hangs, simd::broadcast<F>(kHangingHold.*term), simd::broadcast<F>(kHold.*term));
  };
  const F from = ramp(&HoldRamp::fromWeights);
  const F weights = load * simd::max(c.invMassA, c.invMassB) / simd::broadcast<F>(weightPerMass);
  const F rise = (weights - from) / (ramp(&HoldRamp::fullWeights) - from);
  const F share = ramp(&HoldRamp::share) * simd::clamp(rise, zero, simd::broadcast<F>(1));
  const F fastest = simd::broadcast<F>(kHoldSpeedSubSteps * weightPerMass);
  return simd::select(mayHold, simd::min(share * c.biasRate * loadOverlap, fastest), zero);
}

// Everything a bundle derives from its gathered numbers and the bodies'
// velocities (the scalar prepareContact's rules, lane by lane); returns the
// lanes with a point deeper than its load explains (hasIntrusion).
template <class F>
F finishBundle(std::span<const SolverState> states, const WorldSettings& settings, const ContactSoftness& softness,
               const BundleInputs<F>& in, WideConstraint<F>& c, WideContactCold<F>& cold) {
  const F zero = simd::broadcast<F>(0);
  const WideBody<F> a = gather<F>(states, c.stateA);
  const WideBody<F> b = gather<F>(states, c.stateB);
  const F tx = c.normalY;
  const F ty = -c.normalX;
  c.rollingMass = inverseOrZero(c.invInertiaA + c.invInertiaB);
  const F stickSpeed = simd::broadcast<F>(settings.stickSpeed);
  const F minPush = simd::broadcast<F>(kMinPushSpeed);
  const F maxPush = simd::broadcast<F>(std::max(settings.maxContactPushSpeed, kMinPushSpeed));
  F intrusion = zero;
  for (int j = 0; j < 2; ++j) {
    WidePoint<F>& p = c.points[j];
    const F present = in.present[j];
    p.baseSeparation = simd::select(present, in.separation[j] - ((p.anchorBX - p.anchorAX) * c.normalX +
                                                                 (p.anchorBY - p.anchorAY) * c.normalY), zero);
    p.normalMass = simd::select(present, effectiveMass(c, p, c.normalX, c.normalY), zero);
    p.tangentMass = simd::select(present, effectiveMass(c, p, tx, ty), zero);
    const Relative<F> dv = relativeVelocity(a, b, p);
    cold.relativeVelocity[j] = simd::select(present, dv.vx * c.normalX + dv.vy * c.normalY, zero);
    // The load includes what the support pass carried, or a held-up body's
    // resting overlap would read as an intrusion to push out.
    const F stiffness = p.normalMass * c.massScale * c.biasRate;
    const F load = p.normalImpulse + p.supportImpulse;
    const F loadOverlap = simd::select(simd::greater(stiffness, zero), c.impulseScale * load / stiffness, zero);
    cold.loadOverlap[j] = loadOverlap;
    // pushCapForLoad, lane by lane.
    const F deep = simd::less(in.separation[j] + loadOverlap, simd::broadcast<F>(-kIntrusionSlop));
    const F loadCap = simd::min(c.biasRate * loadOverlap, maxPush);
    const F marginCap =
        simd::clamp(simd::broadcast<F>(kLoadPushMargin) * c.biasRate * loadOverlap, minPush, maxPush);
    p.pushCap = simd::select(present, simd::select(simd::both(deep, in.bothMove), loadCap, marginCap), zero);
    // Coulomb with two coefficients: a contact that is not slipping is held
    // by static friction; once it slips, dynamic friction opposes it.
    const F sticks = simd::less(simd::abs(dv.vx * tx + dv.vy * ty), stickSpeed);
    p.friction = simd::select(present, simd::select(sticks, in.staticFriction, in.dynamicFriction), zero);
    intrusion = simd::either(intrusion, simd::both(present, deep));
    p.holdSpeed = holdSpeedOf(c, loadOverlap, load, simd::select(deep, zero, simd::both(present, in.mayHold)),
                              in.hangs, softness.weightPerMass);
  }
  return intrusion;
}

// ---- the push pass's contacts ------------------------------------------------

// Whether the push pass runs on a contact between these states: one of them
// is marked (WideContactSet::pushZone), at most two contacts from a body
// whose contact intrudes.
bool nearIntrusion(const WideContactSet& set, std::int32_t stateA, std::int32_t stateB) {
  return (set.pushZone[std::size_t(stateA)] | set.pushZone[std::size_t(stateB)]) != 0;
}

void markIntruding(WideContactSet& set, std::int32_t stateA, std::int32_t stateB) {
  for (const std::int32_t state : {stateA, stateB}) {
    if (state != 0) set.pushZone[std::size_t(state)] = kIntrudingBody;
  }
}

// The contacts of the bodies at most two contacts from an intrusion, lane
// by lane: a body pushed out of an overlap into a neighbour is pushed back
// out of that one in the same sub-step, and that neighbour out of the next;
// farther on the push has spent itself, and a crowd's other contacts are
// left to their soft rows as a crowd without intrusions is (islands, bodies
// joined by touching contacts, pushed whole had pushed 95 % of the contacts
// of a pile of 8 000 circles in three quarters of its steps; these, a
// quarter). Any width pushes the same contacts.
template <class F>
void selectPushedContacts(const TaskRunner& tasks, WideContactSet& set, bool anyIntrusion) {
  set.pushBundles.clear();
  set.pushOverflow.clear();
  set.pushedContacts = 0;
  if (!anyIntrusion) return;
  // Each bundle's pushed lanes side by side, then listed in bundle order.
  // A padding lane's states are both the static dummy's, never marked.
  const std::vector<WideConstraint<F>>& bundles = bundlesOf<F>(set);
  set.bundlePushLanes.resize(bundles.size());
  tasks.forRanges(static_cast<std::int32_t>(bundles.size()), kBundlesPerRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t b = begin; b < end; ++b) {
      const WideConstraint<F>& c = bundles[std::size_t(b)];
      std::uint8_t lanes = 0;
      for (int l = 0; l < F::kLanes; ++l) {
        if (nearIntrusion(set, c.stateA[l], c.stateB[l])) lanes = std::uint8_t(lanes | (1u << l));
      }
      set.bundlePushLanes[std::size_t(b)] = lanes;
    }
  });
  listWhere(bundles.size(), [&](std::size_t b) { return set.bundlePushLanes[b] != 0; }, set.pushBundles);
  for (const std::uint8_t lanes : set.bundlePushLanes) set.pushedContacts += std::popcount(lanes);
  for (std::size_t k = 0; k < set.overflow.size(); ++k) {
    const ContactConstraint& c = set.overflow[k];
    if (!nearIntrusion(set, c.stateA, c.stateB)) continue;
    set.pushOverflow.push_back(static_cast<std::int32_t>(k));
    ++set.pushedContacts;
  }
}

// Marks the bodies the push pass reaches (WideContactSet::pushZone);
// returns whether a contact intrudes. A resting stack, which has none,
// skips the marking.
template <class F>
bool markIntrusions(const WorldData& world, std::span<const ConstraintRef> refs, WideContactSet& set) {
  const auto intrudes = [](std::uint8_t lanes) { return lanes != 0; };
  if (std::none_of(set.bundleIntrusion.begin(), set.bundleIntrusion.end(), intrudes) &&
      std::none_of(set.overflowIntrudes.begin(), set.overflowIntrudes.end(), intrudes)) {
    return false;
  }
  set.pushZone.assign(world.solverStates.size(), 0);
  const std::vector<WideConstraint<F>>& bundles = bundlesOf<F>(set);
  for (std::size_t b = 0; b < bundles.size(); ++b) {
    const std::uint8_t intruding = set.bundleIntrusion[b];
    if (intruding == 0) continue;
    for (int l = 0; l < F::kLanes; ++l) {
      if ((intruding >> l & 1u) != 0) markIntruding(set, bundles[b].stateA[l], bundles[b].stateB[l]);
    }
  }
  for (std::size_t k = 0; k < set.overflow.size(); ++k) {
    if (set.overflowIntrudes[k] != 0) markIntruding(set, set.overflow[k].stateA, set.overflow[k].stateB);
  }
  markNearIntrusions(world, refs, set);
  return true;
}

// Starts loading the solver parts of bundle b's contacts (ContactSolverPart)
// and the support records its lanes write, the bundle itself ready to be
// written, and the refs of the bundle as far again ahead, whose contact
// indices that fetch will read: the refs lie scattered too, in colour order.
// A bundle's fill writes about 1.5 KB (eight lanes); without its lines
// asked for ahead, its stores waited for them and the fill stalled on a full
// store queue (about half of its perf samples on one store).
template <class F>
void prefetchBundleContacts(const WorldData& world, std::span<const ConstraintRef> refs, WideContactSet& set,
                            std::int32_t b) {
  const BundleSlices& slices = set.contactSlices;
  const std::int32_t first = slices.first[std::size_t(b)];
  for (std::int32_t k = first; k < first + slices.lanes[std::size_t(b)]; ++k) {
    const std::int32_t entry = set.order[std::size_t(k)];
    const ContactSolverPart& part = world.contacts[refs[std::size_t(entry)].contact];
    fetchLines(&part, sizeof(ContactSolverPart));
    const SupportPlace place = set.supportPlaceOf[std::size_t(entry)];
    if (place.bundle >= 0) fetchLines(&supportLaneOf<F>(set, place), sizeof(SupportLaneRecord));
  }
  fetchLinesForWrite(&bundlesOf<F>(set)[std::size_t(b)], sizeof(WideConstraint<F>));
  fetchLinesForWrite(&coldPartsOf<F>(set)[std::size_t(b)], sizeof(WideContactCold<F>));
  const std::int32_t further = b + kPrefetchBundles;
  if (further >= slices.count()) return;
  const std::int32_t furtherFirst = slices.first[std::size_t(further)];
  for (std::int32_t k = furtherFirst; k < furtherFirst + slices.lanes[std::size_t(further)]; ++k) {
    const auto* ref = reinterpret_cast<const char*>(&refs[std::size_t(set.order[std::size_t(k)])]);
    fetchLines(ref);
    fetchLines(ref + sizeof(ConstraintRef) - 1);  // a ref may straddle two lines
  }
}

// Whether a point of the bundle approached fast enough to bounce when
// prepared, on a contact that bounces at all: the restitution pass's first
// two conditions, which the solve does not change (its third, that the
// point pushed, it does).
template <class F>
F bouncingAtPrepare(const WideContactCold<F>& cold, int j, F threshold) {
  return simd::both(simd::less(cold.relativeVelocity[j], threshold),
                    simd::notEqual(cold.restitution, simd::broadcast<F>(0)));
}

template <class F>
bool mayBounce(const WideContactCold<F>& cold, Real restitutionThreshold) {
  const F threshold = simd::broadcast<F>(-restitutionThreshold);
  return simd::any(bouncingAtPrepare(cold, 0, threshold)) || simd::any(bouncingAtPrepare(cold, 1, threshold));
}

// The lanes whose body (of inverse mass and inertia as given) contacts move
// (movesBody), as bits.
template <class F>
std::uint8_t movingLanes(F invMass, F invInertia) {
  const F zero = simd::broadcast<F>(0);
  return std::uint8_t(simd::bitsOf(simd::either(simd::notEqual(invMass, zero), simd::notEqual(invInertia, zero))));
}

// The lanes on a body's state rather than the static dummy's, as bits.
template <class F>
std::uint8_t lanesWithState(const std::int32_t (&state)[F::kLanes]) {
  std::uint8_t lanes = 0;
  for (int lane = 0; lane < F::kLanes; ++lane) {
    if (state[lane] != 0) lanes = std::uint8_t(lanes | (1u << lane));
  }
  return lanes;
}

// Prepares bundle b from its lanes' contacts; returns its lanes with a
// point deeper than its load explains. Reads only its own lanes' contacts
// and writes only its own bundle, so bundles fill side by side.
template <class F>
std::uint8_t fillBundle(const WorldData& world, std::span<const ConstraintRef> refs, const ContactSoftness& softness,
                        std::span<const Real> starts, WideContactSet& set, std::int32_t b) {
  WideConstraint<F>& c = bundlesOf<F>(set)[std::size_t(b)];
  WideContactCold<F>& cold = coldPartsOf<F>(set)[std::size_t(b)];
  const std::int32_t first = set.contactSlices.first[std::size_t(b)];
  const std::span<const std::int32_t> entries(set.order.data() + first, set.contactSlices.lanes[std::size_t(b)]);
  const ConstraintRef* laneRefs[F::kLanes];
  for (std::size_t lane = 0; lane < entries.size(); ++lane) laneRefs[lane] = &refs[std::size_t(entries[lane])];
  BundleInputs<F> inputs;
  gatherLanes<F>(std::span(laneRefs, entries.size()), world, softness, startImpulsesOf<F>(starts, entries), c, cold,
                 inputs);
  BundleTraits& traits = set.bundleTraits[std::size_t(b)];
  traits.quiet = std::all_of(laneRefs, laneRefs + entries.size(), [](const ConstraintRef* ref) { return ref->quiet; });
  traits.twoPointLanes = simd::bitsOf(inputs.present[1]);
  traits.movesA = movingLanes<F>(c.invMassA, c.invInertiaA);
  traits.movesB = movingLanes<F>(c.invMassB, c.invInertiaB);
  traits.readsOnly = traits.movesA != lanesWithState<F>(c.stateA) || traits.movesB != lanesWithState<F>(c.stateB);
  const std::uint8_t intruding =
      simd::bitsOf(finishBundle(world.solverStates, world.settings, softness, inputs, c, cold));
  packSupportLanes(set, c, b, entries);
  traits.mayBounce = mayBounce(cold, world.settings.restitutionThreshold);
  return intruding;
}

template <class F>
bool buildWideContacts(const WorldData& world, std::span<const ConstraintRef> refs,
                       const ContactSoftness& softness, const SupportPass& support, WideContactSet& set) {
  const ColorStarts& start = set.colorStart;
  placeSupportRows<F>(support, refs.size(), world.tasks, set);
  set.contactSlices.cut(std::span(start).first(GraphColoring::kOverflow + 1), F::kLanes, set.colorBundleStart);
  const std::int32_t bundleCount = set.contactSlices.count();

  auto& bundles = bundlesOf<F>(set);
  bundles.resize(std::size_t(bundleCount));
  coldPartsOf<F>(set).resize(std::size_t(bundleCount));
  set.bundleTraits.resize(std::size_t(bundleCount));
  set.laneSupportRecord.resize(std::size_t(bundleCount) * F::kLanes);
  set.bundleIntrusion.resize(std::size_t(bundleCount));
  const std::span<const Real> starts = support.startImpulses();
  world.tasks.forRanges(bundleCount, kBundlesPerFillRange, [&](std::int32_t begin, std::int32_t end) {
    visitFetchingAhead(
        begin, end, [&](std::int32_t b) { prefetchBundleContacts<F>(world, refs, set, b); },
        [&](std::int32_t b) {
          set.bundleIntrusion[std::size_t(b)] = fillBundle<F>(world, refs, softness, starts, set, b);
        });
  });

  listWhere(std::size_t(bundleCount), [&](std::size_t b) { return set.bundleTraits[b].mayBounce; }, set.bounceBundles);
  set.overflow.clear();
  set.overflowIntrudes.clear();
  set.overflowSupportRecord.clear();
  for (std::int32_t k = start[GraphColoring::kOverflow]; k < start[GraphColoring::kOverflow + 1]; ++k) {
    const ConstraintRef& ref = refs[std::size_t(set.order[k])];
    ContactConstraint& constraint = set.overflow.emplace_back();
    prepareContact(world, ref, softness, startImpulseOf(starts, set.order[k]), constraint);
    const SupportPlace place = set.supportPlaceOf[std::size_t(set.order[k])];
    set.overflowSupportRecord.push_back(supportRecordOf<F>(place));
    if (place.bundle >= 0) packSupportLane(supportLaneOf<F>(set, place), constraint, place.upperIsB);
    set.overflowIntrudes.push_back(hasIntrusion(constraint, world.contacts[ref.contact].manifold) ? 1 : 0);
  }
  const bool anyIntrusion = markIntrusions<F>(world, refs, set);
  finishSupportBundles<F>(world.tasks, set);
  selectPushedContacts<F>(world.tasks, set, anyIntrusion);
  return anyIntrusion;
}

// visitRun(begin, end) for runs of bundles [begin, end), colour by colour;
// one colour's runs side by side, since none of their lanes shares a body
// that they move.
template <class VisitRun>
void forEachBundleRunByColor(const ContactSolverContext& context, const WideContactSet& set, VisitRun&& visitRun) {
  const int colours = coloursTaken(set.colorBundleStart);
  for (int color = 0; color < colours; ++color) {
    const std::int32_t first = set.colorBundleStart[std::size_t(color)];
    const std::int32_t count = set.colorBundleStart[std::size_t(color) + 1] - first;
    context.tasks->forRanges(count, kBundlesPerColorRange, [&](std::int32_t begin, std::int32_t end) {
      visitRun(first + begin, first + end);
    });
  }
}

// visit(bundle, traits) for each bundle, as forEachBundleRunByColor.
template <class F, class Visit>
void forEachBundleByColor(const ContactSolverContext& context, WideContactSet& set, Visit&& visit) {
  std::vector<WideConstraint<F>>& bundles = bundlesOf<F>(set);
  forEachBundleRunByColor(context, set, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t b = begin; b < end; ++b) visit(bundles[std::size_t(b)], set.bundleTraits[std::size_t(b)]);
  });
}

// visit(k) for each entry k of a list of bundles in bundle order (the push
// pass's, the restitution pass's), colour by colour, one colour's side by
// side; backwards through the colours when `backwards`. In bundle order,
// each colour's entries are one run of the list.
template <class Visit>
void forEachListedBundleByColor(const ContactSolverContext& context, const WideContactSet& set,
                                const std::vector<std::int32_t>& list, bool backwards, Visit&& visit) {
  std::array<std::size_t, GraphColoring::kOverflow + 1> colorStart{};
  const std::size_t colours = std::size_t(coloursTaken(set.colorBundleStart));
  for (std::size_t color = 0; color < colours; ++color) {
    const auto from = list.begin() + std::ptrdiff_t(colorStart[color]);
    const auto to = std::lower_bound(from, list.end(), set.colorBundleStart[color + 1]);
    colorStart[color + 1] = std::size_t(to - list.begin());
  }
  for (std::size_t k = 0; k < colours; ++k) {
    const std::size_t color = backwards ? colours - 1 - k : k;
    const std::size_t first = colorStart[color];
    context.tasks->forRanges(std::int32_t(colorStart[color + 1] - first), kBundlesPerColorRange,
                             [&](std::int32_t begin, std::int32_t end) {
                               for (std::int32_t entry = begin; entry < end; ++entry) visit(first + std::size_t(entry));
                             });
  }
}

// Whether a bundle holds no impulse at all: its warm start and friction
// would apply nothing.
template <class F>
bool holdsNoImpulse(const WideConstraint<F>& c) {
  const F zero = simd::broadcast<F>(0);
  F held = simd::notEqual(c.rollingImpulse, zero);
  for (const WidePoint<F>& p : c.points) {
    held = simd::either(held, simd::notEqual(p.normalImpulse, zero));
    held = simd::either(held, simd::notEqual(p.tangentImpulse, zero));
    held = simd::either(held, simd::notEqual(p.supportImpulse, zero));
  }
  return !simd::any(held);
}

// Whether solving a quiet bundle (WideConstraint::quiet) would change
// nothing: it holds no impulse, and each point is apart and closing no
// faster than its gap closes in the sub-step, so the solve's own rule
// (solveNormal's, for a speculative point) gives it no impulse, and with
// none its friction and rolling have no room either. Then its bodies are
// not written back. (Exactly so but for the sign of a velocity that is
// zero: the skipped solve would add a zero impulse to it.)
template <class F>
bool staysQuiet(const WideConstraint<F>& c, const WideBody<F>& a, const WideBody<F>& b, F dpx, F dpy,
                const ContactSolverContext& context) {
  if (!holdsNoImpulse(c)) return false;
  const F zero = simd::broadcast<F>(0);
  F acts = zero;
  for (const WidePoint<F>& p : c.points) {
    const F separation = currentSeparation(a, b, p, dpx, dpy, c);
    const F closeGap = separation * simd::broadcast<F>(context.inverseSubStep);
    const F closesFaster = simd::less(normalVelocity(a, b, c, p) + closeGap, zero);
    const F present = simd::greater(p.normalMass, zero);
    const F touches = simd::atLeast(zero, separation);
    acts = simd::either(acts, simd::both(present, simd::either(touches, closesFaster)));
  }
  return !simd::any(acts);
}

// The warm start of a bundle's first `points` points.
template <int points, class F>
[[gnu::always_inline]] inline void warmStartPoints(WideConstraint<F>& c, WideBody<F>& a, WideBody<F>& b) {
  const F tx = c.normalY;
  const F ty = -c.normalX;
  for (int j = 0; j < points; ++j) {
    WidePoint<F>& p = c.points[j];
    p.totalNormalImpulse += p.normalImpulse;
    applyWide(a, b, c, p, p.normalImpulse * c.normalX + p.tangentImpulse * tx,
              p.normalImpulse * c.normalY + p.tangentImpulse * ty);
  }
}

template <class F>
void warmStartWide(const ContactSolverContext& context, WideContactSet& set) {
  forEachBundleByColor<F>(context, set, [&](WideConstraint<F>& c, const BundleTraits& traits) {
    if (traits.quiet && holdsNoImpulse(c)) return;
    WideBody<F> a = gather<F>(context.states, c.stateA);
    WideBody<F> b = gather<F>(context.states, c.stateB);
    if (traits.points() == 2) {
      warmStartPoints<2>(c, a, b);
    } else {
      warmStartPoints<1>(c, a, b);
    }
    if (anyRolling(c)) {
      a.w -= c.invInertiaA * c.rollingImpulse;
      b.w += c.invInertiaB * c.rollingImpulse;
    }
    scatterBundle<F>(context.states, c, traits, a, b);
  });
  warmStartContacts(overflowContext(context, set));
}

// The solve of `count` bundles of one colour (one or two): each bundle's
// normal rows of its first `points` points (a fixed count, as
// warmStartPoints), then their friction rows, then its rolling row.
// Compiled apart for each point count: inlined side by side in one loop,
// the two counts' copies crowded each other's registers (a lone 60-row
// pyramid's solve, all two-point, took a tenth longer). A bundle's rows
// are one long chain of dependent arithmetic; two bundles' chains, row by
// row in step, keep the core's units busier. Each bundle's arithmetic is
// its own, as alone: the same bits. A quiet bundle comes alone (its check
// may leave its bodies as they are).
template <int points, std::size_t count, class F>
[[gnu::noinline]] void solveBundles(const std::array<WideConstraint<F>*, count>& bundles,
                                    const std::array<const BundleTraits*, count>& traits,
                                    const ContactSolverContext& context, bool useBias) {
  std::array<WideBody<F>, count> a, b;
  std::array<F, count> dpx, dpy;
  std::array<F, count> normalImpulse;
  for (std::size_t n = 0; n < count; ++n) {
    a[n] = gather<F>(context.states, bundles[n]->stateA);
    b[n] = gather<F>(context.states, bundles[n]->stateB);
    dpx[n] = b[n].dpx - a[n].dpx;
    dpy[n] = b[n].dpy - a[n].dpy;
    normalImpulse[n] = simd::broadcast<F>(0);
  }
  if (count == 1 && traits[0]->quiet && staysQuiet(*bundles[0], a[0], b[0], dpx[0], dpy[0], context)) return;
  for (int k = 0; k < points; ++k) {
    const int j = context.reversePointOrder ? points - 1 - k : k;
    for (std::size_t n = 0; n < count; ++n) {
      WideConstraint<F>& c = *bundles[n];
      normalImpulse[n] += solveNormal(c, c.points[j], a[n], b[n], dpx[n], dpy[n], context, useBias);
    }
  }
  for (int j = 0; j < points; ++j) {
    for (std::size_t n = 0; n < count; ++n) solveFriction(*bundles[n], bundles[n]->points[j], a[n], b[n]);
  }
  for (std::size_t n = 0; n < count; ++n) solveRolling(*bundles[n], a[n], b[n], normalImpulse[n]);
  for (std::size_t n = 0; n < count; ++n) scatterBundle<F>(context.states, *bundles[n], *traits[n], a[n], b[n]);
}

// Bundle b alone, or with the one after it (`paired`), of `points` points.
template <int points, class F>
void solveBundleOrPair(std::vector<WideConstraint<F>>& bundles, const std::vector<BundleTraits>& traits,
                       std::size_t b, bool paired, const ContactSolverContext& context, bool useBias) {
  if (paired) {
    solveBundles<points>(std::array{&bundles[b], &bundles[b + 1]}, std::array{&traits[b], &traits[b + 1]}, context,
                         useBias);
  } else {
    solveBundles<points>(std::array{&bundles[b]}, std::array{&traits[b]}, context, useBias);
  }
}

// Two bundles at a time where they are alike (solveBundles).
template <class F>
void solveWide(const ContactSolverContext& context, WideContactSet& set, bool useBias) {
  std::vector<WideConstraint<F>>& bundles = bundlesOf<F>(set);
  const std::vector<BundleTraits>& traits = set.bundleTraits;
  forEachBundleRunByColor(context, set, [&](std::int32_t begin, std::int32_t end) {
    for (auto b = std::size_t(begin); b < std::size_t(end);) {
      const int points = traits[b].points();
      const bool paired = b + 1 < std::size_t(end) && !traits[b].quiet && !traits[b + 1].quiet &&
                          traits[b + 1].points() == points;
      if (points == 2) {
        solveBundleOrPair<2>(bundles, traits, b, paired, context, useBias);
      } else {
        solveBundleOrPair<1>(bundles, traits, b, paired, context, useBias);
      }
      b += paired ? 2 : 1;
    }
  });
  solveContacts(overflowContext(context, set), useBias);
}

// Only the contacts of islands where one intruded when prepared
// (selectPushedContacts): the others' bodies are left where they are.
template <class F>
void pushWide(const ContactSolverContext& context, WideContactSet& set) {
  const F maxPush = simd::broadcast<F>(-context.maxPushSpeed);
  std::vector<WideConstraint<F>>& bundles = bundlesOf<F>(set);
  const std::vector<WideContactCold<F>>& cold = coldPartsOf<F>(set);
  // The colours run backwards on the sub-steps that reverse the point
  // order. The push starts from rest every sub-step and sweeps once, so the
  // contacts solved last have the last word: in one fixed order a body is
  // pushed into the contacts solved before, the same way every sub-step,
  // and in a packed crowd pairs of circles were squeezed almost through
  // each other.
  forEachListedBundleByColor(context, set, set.pushBundles, context.reversePointOrder, [&](std::size_t k) {
    const auto bundle = std::size_t(set.pushBundles[k]);
    WideConstraint<F>& c = bundles[bundle];
    const F* loadOverlap = cold[bundle].loadOverlap;
    const BundleTraits& traits = set.bundleTraits[bundle];
    const int points = traits.points();
    const F pushes = simd::maskOfBits<F>(set.bundlePushLanes[bundle]);
    WideBody<F> a = gather<F>(context.states, c.stateA);
    WideBody<F> b = gather<F>(context.states, c.stateB);
    F dpx = b.dpx - a.dpx;
    F dpy = b.dpy - a.dpy;
    F intrusions[2];
    F pushed[2] = {simd::broadcast<F>(0), simd::broadcast<F>(0)};  // the lanes whose point j is pushed
    for (int j = 0; j < points; ++j) {
      intrusions[j] = currentSeparation(a, b, c.points[j], dpx, dpy, c) + loadOverlap[j];
      pushed[j] = simd::both(pushes, simd::less(intrusions[j], simd::broadcast<F>(0)));
    }
    // No pushed lane intrudes (in a tumbling crowd, most quiet bundles):
    // every impulse below would be zero, and its bodies are not written back.
    if (!simd::any(simd::either(pushed[0], pushed[1]))) return;
    for (int j = 0; j < points; ++j) {
      WidePoint<F>& p = c.points[j];
      F bias = simd::max(c.biasRate * intrusions[j], maxPush);
      F vn = normalVelocity(a, b, c, p);
      F impulse = simd::max(-(p.normalMass * c.massScale * (vn + bias)), simd::broadcast<F>(0));
      impulse = simd::select(pushed[j], impulse, simd::broadcast<F>(0));
      applyWide(a, b, c, p, impulse * c.normalX, impulse * c.normalY);
    }
    scatterBundle<F>(context.states, c, traits, a, b);
  });
  for (std::int32_t index : set.pushOverflow) pushOverlap(context, set.overflow[std::size_t(index)]);
}

template <class F>
void restitutionWide(const ContactSolverContext& context, WideContactSet& set) {
  const F threshold = simd::broadcast<F>(-context.restitutionThreshold);
  // Same rule as the scalar pass: only points that approached fast and
  // pushed, on contacts that bounce at all.
  auto bouncing = [&](const WideContactCold<F>& cold, const WideConstraint<F>& c, int j) {
    return simd::both(bouncingAtPrepare(cold, j, threshold),
                      simd::notEqual(c.points[j].totalNormalImpulse, simd::broadcast<F>(0)));
  };
  // Only the bundles that may bounce (mayBounce, when prepared).
  std::vector<WideConstraint<F>>& bundles = bundlesOf<F>(set);
  const std::vector<WideContactCold<F>>& coldParts = coldPartsOf<F>(set);
  forEachListedBundleByColor(context, set, set.bounceBundles, false, [&](std::size_t k) {
    const auto bundle = std::size_t(set.bounceBundles[k]);
    WideConstraint<F>& c = bundles[bundle];
    const WideContactCold<F>& cold = coldParts[bundle];
    const BundleTraits& traits = set.bundleTraits[bundle];
    // Resting contacts never bounce: skip their bodies entirely.
    if (!simd::any(bouncing(cold, c, 0)) && !simd::any(bouncing(cold, c, 1))) return;
    WideBody<F> a = gather<F>(context.states, c.stateA);
    WideBody<F> b = gather<F>(context.states, c.stateB);
    for (int j = 0; j < 2; ++j) {
      WidePoint<F>& p = c.points[j];
      F bounces = bouncing(cold, c, j);
      F vn = normalVelocity(a, b, c, p);
      F impulse = -(p.normalMass * (vn + cold.restitution * cold.relativeVelocity[j]));
      F accumulated = simd::max(p.normalImpulse + impulse, simd::broadcast<F>(0));
      impulse = simd::select(bounces, accumulated - p.normalImpulse, simd::broadcast<F>(0));
      p.normalImpulse += impulse;
      p.totalNormalImpulse += impulse;
      applyWide(a, b, c, p, impulse * c.normalX, impulse * c.normalY);
    }
    scatterBundle<F>(context.states, c, traits, a, b);
  });
  applyRestitution(overflowContext(context, set));
}

// Whether a quiet bundle stayed so through the step: it holds no impulse
// and none of its lanes holds a body up. Its manifolds held none either
// (ConstraintRef::quiet), and its store would write them as they are: in a
// crowd of debris flying apart most of the contacts are such speculative
// ones, apart and closing too slowly to act.
template <class F>
bool keepsQuietManifolds(const WideConstraint<F>& w, const BundleTraits& traits, const std::int32_t* records) {
  if (!traits.quiet || !holdsNoImpulse(w)) return false;
  return std::all_of(records, records + F::kLanes, [](std::int32_t record) { return record < 0; });
}

// Writes one bundle's impulses into its lanes' manifolds: the support
// pass's where a lane's contact holds a body up (its `records`). Only
// writes: each lane's point count comes with the bundle (reading the
// manifold's made each store wait for its line).
template <class F>
void storeBundleImpulses(const WideContactSet& set, const WideConstraint<F>& w, const WideContactCold<F>& cold,
                         const BundleTraits& traits, const std::int32_t* records, WorldData& world) {
  if (keepsQuietManifolds(w, traits, records)) return;
  alignas(16) float rolling[F::kLanes];
  alignas(16) float normal[2][F::kLanes], tangent[2][F::kLanes], support[2][F::kLanes];
  simd::store(rolling, w.rollingImpulse);
  for (int j = 0; j < 2; ++j) {
    simd::store(normal[j], w.points[j].normalImpulse);
    simd::store(tangent[j], w.points[j].tangentImpulse);
    simd::store(support[j], w.points[j].supportImpulse);
  }
  for (int lane = 0; lane < F::kLanes; ++lane) {
    if (cold.source[lane] < 0) continue;
    Manifold& manifold = world.contacts[cold.source[lane]].manifold;
    manifold.rollingImpulse = rolling[lane];
    const std::int32_t record = records[lane];
    const int points = 1 + (traits.twoPointLanes >> lane & 1);
    for (int j = 0; j < points; ++j) {
      manifold.points[j].normalImpulse = normal[j][lane];
      manifold.points[j].tangentImpulse = tangent[j][lane];
      manifold.points[j].supportImpulse = record < 0 ? support[j][lane] : supportImpulseOf<F>(set, record, j);
    }
  }
}

// The overflow constraints' impulses, then the support pass's of those that
// hold a body up.
template <class F>
void storeOverflowImpulses(const WideContactSet& set, WorldData& world) {
  storeImpulses(set.overflow, world);
  for (std::size_t k = 0; k < set.overflow.size(); ++k) {
    const std::int32_t record = set.overflowSupportRecord[k];
    if (record < 0) continue;
    Manifold& manifold = world.contacts[set.overflow[k].contact].manifold;
    for (int j = 0; j < manifold.pointCount; ++j) manifold.points[j].supportImpulse = supportImpulseOf<F>(set, record, j);
  }
}

// Starts loading the manifolds a bundle stores into (`cold`: its cold
// part), ready to be written.
template <class F>
void prefetchStoreTargets(const WideContactCold<F>& cold, WorldData& world) {
  for (int lane = 0; lane < F::kLanes; ++lane) {
    if (cold.source[lane] < 0) continue;
    fetchLinesForWrite(&world.contacts[cold.source[lane]].manifold, sizeof(Manifold));
  }
}

// Each bundle writes only its own lanes' manifolds: side by side, fetching
// the manifolds of the bundles ahead meanwhile (as fillBundle).
template <class F>
void storeWideImpulses(WideContactSet& set, WorldData& world) {
  collectSupportImpulses<F>(set, world.tasks);
  const std::vector<WideConstraint<F>>& bundles = bundlesOf<F>(set);
  const std::vector<WideContactCold<F>>& cold = coldPartsOf<F>(set);
  world.tasks.forRanges(static_cast<std::int32_t>(bundles.size()), kBundlesPerFillRange,
                        [&](std::int32_t begin, std::int32_t end) {
                          visitFetchingAhead(
                              begin, end,
                              [&](std::int32_t b) {
                                // The store's own test, a few bundles ahead (its lines are
                                // then still in for it): the lines of a bundle it skips are
                                // not fetched. Fetching for every bundle but quiet ones
                                // instead took smash's store 0.91-1.00 -> 1.05-1.25 %.
                                const std::size_t k = std::size_t(b);
                                if (keepsQuietManifolds(bundles[k], set.bundleTraits[k],
                                                        &set.laneSupportRecord[k * F::kLanes])) {
                                  return;
                                }
                                prefetchStoreTargets(cold[k], world);
                              },
                              [&](std::int32_t b) {
                                storeBundleImpulses(set, bundles[std::size_t(b)], cold[std::size_t(b)],
                                                    set.bundleTraits[std::size_t(b)],
                                                    &set.laneSupportRecord[std::size_t(b) * F::kLanes], world);
                              });
                        });
  storeOverflowImpulses<F>(set, world);
}

// integrateRotation (math.h) and the delta position's step, a bundle of
// consecutive states at a time with the same operations in the same order:
// the square root and division per body, one body at a time, took about a
// tenth of the solve of v3's many_pyramids.
template <class F>
std::size_t integratePositionsWide(std::span<SolverState> states, float h) {
  const std::size_t whole = states.size() - states.size() % F::kLanes;
  const F step = simd::broadcast<F>(h);
  const F zero = simd::broadcast<F>(0);
  const F one = simd::broadcast<F>(1);
  for (std::size_t first = 0; first < whole; first += F::kLanes) {
    float* rows[F::kLanes];
    for (int lane = 0; lane < F::kLanes; ++lane) rows[lane] = floatsOf(states[first + std::size_t(lane)]);
    const WideBody<F> body = bodyOfRows<F>(rows);
    const F turn = step * body.w;
    const F c = body.dqc - turn * body.dqs;
    const F s = body.dqs + turn * body.dqc;
    const F length = simd::sqrt(c * c + s * s);
    const F inverse = simd::select(simd::greater(length, zero), one / length, zero);
    const F moved[4] = {body.dpx + step * body.vx, body.dpy + step * body.vy, c * inverse, s * inverse};
    // The four floats from the delta position on: (dpx, dpy, dqc, dqs).
    for (float*& row : rows) row += 3;
    simd::storeColumns(moved, rows);
  }
  return whole;
}

}  // namespace
}  // namespace impulse

#include "joint_pins_wide_impl.h"

namespace impulse {
namespace {

/// This width's passes as a table (contact_solver_wide.h).
template <class F>
WideContactKernels makeWideContactKernels() {
  return {F::kLanes,      &buildWideContacts<F>, &warmStartWide<F>,    &solveWide<F>,
          &pushWide<F>,    &solveSupportWide<F>,  &restitutionWide<F>, &storeWideImpulses<F>,
          &warmStartPins<F>, &solvePins<F>,      &warmStartTreePins<F>,  &solveTreePins<F>,
          &warmStartRevolutes<F>, &solveRevolutes<F>, &integratePositionsWide<F>};
}

}  // namespace
}  // namespace impulse
