#pragma once
// The contact solver's data: one touching contact as a constraint, and the
// same side by side in SIMD bundles (contact_solver_wide.h).

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "contact_data.h"
#include "graph_coloring.h"
#include "simd.h"
#include "solver_data.h"
#include "task_runner.h"
#include "wide_support_row.h"

namespace impulse {

/// A touching contact the solver takes this step, with its bodies' solver
/// states (0: the static dummy, for anything not awake).
struct ConstraintRef {
  std::int32_t contact = kNullIndex;
  std::int32_t stateA = 0;
  std::int32_t stateB = 0;
  /// Holds its upper body up in the support pass (support_pass.h).
  bool holdsUp = false;
  /// Whether the contact is level enough to stand on, and which way up
  /// (support_pass.h, facingOf): +1 with B above, -1 with A above, 0 not
  /// level; twice that when flat.
  /// Read with the contact's bodies, whose line holds its normal too.
  std::int8_t facing = 0;
  /// One of its bodies hangs on steep contacts (an arch's upper stones,
  /// support_pass.h): as a wedge's contact it holds from lighter loads
  /// (kHangingHold, contact_solver.h).
  bool hangs : 1 = false;
  /// A point touches (within kStartTouch, support_pass.h) and none carried
  /// a load last step: it may be new, and start from an estimated load
  /// (SupportPass::estimateStartLoads). This flag, the last and the next
  /// are bits of one byte, which keeps the masses within the ref's first 32
  /// bytes, all the wide fill reads of it (kRefFloats).
  bool touchesUnloaded : 1 = false;
  /// Quiet: it carried no impulse last step (normal, support, friction or
  /// rolling) and every point is apart. Most of a tumbling crowd's
  /// speculative contacts stay so through a step; each colour's quiet
  /// contacts are bundled together (colourContacts), so that passes over
  /// bundles that would change nothing skip their bodies' write-back.
  bool quiet : 1 = false;
  /// Its manifold has two points: each colour's one-point contacts are
  /// bundled together too, whose passes skip the second point.
  bool twoPoints : 1 = false;
  /// Body A (B) has joints, read off the bodies with the rest of the ref.
  bool jointedA : 1 = false;
  bool jointedB : 1 = false;
  /// The byte's other bits, named so that a ref built whole is stored whole:
  /// left unnamed, they were read back from the ref's place before each
  /// store, a cache miss for most refs (a third of their collection's time).
  std::uint8_t unusedBits : 2 = 0;
  /// The bodies' inverse mass and inertia, zero unless awake: read once
  /// with the states, so preparing a contact touches no body.
  Real invMassA = 0;
  Real invInertiaA = 0;
  Real invMassB = 0;
  Real invInertiaB = 0;
  /// What its points carried in the last sub-step of last step (normal
  /// plus support impulses): the support pass's measured load.
  Real lastLoad = 0;

