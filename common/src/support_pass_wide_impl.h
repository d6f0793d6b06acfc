#pragma once
// The support pass (support_pass.h) several rows at a time, written once for
// any lane type F. Included by contact_solver_wide_impl.h after the body
// gather and scatter it uses, so it is instantiated by the same two files.
//
// A row, with its lower body held immovable, stops its upper body's points
// from approaching the lower body (or, when apart, from closing more than
// the gap this sub-step). The rows of one group lift distinct upper bodies
// and only read their lower ones, which nothing in the storey moves: the
// lanes of a bundle are independent, and any width gives the same result.

#include <cmath>
#include <cstdint>
#include <span>

#include "contact_solver_wide.h"
#include "prefetch.h"
#include "world_data.h"

namespace impulse {
namespace {

// What a padding lane reads: the static dummy, no points.
const SupportLaneRecord kPaddingSupportLane{};

// A contact holds its upper body sideways when last step's friction
// carried at least this share of what its cone allowed: a body pushed from
// one side (an arch's foot), not one standing free.
constexpr Real kSidewaysShare = Real(0.5);

// Whether the upper body stands on a base narrower than its centre is high
// (a card on its edge), the only kind whose lift turns it enough to slip:
// a box's base is as wide as it is tall, and holding its slip there only
// unsettled stacks and pyramids (a vertical stack 2.5 -> 3.4 mm).
bool standsNarrow(const ContactConstraint& c, bool upperIsB) {
  const Vec2 normal = upperIsB ? c.normal : Vec2(-c.normal);
  const Vec2 tangent(normal.y(), -normal.x());
  const Vec2& first = upperIsB ? c.points[0].anchorB : c.points[0].anchorA;
  const Vec2& last = upperIsB ? c.points[c.pointCount - 1].anchorB : c.points[c.pointCount - 1].anchorA;
  const Real base = std::abs((first - last).dot(tangent));
  const Real centreHeight = -first.dot(normal);
  return base < centreHeight;
}

Real slipFrictionOf(const ContactConstraint& c, bool upperIsB) {
  if (c.pointCount == 0 || !standsNarrow(c, upperIsB)) return 0;
  Real tangent = 0;
  Real normal = 0;
  for (int j = 0; j < c.pointCount; ++j) {
    tangent += c.points[j].tangentImpulse;
    normal += c.points[j].normalImpulse + c.points[j].supportImpulse;
  }
  const Real friction = c.points[0].friction;
  return std::abs(tangent) >= kSidewaysShare * friction * normal && normal > 0 ? friction : Real(0);
}

// One row's numbers into its record, upper body as B: a row holding up A is
// swapped and its normal negated, which leaves every separation and normal
// speed as it was. finishSupportBundle derives the rest.
void packSupportLane(SupportLaneRecord& r, const ContactConstraint& c, bool upperIsB) {
  const Vec2 normal = upperIsB ? c.normal : Vec2(-c.normal);
  r.stateA = upperIsB ? c.stateA : c.stateB;
  r.stateB = upperIsB ? c.stateB : c.stateA;
  r.normalX = normal.x();
  r.normalY = normal.y();
  r.invMass = upperIsB ? c.invMassB : c.invMassA;
  r.invInertia = upperIsB ? c.invInertiaB : c.invInertiaA;
  r.slipFriction = slipFrictionOf(c, upperIsB);
  for (int j = 0; j < 2; ++j) {
    const ConstraintPoint& cp = c.points[j];
    const Vec2& lower = upperIsB ? cp.anchorA : cp.anchorB;
    const Vec2& upper = upperIsB ? cp.anchorB : cp.anchorA;
    SupportLaneRecord::Point& p = r.points[j];
    p.anchorAX = lower.x();
    p.anchorAY = lower.y();
    p.anchorBX = upper.x();
    p.anchorBY = upper.y();
    p.baseSeparation = cp.baseSeparation;
    p.present = j < c.pointCount && cp.normalMass > 0 ? ~std::uint32_t(0) : 0;
  }
}

// Floats of a support lane's record.
constexpr std::size_t kSupportLaneFloats = sizeof(SupportLaneRecord) / sizeof(float);

// The column of point j's field at `pointOffset` in a record.
constexpr std::size_t lanePointColumn(int j, std::size_t pointOffset) {
  return floatAt(offsetof(SupportLaneRecord, points) + std::size_t(j) * sizeof(SupportLaneRecord::Point) +
                 pointOffset);
}

// standsNarrow and slipFrictionOf for a bundle's lanes, upper body as B
// (`normal` already turned so), with the same operations in the same
// order; a bundle's lanes have two points, the second all zero when the
// manifold has one.
template <class F>
F slipFrictionOfLanes(const WideConstraint<F>& c, F upperIsB, F normalX, F normalY) {
  const WidePoint<F>& p0 = c.points[0];
  const WidePoint<F>& p1 = c.points[1];
  const F firstX = simd::select(upperIsB, p0.anchorBX, p0.anchorAX);
  const F firstY = simd::select(upperIsB, p0.anchorBY, p0.anchorAY);
  const F lastX = simd::select(upperIsB, p1.anchorBX, p1.anchorAX);
  const F lastY = simd::select(upperIsB, p1.anchorBY, p1.anchorAY);
  const F base = simd::abs((firstX - lastX) * normalY + (firstY - lastY) * simd::negated(normalX));
  const F centreHeight = simd::negated(firstX * normalX + firstY * normalY);
  const F zero = simd::broadcast<F>(0);
  const F tangent = (zero + p0.tangentImpulse) + p1.tangentImpulse;
  const F normal = (zero + (p0.normalImpulse + p0.supportImpulse)) + (p1.normalImpulse + p1.supportImpulse);
  const F friction = p0.friction;
  const F holds = simd::both(simd::atLeast(simd::abs(tangent), simd::broadcast<F>(kSidewaysShare) * friction * normal),
                             simd::greater(normal, zero));
  return simd::select(simd::both(simd::less(base, centreHeight), holds), friction, zero);
}

// The records of a contact bundle's lanes (packSupportLane's numbers for
// every lane at once), as columns in the record's layout.
template <class F>
void supportColumns(const WideConstraint<F>& c, F upperIsB, F (&column)[kSupportLaneFloats]) {
  const F stateA = simd::loadInts<F>(c.stateA);
  const F stateB = simd::loadInts<F>(c.stateB);
  const F normalX = simd::select(upperIsB, c.normalX, simd::negated(c.normalX));
  const F normalY = simd::select(upperIsB, c.normalY, simd::negated(c.normalY));
  // The record's unused tail; the other columns are all set below (zeroing
  // every column first was a memset, a tenth of v3's many_pyramids' fill).
  for (std::size_t k = floatAt(offsetof(SupportLaneRecord, unused)); k < kSupportLaneFloats; ++k) {
    column[k] = simd::broadcast<F>(0);
  }
  column[floatAt(offsetof(SupportLaneRecord, stateA))] = simd::select(upperIsB, stateA, stateB);
  column[floatAt(offsetof(SupportLaneRecord, stateB))] = simd::select(upperIsB, stateB, stateA);
  column[floatAt(offsetof(SupportLaneRecord, normalX))] = normalX;
  column[floatAt(offsetof(SupportLaneRecord, normalY))] = normalY;
  column[floatAt(offsetof(SupportLaneRecord, invMass))] = simd::select(upperIsB, c.invMassB, c.invMassA);
  column[floatAt(offsetof(SupportLaneRecord, invInertia))] = simd::select(upperIsB, c.invInertiaB, c.invInertiaA);
  column[floatAt(offsetof(SupportLaneRecord, slipFriction))] = slipFrictionOfLanes(c, upperIsB, normalX, normalY);
  using Point = SupportLaneRecord::Point;
  for (int j = 0; j < 2; ++j) {
    const WidePoint<F>& p = c.points[j];
    column[lanePointColumn(j, offsetof(Point, anchorAX))] = simd::select(upperIsB, p.anchorAX, p.anchorBX);
    column[lanePointColumn(j, offsetof(Point, anchorAY))] = simd::select(upperIsB, p.anchorAY, p.anchorBY);
    column[lanePointColumn(j, offsetof(Point, anchorBX))] = simd::select(upperIsB, p.anchorBX, p.anchorAX);
    column[lanePointColumn(j, offsetof(Point, anchorBY))] = simd::select(upperIsB, p.anchorBY, p.anchorAY);
    column[lanePointColumn(j, offsetof(Point, baseSeparation))] = p.baseSeparation;
    column[lanePointColumn(j, offsetof(Point, present))] = simd::greater(p.normalMass, simd::broadcast<F>(0));
  }
}

// The bundle's lanes from their records, as columns.
template <class F>
void loadSupportLanes(const void* const records[F::kLanes], WideSupportRow<F>& row) {
  F column[kSupportLaneFloats];
  loadRecordColumns<F>(records, kSupportLaneFloats, column);
  simd::storeInts(row.stateA, column[floatAt(offsetof(SupportLaneRecord, stateA))]);
  simd::storeInts(row.stateB, column[floatAt(offsetof(SupportLaneRecord, stateB))]);
  row.normalX = column[floatAt(offsetof(SupportLaneRecord, normalX))];
  row.normalY = column[floatAt(offsetof(SupportLaneRecord, normalY))];
  row.invMass = column[floatAt(offsetof(SupportLaneRecord, invMass))];
  row.invInertia = column[floatAt(offsetof(SupportLaneRecord, invInertia))];
  row.slipFriction = column[floatAt(offsetof(SupportLaneRecord, slipFriction))];
  for (int j = 0; j < 2; ++j) {
    WideSupportPoint<F>& p = row.points[j];
    using Point = SupportLaneRecord::Point;
    p.anchorAX = column[lanePointColumn(j, offsetof(Point, anchorAX))];
    p.anchorAY = column[lanePointColumn(j, offsetof(Point, anchorAY))];
    p.anchorBX = column[lanePointColumn(j, offsetof(Point, anchorBX))];
    p.anchorBY = column[lanePointColumn(j, offsetof(Point, anchorBY))];
    p.baseSeparation = column[lanePointColumn(j, offsetof(Point, baseSeparation))];
    p.present = column[lanePointColumn(j, offsetof(Point, present))];
  }
}

// Support bundle b from its lanes' records (a short bundle's others read
// the padding record), and the upper body's response K (impulse to normal
// speed) at the points, K_ij = invMass + invInertia * arm_i * arm_j,
// inverted once per step: both points together (zero when singular or a
// point is missing), and each alone (1 / K_jj; zero for a missing point).
template <class F>
void finishSupportBundle(const SupportLaneRecord* first, int lanes, WideSupportRow<F>& row) {
  const void* records[F::kLanes];
  for (int lane = 0; lane < F::kLanes; ++lane) records[lane] = lane < lanes ? first + lane : &kPaddingSupportLane;
  loadSupportLanes<F>(records, row);
  const F zero = simd::broadcast<F>(0);
  for (WideSupportPoint<F>& p : row.points) {
    p.arm = simd::select(p.present, p.anchorBX * row.normalY - p.anchorBY * row.normalX, zero);
    // anchor x tangent, the tangent being (normalY, -normalX).
    p.tangentArm =
        simd::select(p.present, -(p.anchorBX * row.normalX + p.anchorBY * row.normalY), zero);
  }
  const F arm0 = row.points[0].arm;
  const F arm1 = row.points[1].arm;
  const F k11 = row.invMass + row.invInertia * arm0 * arm0;
  const F k22 = row.invMass + row.invInertia * arm1 * arm1;
  row.k12 = row.invMass + row.invInertia * arm0 * arm1;
  const F one = simd::broadcast<F>(1);
  row.points[0].singleMass = simd::select(row.points[0].present, one / k11, zero);
  row.points[1].singleMass = simd::select(row.points[1].present, one / k22, zero);
  const F det = k11 * k22 - row.k12 * row.k12;
  // Below this the points share one arm: only one of them can lift.
  const F regular = simd::greater(det, simd::broadcast<F>(Real(1e-6)) * k11 * k22);
  const F pair = simd::both(regular, simd::both(row.points[0].present, row.points[1].present));
  row.pairInverse11 = simd::select(pair, k22 / det, zero);
  row.pairInverse12 = simd::select(pair, (-row.k12) / det, zero);
  row.pairInverse22 = simd::select(pair, k11 / det, zero);
}

// A support bundle of one row is solved as that row alone
// (WideContactSet::supportLoneRows): a bundle's cost is mostly its gather
// and scatter of a body per lane, used or not, where a lone row reads and
// writes only its own two. A tower has one row a storey (a 15-box tower's
// holdUp had a quarter of its perf samples), a pyramid's top storeys one each.
// Two rows alone were no faster than their bundle on four lanes.
bool holdsOneRow(const WideContactSet& set, std::int32_t b) { return set.supportSlices.lanes[std::size_t(b)] == 1; }

// visit(row) on support bundle b as the pass keeps it: its lone row where it
// holds one, the bundle of F's lanes otherwise.
template <class F, class Visit>
void visitSupportRow(WideContactSet& set, std::int32_t b, Visit&& visit) {
  if (holdsOneRow(set, b)) {
    visit(set.supportLoneRows[std::size_t(b)]);
  } else {
    visit(supportBundlesOf<F>(set)[std::size_t(b)]);
  }
}

// Refs per range when clearing their support places side by side.
constexpr std::int32_t kPlacesPerRange = 4096;

// Lays the rows out group by group, each group in bundles of F::kLanes, and
// notes each row's lane by its contact, which fills the lane's record as it
// is prepared (packSupportLanes): the contact's numbers are at hand then.
// Side by side (a contact has at most one row): on v3's many_pyramids the
// places' scattered writes had kept the other thread waiting.
template <class F>
void placeSupportRows(const SupportPass& pass, std::size_t refCount, const TaskRunner& tasks, WideContactSet& set) {
  const std::span<const std::int32_t> groups = pass.groupStarts();
  set.supportGroupBundle.resize(groups.size());
  set.supportSlices.cut(groups, F::kLanes, set.supportGroupBundle);
  const std::int32_t count = set.supportSlices.count();
  supportBundlesOf<F>(set).resize(std::size_t(count));
  set.supportLoneRows.resize(std::size_t(count));
  set.supportLanes.resize(std::size_t(count) * F::kLanes);
  set.supportPlaceOf.resize(refCount);
  tasks.forRanges(std::int32_t(refCount), kPlacesPerRange, [&](std::int32_t begin, std::int32_t end) {
    std::fill(set.supportPlaceOf.begin() + begin, set.supportPlaceOf.begin() + end, SupportPlace{});
  });
  tasks.forRanges(count, kBundlesPerFillRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t b = begin; b < end; ++b) {
      const std::int32_t first = set.supportSlices.first[std::size_t(b)];
      std::uint8_t leans = 0;
      for (int lane = 0; lane < set.supportSlices.lanes[std::size_t(b)]; ++lane) {
        const SupportRow& row = pass.rows()[std::size_t(first + lane)];
        set.supportPlaceOf[std::size_t(row.ref)] = {b, static_cast<std::int16_t>(lane), row.upperIsB};
        if (row.leans) leans = std::uint8_t(leans | (1u << lane));
      }
      visitSupportRow<F>(set, b, [&]<class L>(WideSupportRow<L>& bundle) { bundle.leans = simd::maskOfBits<L>(leans); });
    }
  });
}

