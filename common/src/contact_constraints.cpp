#include "contact_constraints.h"

#include <algorithm>
#include <array>
#include <span>

#include "contact_solver_wide.h"
#include "counting_sort.h"
#include "prefetch.h"
#include "world_data.h"

namespace impulse {

namespace {

// A body's side of a ref. Anything not awake (static) shares the dummy
// state 0 and gets zero inverse mass, so the dummy's velocity stays zero
// without checks.
struct RefSide {
  std::int32_t state = 0;
  Real invMass = 0;
  Real invInertia = 0;
};

RefSide sideOf(const Body& body) {
  return body.awake ? RefSide{body.solverIndex, body.invMass, body.invInertia} : RefSide{};
}

Real lastLoad(const Manifold& manifold) {
  Real load = 0;
  for (int j = 0; j < manifold.pointCount; ++j) {
    load += manifold.points[j].normalImpulse + manifold.points[j].supportImpulse;
  }
  return load;
}

// Whether a point touches (kStartTouch): read with the manifold's impulses.
bool touches(const Manifold& manifold) {
  for (int j = 0; j < manifold.pointCount; ++j) {
    if (manifold.points[j].separation <= kStartTouch) return true;
  }
  return false;
}

// ConstraintRef::quiet, given the manifold's last load (normal and support).
bool quiet(const Manifold& manifold, Real load) {
  if (load != 0 || manifold.rollingImpulse != 0) return false;
  for (int j = 0; j < manifold.pointCount; ++j) {
    if (manifold.points[j].tangentImpulse != 0 || manifold.points[j].separation <= 0) return false;
  }
  return manifold.pointCount > 0;
}

// Everything the step reads of a contact outside its bundle lane, read
// together while its lines are in.
ConstraintRef refOf(const WorldData& world, std::int32_t index, const Vec2& up) {
  const Contact& contact = world.contacts[index];
  const Body& bodyA = world.bodies[contact.edges.bodyA];
  const Body& bodyB = world.bodies[contact.edges.bodyB];
  const RefSide a = sideOf(bodyA);
  const RefSide b = sideOf(bodyB);
  const Real load = lastLoad(contact.manifold);
  return {.contact = index,
          .stateA = a.state,
          .stateB = b.state,
          .facing = facingOf(contact.manifold.normal, up),
          .touchesUnloaded = load == 0 && touches(contact.manifold),
          .quiet = quiet(contact.manifold, load),
          .twoPoints = contact.manifold.pointCount == 2,
          .jointedA = bodyA.jointHead != kNullIndex,
          .jointedB = bodyB.jointHead != kNullIndex,
          .invMassA = a.invMass,
          .invInertiaA = a.invInertia,
          .invMassB = b.invMass,
          .invInertiaB = b.invInertia,
          .lastLoad = load};
}

// Contacts ahead of the one read whose lines (the manifold's two, and the
// one naming its bodies) are fetched meanwhile: the list runs through memory
// in order, but with gaps. Half as far ahead, that line has arrived, and the
// bodies it names and the ref the contact fills are fetched: a body's lines
// and the ref's place (the refs are filled in solver order, scattered) are
// misses of their own. At 4 contacts ahead and without the bodies and refs,
// the loop waited on each of the three (v3's washer: about a quarter more
// perf samples); at 16 rather than 32, on the bodies still (many_pyramids:
// a tenth more of the loop's samples).
constexpr std::int32_t kRefPrefetchDistance = 32;

// The line of a body that refOf reads: its first (Body's layout).
void fetchRefSide(const Body& body) { fetchLines(&body); }

// The fetches for entry j of the narrow phase's list (see above).
void fetchAhead(const WorldData& world, std::span<ConstraintRef> refs, std::span<const std::int32_t> refOfUnsorted,
                std::int32_t j, std::int32_t end) {
  if (j + kRefPrefetchDistance < end) {
    const Contact& far = world.contacts[world.touchingUnsorted[std::size_t(j + kRefPrefetchDistance)]];
    fetchLines(&far.manifold, sizeof(Manifold));
    fetchLines(&far.edges);
  }
  const std::int32_t near = j + kRefPrefetchDistance / 2;
  if (near >= end) return;
  const Contact& contact = world.contacts[world.touchingUnsorted[std::size_t(near)]];
  fetchRefSide(world.bodies[contact.edges.bodyA]);
  fetchRefSide(world.bodies[contact.edges.bodyB]);
  fetchLinesForWrite(&refs[std::size_t(refOfUnsorted[std::size_t(near)])], sizeof(ConstraintRef));
}

// Refs per range when collecting them side by side.
constexpr std::int32_t kRefsPerRange = 256;

// The touching contacts the step solves: the narrow phase's list. Made in
// the order memory holds the contacts (reading them in the list's order
// misses the cache about once a contact); `refOfUnsorted` keeps where each
// went.
void collectTouching(const WorldData& world, std::vector<ConstraintRef>& refs,
                     std::vector<std::int32_t>& refOfUnsorted) {
  refs.resize(world.touchingContacts.size());
  placesInOrder(world.touchingOrder, refOfUnsorted);
  const Vec2 up = upwards(world.settings.gravity);
  world.tasks.forRanges(static_cast<std::int32_t>(refs.size()), kRefsPerRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t j = begin; j < end; ++j) {
      fetchAhead(world, refs, refOfUnsorted, j, end);
      refs[std::size_t(refOfUnsorted[std::size_t(j)])] = refOf(world, world.touchingUnsorted[std::size_t(j)], up);
    }
  });
}