  /// Either body has joints: its loads are not weights it carries, so the
  /// contact never holds as a wedge's (kHold, contact_solver.h).
  bool jointed() const { return jointedA || jointedB; }
  /// Body A (B) moves and has no joints: only such a body stands on a row
  /// of the support pass (a jointed one is held by more than its contacts:
  /// lifting it alone would fight its joints, as a welded pair landing
  /// twisted did).
  bool freeA() const { return stateA != 0 && !jointedA; }
  bool freeB() const { return stateB != 0 && !jointedB; }
};

struct ConstraintPoint {
  Vec2 anchorA = Vec2::Zero();
  Vec2 anchorB = Vec2::Zero();
  Real baseSeparation = 0;
  Real normalImpulse = 0;
  Real tangentImpulse = 0;
  Real totalNormalImpulse = 0;
  /// The support pass's impulse (ManifoldPoint::supportImpulse).
  Real supportImpulse = 0;
  Real normalMass = 0;
  Real tangentMass = 0;
  Real relativeVelocity = 0;
  Real friction = 0;
  /// Overlap at which the soft contact holds the load it carried last step.
  Real loadOverlap = 0;
  /// Fastest the soft contact may push (m/s): enough to carry that load.
  Real pushCap = 0;
  /// Push (m/s) added while overlapping, so that the soft contact holds
  /// most of that load with no overlap (kHold, contact_solver.h); 0 on
  /// most contacts.
  Real holdSpeed = 0;
};

struct ContactConstraint {
  std::int32_t stateA = 0;
  std::int32_t stateB = 0;
  std::int32_t contact = kNullIndex;
  int pointCount = 0;
  Vec2 normal = Vec2::Zero();
  Real invMassA = 0;
  Real invInertiaA = 0;
  Real invMassB = 0;
  Real invInertiaB = 0;
  Real restitution = 0;
  Real rollingResistance = 0;
  Real rollingImpulse = 0;
  Real rollingMass = 0;
  Softness softness;
  ConstraintPoint points[2];
};

// Constraints side by side for the SIMD solver (contact_solver_wide.h), as
// many as the lane type F holds: four on SSE2, eight on AVX2.
// A bundle holds what the sub-steps' passes read, on whole cache lines of
// its own; what only the push and restitution passes and the store read
// lies apart (WideContactCold), so that the passes over every bundle
// stream fewer lines: 21 instead of 25 on AVX2 (v3's many_pyramids: the
// solve's perf samples about 3 % fewer, the whole step's 1.7 %).
template <class F>
struct WidePoint {
  F anchorAX, anchorAY, anchorBX, anchorBY;
  F baseSeparation;
  F normalImpulse, tangentImpulse, totalNormalImpulse, supportImpulse;
  F normalMass, tangentMass;
  F friction, pushCap, holdSpeed;
};

template <class F>
struct alignas(64) WideConstraint {
  std::int32_t stateA[F::kLanes];
  std::int32_t stateB[F::kLanes];
  F normalX, normalY;
  F invMassA, invInertiaA, invMassB, invInertiaB;
  F biasRate, massScale, impulseScale;
  // The last two are read only where a lane resists rolling.
  F rollingResistance, rollingMass, rollingImpulse;
  WidePoint<F> points[2];
};

/// A bundle's fields the warm start, solve and relax passes never read.
template <class F>
struct alignas(64) WideContactCold {
  /// The contact each lane came from (-1: padding).
  std::int32_t source[F::kLanes];
  F restitution;
  /// Per point, the normal speed when prepared (the restitution pass's).
  F relativeVelocity[2];
  /// Per point, the overlap at which its soft contact holds its last load
  /// (ConstraintPoint::loadOverlap): the push pass's.
  F loadOverlap[2];
};

// Eight-lane bundles (contact and support): a type only the AVX2 file completes (see simd_avx2.h
// on why no other file may lay them out).
struct Avx2Bundles;
struct Avx2BundlesDeleter {
  void operator()(Avx2Bundles* bundles) const;  // contact_solver_wide_avx2.cpp
};

/// The support lane a contact fills as it is prepared (bundle -1: its
/// contact holds nothing up), and which side of it is the upper body.
struct SupportPlace {
  std::int32_t bundle = -1;
  std::int16_t lane = 0;
  bool upperIsB = false;
};

/// Runs of entries cut into bundles of a lane width: bundle b holds entries
/// [first[b], first[b] + lanes[b]) of its list. Laid out one after the
/// other, so the bundles can then be filled side by side.
struct BundleSlices {
  std::vector<std::int32_t> first;
  std::vector<std::uint8_t> lanes;

  std::int32_t count() const { return static_cast<std::int32_t>(first.size()); }
  /// Cuts each run [runStarts[i], runStarts[i + 1]) into bundles of `width`
  /// (the last of a run may be short); runBundleStart[i] receives run i's
  /// first bundle, and its last entry the bundle count.
  void cut(std::span<const std::int32_t> runStarts, int width, std::span<std::int32_t> runBundleStart);
};

/// What the passes over a contact bundle read of it besides its fields.
struct BundleTraits {
  /// Every lane was quiet when prepared (ConstraintRef::quiet): its passes
  /// first check whether they would change anything (staysQuiet).
  bool quiet = false;
  /// A bit per lane whose manifold has two points: the store writes their
  /// second point's impulses without reading the manifold's count first.
  std::uint8_t twoPointLanes = 0;
  /// A bit per lane whose body A, and B, contacts can move (a mass or an
  /// inertia to give): only those are written back. A static, kinematic or
  /// padding lane's body is only read, so any number of lanes of a colour
  /// may share it (movesBody).
  std::uint8_t movesA = 0;
  std::uint8_t movesB = 0;
  /// A lane reads a body it does not move (on a state, not in movesA or
  /// movesB): only then are the masks read (scatterBundle).
  bool readsOnly = false;
  /// A lane may bounce (approached faster than the restitution threshold
  /// when prepared, on a contact that bounces at all).
  bool mayBounce = false;