// The index of a row's lane record (SupportPlace), -1 for a contact that
// holds nothing up.
template <class F>
std::int32_t supportRecordOf(const SupportPlace& place) {
  return place.bundle < 0 ? -1 : place.bundle * F::kLanes + place.lane;
}

template <class F>
SupportLaneRecord& supportLaneOf(WideContactSet& set, const SupportPlace& place) {
  return set.supportLanes[std::size_t(supportRecordOf<F>(place))];
}

// The support lanes of a prepared contact bundle's lanes (`entries`, as
// refs), for the lanes whose contact holds a body up.
template <class F>
void packSupportLanes(WideContactSet& set, const WideConstraint<F>& bundle, std::int32_t b,
                      std::span<const std::int32_t> entries) {
  // What lanes that hold nothing up write (left uninitialised: never read).
  alignas(SupportLaneRecord) float discarded[kSupportLaneFloats];
  void* records[F::kLanes];
  std::uint8_t holds = 0;
  std::uint8_t upperIsB = 0;
  for (int lane = 0; lane < F::kLanes; ++lane) {
    records[lane] = discarded;
    if (std::size_t(lane) >= entries.size()) continue;
    const SupportPlace place = set.supportPlaceOf[std::size_t(entries[std::size_t(lane)])];
    set.laneSupportRecord[std::size_t(b) * F::kLanes + std::size_t(lane)] = supportRecordOf<F>(place);
    if (place.bundle < 0) continue;
    records[lane] = &supportLaneOf<F>(set, place);
    holds = std::uint8_t(holds | (1u << lane));
    if (place.upperIsB) upperIsB = std::uint8_t(upperIsB | (1u << lane));
  }
  if (holds == 0) return;
  F column[kSupportLaneFloats];
  supportColumns(bundle, simd::maskOfBits<F>(upperIsB), column);
  storeRecordColumns<F>(column, kSupportLaneFloats, records);
}