// Per solver state, whether one of the refs is its: read off the refs in
// their order, not off each body's contact list (a miss per contact).
void markTouchingStates(std::span<const ConstraintRef> refs, std::size_t stateCount,
                        std::vector<std::uint8_t>& touching) {
  touching.assign(stateCount, 0);
  for (const ConstraintRef& ref : refs) {
    touching[std::size_t(ref.stateA)] = 1;
    touching[std::size_t(ref.stateB)] = 1;
  }
}

// Keys per colour: whether quiet, then whether of two points.
constexpr int kKeysPerColor = 4;

// A ref's place within its colour: quiet ones last, and within either part
// the one-point ones first.
int keyWithinColor(const ConstraintRef& ref) { return (ref.quiet ? 2 : 0) + (ref.twoPoints ? 1 : 0); }

// Takes each ref a colour from the step's shared colouring and sorts the
// refs by colour, each colour's quiet ones last and its one-point ones
// together: what the wide build cuts into bundles (and counts the quiet
// ones, SolverPasses::quietContacts). A colour's contacts share
// no body, so their order within it changes no result; the overflow's,
// solved one by one, keep theirs. The sort runs over the keys of the
// colours taken and the overflow's, which follows them: its fixed cost over
// all 65 colours' keys was 1.6 % of a 15-box tower's step, 6 % of two boxes'.
void colourContacts(std::span<const ConstraintRef> refs, GraphColoring& coloring, WideContactSet& set) {
  constexpr std::int32_t kOverflowKey = kKeysPerColor * GraphColoring::kOverflow;
  set.colorKey.resize(refs.size());
  int coloursTaken = 0;
  bool anyOverflow = false;
  std::int32_t quiet = 0;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const ConstraintRef& ref = refs[i];
    quiet += ref.quiet ? 1 : 0;
    // A body contacts do not move (static, kinematic) is only read: it
    // takes no colour, or a drum's contacts would take one colour each.
    const int color = coloring.take(movesBody(ref.invMassA, ref.invInertiaA) ? ref.stateA : 0,
                                    movesBody(ref.invMassB, ref.invInertiaB) ? ref.stateB : 0);
    const bool overflows = color == GraphColoring::kOverflow;
    anyOverflow = anyOverflow || overflows;
    coloursTaken = overflows ? coloursTaken : std::max(coloursTaken, color + 1);
    set.colorKey[i] = overflows ? kOverflowKey : kKeysPerColor * color + keyWithinColor(ref);
  }
  const std::int32_t overflowKey = kKeysPerColor * coloursTaken;
  if (anyOverflow) std::replace(set.colorKey.begin(), set.colorKey.end(), kOverflowKey, overflowKey);
  std::array<std::int32_t, kOverflowKey + 1> keyStart;
  countingSort(set.colorKey, std::span(keyStart).first(std::size_t(overflowKey) + 1), set.order);
  for (std::size_t color = 0; color <= GraphColoring::kOverflow; ++color) {
    const int key = int(color) < coloursTaken ? kKeysPerColor * int(color) : overflowKey;
    set.colorStart[color] = keyStart[std::size_t(key)];
  }
  set.colorStart[GraphColoring::kOverflow + 1] = std::int32_t(refs.size());
  set.quietContacts = quiet;
}