  /// The most points a lane has (1 or 2): the warm start, solve, relax and
  /// push of a bundle of one-point lanes (circles) skip the second point,
  /// all zero, which would move nothing.
  int points() const { return twoPointLanes != 0 ? 2 : 1; }
};

/// Whether contacts can change a body's motion: the colouring takes a
/// colour only for such bodies, and the bundles write back only theirs.
inline bool movesBody(Real invMass, Real invInertia) { return invMass != 0 || invInertia != 0; }

/// WideContactSet::pushZone's marks: a body with an intruding contact, and
/// the rings of bodies one and two contacts from it.
inline constexpr std::uint8_t kIntrudingBody = 3;
inline constexpr std::uint8_t kNearIntrusion = 1;

struct WideContactSet {
  /// Bundles of the width in use (the other stays empty).
  std::vector<WideConstraint<simd::F4>> bundles4;
  std::vector<WideContactCold<simd::F4>> cold4;
  std::unique_ptr<Avx2Bundles, Avx2BundlesDeleter> bundles8;
  std::vector<ContactConstraint> overflow;
  /// Per ConstraintRef, its support lane (support_pass_wide_impl.h).
  std::vector<SupportPlace> supportPlaceOf;
  /// Colour c's bundles are [colorBundleStart[c], colorBundleStart[c + 1]):
  /// one colour's bundles can be solved side by side.
  std::array<std::int32_t, GraphColoring::kOverflow + 1> colorBundleStart{};
  /// The support pass's rows in bundles of the width in use (eight-lane ones
  /// in bundles8); support group g is bundles [supportGroupBundle[g],
  /// supportGroupBundle[g + 1]).
  std::vector<WideSupportRow<simd::F4>> support4;
  /// Per support bundle that holds one row, that row alone, which the
  /// support pass solves instead of the bundle (support_pass_wide_impl.h).
  std::vector<WideSupportRow<simd::F1>> supportLoneRows;
  std::vector<std::int32_t> supportGroupBundle;
  /// Lane l of support bundle b as its contact filled it: record
  /// b * lanes + l (SupportLaneRecord).
  std::vector<SupportLaneRecord> supportLanes;
  /// Per contact bundle lane (b * lanes + l) and per overflow constraint,
  /// the record of its contact's support lane (-1: it holds nothing up).
  std::vector<std::int32_t> laneSupportRecord;
  std::vector<std::int32_t> overflowSupportRecord;
  /// The support rows' last impulses, per support bundle its points'
  /// columns: what the contacts' store writes into their manifolds.
  std::vector<float> supportImpulses;
  /// The push pass's contacts: those of the bodies at most two contacts
  /// from one whose contact overlaps deeper than its load explains when
  /// prepared (hasIntrusion), which pushZone marks. The bundles with such a
  /// lane, in bundle order, and per contact bundle its pushed lanes (a bit
  /// each, none for a bundle not listed); and by index in the overflow
  /// list.
  std::vector<std::int32_t> pushBundles;
  std::vector<std::uint8_t> bundlePushLanes;
  std::vector<std::int32_t> pushOverflow;
  /// Per overflow constraint, 1 where it intrudes (as bundleIntrusion).
  std::vector<std::uint8_t> overflowIntrudes;
  /// How many contacts that is.
  int pushedContacts = 0;
  /// How many of the step's contacts are quiet (ConstraintRef::quiet).
  int quietContacts = 0;
  /// Per solver state: kIntrudingBody where one of its contacts intrudes,
  /// down to kNearIntrusion two contacts from such a body, else 0 (the
  /// static dummy 0 always); pushQueue is markNearIntrusions' scratch.
  std::vector<std::uint8_t> pushZone;
  std::vector<std::int32_t> pushQueue;
  /// Each ref's key (its colour, its quiet ones after the others), the refs
  /// sorted by it, and where each colour starts in that order
  /// (colourContacts).
  std::vector<std::int32_t> colorKey;
  std::vector<std::int32_t> order;
  ColorStarts colorStart{};
  /// Per entry of WorldData::touchingUnsorted, its ConstraintRef.
  std::vector<std::int32_t> refOfUnsorted;
  /// The contact bundles' entries of `order`, and the support bundles'
  /// rows; per contact bundle, its lanes that intruded when prepared
  /// (bundles fill side by side, the intrusions are marked after).
  BundleSlices contactSlices;
  BundleSlices supportSlices;
  std::vector<std::uint8_t> bundleIntrusion;
  std::vector<BundleTraits> bundleTraits;
  /// The restitution pass's bundles (BundleTraits::mayBounce), in bundle
  /// order.
  std::vector<std::int32_t> bounceBundles;
};

/// What the contact passes of one sub-step read besides the constraints.
struct ContactSolverContext {
  std::span<SolverState> states;  // [0] is the static dummy
  std::span<ContactConstraint> constraints;
  Real inverseSubStep = 0;
  Real maxPushSpeed = 0;
  Real restitutionThreshold = 0;
  /// Solve each manifold's second normal point first. Solving two points one
  /// after the other favours one side, and a tall stack leans that way; the
  /// solver alternates the order every sub-step so the favour cancels.
  bool reversePointOrder = false;
  /// Runs a colour's bundles side by side.
  const TaskRunner* tasks = nullptr;
};

/// The step's contact softness: between dynamic bodies, and against static
/// ones (stiffer, so stacks are not pushed into the ground); and a unit
/// mass's weight per sub-step (g h; 0 without gravity), against which a
/// contact's load is measured (kHold, contact_solver.h).
struct ContactSoftness {
  Softness dynamic;
  Softness statics;
  Real weightPerMass = 0;
};

}  // namespace impulse