// Each support bundle's masses once all its lanes are in, side by side.
template <class F>
void finishSupportBundles(const TaskRunner& tasks, WideContactSet& set) {
  tasks.forRanges(set.supportSlices.count(), kBundlesPerFillRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t b = begin; b < end; ++b) {
      const SupportLaneRecord* first = &set.supportLanes[std::size_t(b) * F::kLanes];
      const int lanes = set.supportSlices.lanes[std::size_t(b)];
      visitSupportRow<F>(set, b, [&](auto& bundle) { finishSupportBundle(first, lanes, bundle); });
    }
  });
}

template <class F>
struct Lift {
  F first, second;
};

// The smallest non-negative impulses (at most two points) that lift every
// point by its shortfall b: the 2x2 linear complementarity problem by its
// cases, the first that holds taken. Solving the two points one after the
// other instead gives the first a spin the second only half undoes: a box
// resting flat crept sideways. No shortfall, no lift.
template <class F>
Lift<F> liftImpulses(const WideSupportRow<F>& row, F b1, F b2) {
  const F zero = simd::broadcast<F>(0);
  const F pair1 = row.pairInverse11 * b1 + row.pairInverse12 * b2;
  const F pair2 = row.pairInverse12 * b1 + row.pairInverse22 * b2;
  const F pairHolds = simd::both(simd::both(simd::atLeast(pair1, zero), simd::atLeast(pair2, zero)),
                                 simd::either(simd::greater(pair1, zero), simd::greater(pair2, zero)));
  const F alone1 = b1 * row.points[0].singleMass;
  const F alone1Holds = simd::both(simd::greater(alone1, zero), simd::atLeast(row.k12 * alone1, b2));
  const F alone2 = b2 * row.points[1].singleMass;
  const F alone2Holds = simd::both(simd::greater(alone2, zero), simd::atLeast(row.k12 * alone2, b1));
  const F anyShortfall = simd::either(simd::greater(b1, zero), simd::greater(b2, zero));
  const F first = simd::select(pairHolds, pair1, simd::select(alone1Holds, alone1, zero));
  const F second =
      simd::select(pairHolds, pair2, simd::select(alone1Holds, zero, simd::select(alone2Holds, alone2, zero)));
  return {simd::select(anyShortfall, first, zero), simd::select(anyShortfall, second, zero)};
}