// The kernels for this step's colours: the widest the world allows, but
// the narrowest (SSE2's four lanes) when no colour has more contacts than
// that. A bundle's cost is mostly its eight bodies' gather and scatter,
// lanes used or not: with every colour at four contacts or fewer (a box
// under a heavy one, a short stack) the bundles are as many at four lanes,
// each about half the work (heavy-on-box-1000 and mass-ratio-400 took
// 0.85 of the time), and every width gives the same bits.
const WideContactKernels& kernelsForColours(SimdWidth requested, const ColorStarts& starts) {
  const WideContactKernels& narrowest = wideContactKernels(SimdWidth::Sse2);
  for (std::size_t color = 0; color < GraphColoring::kOverflow; ++color) {
    if (starts[color + 1] - starts[color] > narrowest.lanes) return wideContactKernels(requested);
  }
  return narrowest;
}

ContactSoftness contactSoftness(const WorldSettings& settings, Real h) {
  Real hertz = std::min(settings.contactHertz, Real(0.25) / h);
  return {makeSoftness(hertz, settings.contactDampingRatio, h),
          makeSoftness(2 * hertz, settings.contactDampingRatio, h), settings.gravity.norm() * h};
}

}  // namespace

void ContactConstraints::collect(const WorldData& world) {
  collectTouching(world, refs_, wide_.refOfUnsorted);
  markTouchingStates(refs_, world.solverStates.size(), touching_);
}

bool ContactConstraints::prepare(const WorldData& world, const SolveStep& step, GraphColoring& coloring) {
  const ContactSoftness softness = contactSoftness(world.settings, step.h);
  const std::size_t stateCount = world.solverStates.size();
  if (refs_.empty()) {
    // Nothing to colour or bundle: the solver skips this kind's passes
    // (empty()). The support pass still learns that no stack stands.
    support_.order(world, refs_, stateCount, softness, step.h);
    return false;
  }
  context_ = {{}, {}, 1 / step.h, world.settings.maxContactPushSpeed, world.settings.restitutionThreshold};
  // The support pass's plan writes only the refs' flags; the colours read
  // only their states: the two go side by side, given a range of refs.
  world.tasks.bothAtOnce(std::int32_t(refs_.size()), kRefsPerRange,
                         [&] { support_.order(world, refs_, stateCount, softness, step.h); },
                         [&] { colourContacts(refs_, coloring, wide_); });
  kernels_ = &kernelsForColours(world.settings.simdWidth, wide_.colorStart);
  return kernels_->build(world, refs_, softness, support_, wide_);
}

ContactSolverContext ContactConstraints::contextFor(const SubStep& sub) const {
  ContactSolverContext context = context_;
  context.states = sub.states;
  context.reversePointOrder = sub.index % 2 == 1;
  context.tasks = sub.tasks;
  return context;
}

void ContactConstraints::warmStart(const SubStep& sub) { kernels_->warmStart(contextFor(sub), wide_); }
void ContactConstraints::solve(const SubStep& sub) {
  const ContactSolverContext context = contextFor(sub);
  // Leaning rows first, so that the soft rows' friction has the last word
  // on how their bodies slide (support_pass.h).
  if (support_.leaningRows() > 0)
    kernels_->solveSupport(context, wide_, support_, SupportRows::Leaning);
  kernels_->solve(context, wide_, true);
  // A structure built at rest settles its new contacts' loads (kStartPasses).
  if (sub.index == 0) {
    for (int pass = 0; pass < support_.startPasses(); ++pass) kernels_->solve(context, wide_, true);
  }
  kernels_->solveSupport(context, wide_, support_, SupportRows::Standing);
}
void ContactConstraints::relax(const SubStep& sub) { kernels_->solve(contextFor(sub), wide_, false); }
void ContactConstraints::push(const SubStep& sub) { kernels_->push(contextFor(sub), wide_); }
void ContactConstraints::restitution(const SubStep& sub) {
  // Most steps nothing approached fast enough to bounce: no walk through the
  // colours for it.
  if (wide_.bounceBundles.empty() && wide_.overflow.empty()) return;
  kernels_->restitution(contextFor(sub), wide_);
}
void ContactConstraints::store(WorldData& world) { kernels_->store(wide_, world); }

void ContactConstraints::countPasses(SolverPasses& passes) const {
  passes.contacts += static_cast<int>(refs_.size());
  passes.supportRows += static_cast<int>(support_.rows().size());
  passes.pushedContacts += wide_.pushedContacts;
  passes.quietContacts += wide_.quietContacts;
}

}  // namespace impulse