// How much faster each point's normal speed must be for it to stop
// approaching the lower body (or, when apart, closing more than the gap
// this sub-step).
template <class F>
Lift<F> shortfalls(const WideBody<F>& lower, const WideBody<F>& upper, F inverseSubStep,
                   const WideSupportRow<F>& row) {
  const F zero = simd::broadcast<F>(0);
  const F dpx = upper.dpx - lower.dpx;
  const F dpy = upper.dpy - lower.dpy;
  F shortfall[2];
  for (int j = 0; j < 2; ++j) {
    const WideSupportPoint<F>& p = row.points[j];
    const F separation = currentSeparation(lower, upper, p, dpx, dpy, row);
    const F slowestAllowed = simd::select(simd::greater(separation, zero), (-separation) * inverseSubStep, zero);
    shortfall[j] = simd::select(p.present, slowestAllowed - normalVelocity(lower, upper, row, p), zero);
  }
  return {shortfall[0], shortfall[1]};
}

// Speed of the upper body's point over the lower body's along the tangent.
template <class F>
F slipSpeed(const WideBody<F>& lower, const WideBody<F>& upper, const WideSupportRow<F>& row,
            const WideSupportPoint<F>& p) {
  const Relative<F> dv = relativeVelocity(lower, upper, p);
  return dv.vx * row.normalY - dv.vy * row.normalX;
}

// A row on the static world is a rigid contact, and its lift must not make
// its points slip. Lifting one point more than the other turns the upper
// body about its centre, which slides its points along the ground after the
// friction rows have held them: a stone pushed from one side (an arch's
// foot) was turned the same way every sub-step and crept outwards. Friction
// at the face (the points' mean) takes that slip back, within the friction
// of the lift; both points at once, as one point after the other would
// lean a straight tower.
template <class F>
void holdSlip(const WideBody<F>& lower, WideBody<F>& upper, const WideSupportRow<F>& row,
              const F slipBefore[2], const Lift<F>& lift) {
  const F zero = simd::broadcast<F>(0);
  const F half = simd::broadcast<F>(0.5f);
  const WideSupportPoint<F>& first = row.points[0];
  const WideSupportPoint<F>& second = row.points[1];
  const F slip0 = slipSpeed(lower, upper, row, first) - slipBefore[0];
  const F slip1 = slipSpeed(lower, upper, row, second) - slipBefore[1];
  const F both = simd::both(first.present, second.present);
  const F slip =
      simd::select(both, half * (slip0 + slip1), simd::select(first.present, slip0, zero));
  const F arm = simd::select(both, half * (first.tangentArm + second.tangentArm), first.tangentArm);
  const F response = row.invMass + row.invInertia * arm * arm;
  const F mass = simd::select(first.present, simd::broadcast<F>(1) / response, zero);
  const F limit = row.slipFriction * (lift.first + lift.second);
  const F impulse = simd::clamp(-(mass * slip), -limit, limit);
  upper.vx += row.invMass * impulse * row.normalY;
  upper.vy -= row.invMass * impulse * row.normalX;
  upper.w += row.invInertia * arm * impulse;
}

// The lift of the lanes a run solves (`rows`), and none in the others, whose
// impulses stay as their own run left them.
template <class F>
Lift<F> liftOf(SupportRows rows, const Lift<F>& lift, WideSupportRow<F>& row) {
  const F zero = simd::broadcast<F>(0);
  if (rows == SupportRows::Leaning) {
    row.points[0].impulse = simd::select(row.leans, lift.first, row.points[0].impulse);
    row.points[1].impulse = simd::select(row.leans, lift.second, row.points[1].impulse);
    return {simd::select(row.leans, lift.first, zero), simd::select(row.leans, lift.second, zero)};
  }
  row.points[0].impulse = simd::select(row.leans, row.points[0].impulse, lift.first);
  row.points[1].impulse = simd::select(row.leans, row.points[1].impulse, lift.second);
  return {simd::select(row.leans, zero, lift.first), simd::select(row.leans, zero, lift.second)};
}

template <class F>
void holdUp(std::span<SolverState> states, F inverseSubStep, SupportRows rows, bool onStaticWorld,
            WideSupportRow<F>& row) {
  if (rows == SupportRows::Leaning && !simd::any(row.leans)) return;
  const WideBody<F> lower = gather<F>(states, row.stateA);
  WideBody<F> upper = gather<F>(states, row.stateB);
  F slipBefore[2] = {};
  if (onStaticWorld) {
    for (int j = 0; j < 2; ++j) slipBefore[j] = slipSpeed(lower, upper, row, row.points[j]);
  }
  const Lift<F> shortfall = shortfalls(lower, upper, inverseSubStep, row);
  const Lift<F> lift = liftOf(rows, liftImpulses(row, shortfall.first, shortfall.second), row);
  const F push = row.invMass * (lift.first + lift.second);
  upper.vx += push * row.normalX;
  upper.vy += push * row.normalY;
  upper.w += row.invInertia * (row.points[0].arm * lift.first + row.points[1].arm * lift.second);
  if (onStaticWorld) holdSlip(lower, upper, row, slipBefore, lift);
  scatter<F>(states, row.stateB, upper);
}

// Storey by storey from the ground (storey 0: the rows on the static
// world); within a storey the groups run backwards on the sub-steps that
// also reverse the contacts' point order. A group's bundles run side by
// side: its rows lift distinct upper bodies and only read lower ones, in
// ranges as short as a colour's: with 64 bundles a range, a group of fewer
// than 128 (the upper storeys of v3's many_pyramids) ran on one thread
// while the other waited.
template <class F>
void solveSupportWide(const ContactSolverContext& context, WideContactSet& set,
                      const SupportPass& pass, SupportRows rows) {
  const float inverseSubStep = context.inverseSubStep;
  const std::span<const std::int32_t> storeys = pass.storeyStarts();
  for (std::size_t storey = 0; storey + 1 < storeys.size(); ++storey) {
    const std::int32_t first = storeys[storey];
    const std::int32_t count = storeys[storey + 1] - first;
    for (std::int32_t k = 0; k < count; ++k) {
      const std::size_t group = std::size_t(context.reversePointOrder ? first + count - 1 - k : first + k);
      const std::int32_t groupFirst = set.supportGroupBundle[group];
      context.tasks->forRanges(set.supportGroupBundle[group + 1] - groupFirst, kBundlesPerColorRange,
                               [&](std::int32_t begin, std::int32_t end) {
                                 for (std::int32_t b = groupFirst + begin; b < groupFirst + end; ++b) {
                                   visitSupportRow<F>(set, b, [&]<class L>(WideSupportRow<L>& bundle) {
                                     holdUp(context.states, simd::broadcast<L>(inverseSubStep), rows, storey == 0,
                                            bundle);
                                   });
                                 }
                               });
    }
  }
}

// The last sub-step's impulses, bundle by bundle, into supportImpulses:
// where the contacts' store takes them from (supportImpulseOf), in their
// own order, instead of writing each row's manifold a second time.
template <class F>
void collectSupportImpulses(WideContactSet& set, const TaskRunner& tasks) {
  const std::int32_t count = set.supportSlices.count();
  set.supportImpulses.resize(std::size_t(count) * 2 * F::kLanes);
  tasks.forRanges(count, kBundlesPerFillRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t b = begin; b < end; ++b) {
      float* columns = &set.supportImpulses[std::size_t(b) * 2 * F::kLanes];
      visitSupportRow<F>(set, b, [&](const auto& bundle) {
        for (int j = 0; j < 2; ++j) simd::store(columns + std::size_t(j) * F::kLanes, bundle.points[j].impulse);
      });
    }
  });
}

// Point j's impulse of the row whose lane is record `record`
// (collectSupportImpulses).
template <class F>
float supportImpulseOf(const WideContactSet& set, std::int32_t record, int j) {
  const std::size_t bundle = std::size_t(record) / F::kLanes;
  const std::size_t lane = std::size_t(record) % F::kLanes;
  return set.supportImpulses[(bundle * 2 + std::size_t(j)) * F::kLanes + lane];
}

}  // namespace
}  // namespace impulse
