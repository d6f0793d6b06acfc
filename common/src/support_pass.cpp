#include "support_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "counting_sort.h"
#include "prefetch.h"
#include "union_find.h"
#include "world_data.h"

namespace impulse {

namespace {

constexpr std::int32_t kUnreached = -1;

// A row's upper and lower body's inverse masses, as its ref carries them.
Real upperInvMass(const SupportRow& row, const ConstraintRef& ref) {
  return row.upperIsB ? ref.invMassB : ref.invMassA;
}

Real lowerInvMass(const SupportRow& row, const ConstraintRef& ref) {
  return row.upperIsB ? ref.invMassA : ref.invMassB;
}

Real massOf(Real invMass) { return invMass > 0 ? 1 / invMass : Real(0); }

// A soft contact at rest overlaps by impulseScale * L / (massScale *
// biasRate * normal mass) for a load L per sub-step (overlapForLoad in
// contact_solver.cpp). Without a bias rate nothing pushes back: the sink
// has no bound.
Real complianceOf(const Softness& softness) {
  if (softness.biasRate <= 0) return std::numeric_limits<Real>::infinity();
  return softness.impulseScale / (softness.massScale * softness.biasRate);
}

// How many of a new contact's points touch (within kStartTouch), or none
// unless its bodies rest against each other there (meet or part along the
// normal slower than kStartRestSpeed): a contact made as a body lands takes
// the load it meets.
int pointsAtRest(const WorldData& world, const ConstraintRef& ref, const Manifold& manifold) {
  const SolverState& a = world.solverStates[std::size_t(ref.stateA)];
  const SolverState& b = world.solverStates[std::size_t(ref.stateB)];
  int touching = 0;
  for (int j = 0; j < manifold.pointCount; ++j) {
    const ManifoldPoint& point = manifold.points[j];
    if (point.separation > kStartTouch) continue;
    const Vec2 relative = b.linearVelocity + cross(b.angularVelocity, point.anchorB) - a.linearVelocity -
                          cross(a.angularVelocity, point.anchorA);
    if (std::abs(relative.dot(manifold.normal)) > kStartRestSpeed) return 0;
    ++touching;
  }
  return touching;
}

}  // namespace

Vec2 upwards(const Vec2& gravity) {
  return gravity.squaredNorm() > 0 ? Vec2(-gravity.normalized()) : Vec2::Zero();
}

// Adjacency lists in one array (counted, then filled) over the contacts
// `joined` lists (by position in refs), each edge marked steep where its
// contact is not level.
void SupportPass::linkBodies(std::span<const ConstraintRef> refs, std::size_t stateCount,
                             std::span<const std::int32_t> joined) {
  edgeStart_.assign(stateCount + 1, 0);
  for (const std::int32_t i : joined) {
    ++edgeStart_[std::size_t(refs[std::size_t(i)].stateA) + 1];
    ++edgeStart_[std::size_t(refs[std::size_t(i)].stateB) + 1];
  }
  for (std::size_t s = 1; s <= stateCount; ++s) edgeStart_[s] += edgeStart_[s - 1];
  neighbours_.resize(std::size_t(edgeStart_[stateCount]));
  steepEdge_.resize(neighbours_.size());
  cursor_.assign(edgeStart_.begin(), edgeStart_.end() - 1);
  for (const std::int32_t i : joined) {
    const ConstraintRef& ref = refs[std::size_t(i)];
    for (const auto& [from, to] : {std::pair{ref.stateA, ref.stateB}, std::pair{ref.stateB, ref.stateA}}) {
      const std::size_t edge = std::size_t(cursor_[std::size_t(from)]++);
      neighbours_[edge] = to;
      steepEdge_[edge] = ref.facing == 0 ? 1 : 0;
    }
  }
}

// Breadth-first over the linked bodies from the queue's bodies on: each
// body reached a level above the one it was reached from, hanging when
// reached over a steep contact.
void SupportPass::walkLevels() {
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const std::int32_t state = queue_[head];
    for (std::int32_t e = edgeStart_[std::size_t(state)]; e < edgeStart_[std::size_t(state) + 1]; ++e) {
      const std::int32_t next = neighbours_[std::size_t(e)];
      if (level_[std::size_t(next)] != kUnreached) continue;
      level_[std::size_t(next)] = level_[std::size_t(state)] + 1;
      hangs_[std::size_t(next)] = steepEdge_[std::size_t(e)];
      queue_.push_back(next);
    }
  }
}

// Refs ahead of the one whose contact's roundness is read (levelBodies): a
// ref takes a few nanoseconds, a miss over a hundred (at 16 ahead, most
// reads still waited).
constexpr std::size_t kRoundnessAhead = 64;

// From the static dummy (state 0) over the level contacts
// (ConstraintRef::facing) first: a column of circles against a wall touches
// the static world at every storey, yet stands on the ground alone. Then,
// where some are left unreached, over the steep contacts between two moving
// bodies too, but those with a round shape (support_pass.h says why).
void SupportPass::levelBodies(const WorldData& world, std::span<const ConstraintRef> refs, std::size_t stateCount) {
  listWhere(refs.size(), [&](std::size_t i) { return refs[i].facing != 0; }, levelRefs_);
  linkBodies(refs, stateCount, levelRefs_);
  level_.assign(stateCount, kUnreached);
  hangs_.assign(stateCount, 0);
  level_[0] = 0;
  queue_.assign(1, 0);
  walkLevels();
  const auto unreached = [&](std::int32_t state) { return level_[std::size_t(state)] == kUnreached; };
  // Every level contact now joins two reached bodies or two unreached ones,
  // and only the latter can become rows through the second walk: without
  // one (a crowd tumbling in a drum) the walk would change no row.
  const bool levelContactLeft = std::any_of(levelRefs_.begin(), levelRefs_.end(), [&](std::int32_t i) {
    return unreached(refs[std::size_t(i)].stateA) && unreached(refs[std::size_t(i)].stateB);
  });
  if (!levelContactLeft) return;
  // Whether a contact's shapes are round is read off the contact, and only
  // for a steep contact between moving bodies that reaches an unreached
  // one: the refs of every step leave it out, a cache line of each contact.
  // In a tumbling pile that line is a miss for most contacts (two fifths of
  // this function's time): both loops below ask for it some refs ahead.
  const auto fetchRoundnessAhead = [&](std::size_t i) {
    if (i + kRoundnessAhead < refs.size()) fetchLines(&world.contacts[refs[i + kRoundnessAhead].contact].rolls);
  };
  const auto betweenMovingAngularShapes = [&](const ConstraintRef& ref) {
    return ref.stateA != 0 && ref.stateB != 0 && !world.contacts[ref.contact].rolls;
  };
  bool bridged = false;
  for (std::size_t i = 0; i < refs.size() && !bridged; ++i) {
    fetchRoundnessAhead(i);
    const ConstraintRef& ref = refs[i];
    bridged = unreached(ref.stateA) != unreached(ref.stateB) && betweenMovingAngularShapes(ref);
  }
  if (!bridged) return;
  // The walk goes over the reached bodies again, but can only step to
  // unreached ones: the contacts between two reached bodies are left out
  // (levels the same; in a tumbling pile most of its contacts, whose
  // shapes would be read to tell whether they are round).
  const auto secondWalkLinks = [&](std::size_t i) {
    fetchRoundnessAhead(i);
    const ConstraintRef& ref = refs[i];
    return (unreached(ref.stateA) || unreached(ref.stateB)) && (ref.facing != 0 || betweenMovingAngularShapes(ref));
  };
  listWhere(refs.size(), secondWalkLinks, secondWalkRefs_);
  linkBodies(refs, stateCount, secondWalkRefs_);
  walkLevels();
  anyHangs_ = true;
}

bool SupportPass::sameGraphAsLastStep(const WorldData& world, std::span<const ConstraintRef> refs) const {
  auto sameRef = [](const ConstraintRef& a, const ConstraintRef& b) {
    return a.contact == b.contact && a.stateA == b.stateA && a.stateB == b.stateB && a.facing == b.facing &&
           a.invMassA == b.invMassA && a.invMassB == b.invMassB;
  };
  return haveLast_ && world.jointLinkChanges == lastJointLinkChanges_ &&
         world.awakeBodies == lastAwake_ && std::equal(refs.begin(), refs.end(), lastRefs_.begin(), lastRefs_.end(), sameRef);
}

void SupportPass::remember(const WorldData& world, std::span<const ConstraintRef> refs) {
  lastRefs_.assign(refs.begin(), refs.end());
  lastAwake_ = world.awakeBodies;
  lastJointLinkChanges_ = world.jointLinkChanges;
  haveLast_ = true;
}

std::int32_t SupportPass::upperOf(const SupportRow& row, std::span<const ConstraintRef> refs) const {
  const ConstraintRef& ref = refs[std::size_t(row.ref)];
  return row.upperIsB ? ref.stateB : ref.stateA;
}

std::int32_t SupportPass::lowerOf(const SupportRow& row, std::span<const ConstraintRef> refs) const {
  const ConstraintRef& ref = refs[std::size_t(row.ref)];
  return row.upperIsB ? ref.stateA : ref.stateB;
}

// The load of a row (impulse per sub-step) is the larger of two: its share
// of what its upper body carries at rest (its own weight and its shares of
// the bodies on it, shared equally over the rows it stands on, top storey
// first), and what the contact carried last step, which also counts what
// reaches it over contacts too steep to be rows (a pile of circles on its
// bottom row). Each body sinks by the deepest of its supports' sinks plus
// the soft contact's under that load (ground first): load times the pair's
// inverse mass times the contact's compliance. An estimate within a small
// factor: the points' lever arms and the load's true spread are left out.
//
// What each body carries at rest depends on the candidates and the bodies'
// masses alone: worked out when the candidates are found, it holds while
// the graph does (sameGraphAsLastStep compares the masses too).
void SupportPass::carryWeights(std::span<const ConstraintRef> refs) {
  const std::size_t stateCount = level_.size();
  carried_.assign(stateCount, 0);
  supports_.assign(stateCount, 0);
  for (std::size_t r = 0; r < candidates_.size(); ++r) {
    const SupportRow& row = candidates_[r];
    const CandidateLink& link = candidateLinks_[r];
    const ConstraintRef& ref = refs[std::size_t(row.ref)];
    carried_[std::size_t(link.upper)] = massOf(upperInvMass(row, ref));
    carried_[std::size_t(link.lower)] = massOf(lowerInvMass(row, ref));
    ++supports_[std::size_t(link.upper)];
  }
  for (auto link = candidateLinks_.rbegin(); link != candidateLinks_.rend(); ++link) {
    carried_[std::size_t(link->lower)] += carried_[std::size_t(link->upper)] / Real(supports_[std::size_t(link->upper)]);
  }
}

void SupportPass::estimateSinks(std::span<const ConstraintRef> refs) {
  sink_.assign(level_.size(), 0);
  for (std::size_t r = 0; r < candidates_.size(); ++r) {
    const SupportRow& row = candidates_[r];
    const CandidateLink& link = candidateLinks_[r];
    const ConstraintRef& ref = refs[std::size_t(row.ref)];
    const Real atRest = weightPerMass_ * carried_[std::size_t(link.upper)] / Real(supports_[std::size_t(link.upper)]);
    const Real load = std::max(atRest, ref.lastLoad);
    const Real compliance = link.lower == 0 ? compliance_.statics : compliance_.dynamic;
    const Real soft = compliance * load * (lowerInvMass(row, ref) + upperInvMass(row, ref));
    sink_[std::size_t(link.upper)] = std::max(sink_[std::size_t(link.upper)], sink_[std::size_t(link.lower)] + soft);
  }
}

// Rows on the static world are always kept: a body standing alone sinks
// little (0.07 mm) but keeps that overlap when something heavy lands on it.
// Rows between bodies are kept with their stack, the bodies the candidate
// rows join above the ground. Dropping rows leaves each group's rows
// lifting distinct bodies; groups left empty are dropped.
void SupportPass::keepStacksThatSink() {
  stackSink_.assign(level_.size(), 0);
  for (const CandidateLink& link : candidateLinks_) {
    Real& deepest = stackSink_[std::size_t(link.stack)];
    deepest = std::max(deepest, sink_[std::size_t(link.upper)]);
  }
  auto keeps = [&](std::int32_t r) {
    const CandidateLink& link = candidateLinks_[std::size_t(r)];
    return link.lower == 0 || stackSink_[std::size_t(link.stack)] >= kSupportedSink;
  };
  rows_.clear();
  leaningRows_ = 0;
  groupStart_.assign(1, 0);
  storeyGroupStart_.assign(1, 0);
  for (std::size_t storey = 0; storey + 1 < candidateStoreyStart_.size(); ++storey) {
    for (std::int32_t group = candidateStoreyStart_[storey]; group < candidateStoreyStart_[storey + 1]; ++group) {
      for (std::int32_t r = candidateGroupStart_[std::size_t(group)]; r < candidateGroupStart_[std::size_t(group) + 1]; ++r) {
        if (!keeps(r)) continue;
        const SupportRow& row = candidates_[std::size_t(r)];
        rows_.push_back(row);
        leaningRows_ += row.leans ? 1 : 0;
      }
      if (std::int32_t(rows_.size()) > groupStart_.back()) groupStart_.push_back(std::int32_t(rows_.size()));
    }
    storeyGroupStart_.push_back(std::int32_t(groupStart_.size() - 1));
  }
}

// Marks the refs that may start (startable_): of those of a hanging body
// that carried nothing last step (startCandidates_, order), those at rest
// and new (not among last step's refs: a contact that carried nothing then
// is left as it is). Returns whether any may. Last step's refs are read
// only where some candidate is at rest.
bool SupportPass::markStartable(const WorldData& world, std::span<const ConstraintRef> refs) {
  const auto restless = [&](std::int32_t i) {
    const ConstraintRef& ref = refs[std::size_t(i)];
    return pointsAtRest(world, ref, world.contacts[ref.contact].manifold) == 0;
  };
  startCandidates_.erase(std::remove_if(startCandidates_.begin(), startCandidates_.end(), restless),
                         startCandidates_.end());
  if (startCandidates_.empty()) return false;
  // All zero between calls; a contact of last step's beyond the world's
  // (should they have shrunk) cannot be one of this step's.
  touchedLastStep_.resize(std::max(touchedLastStep_.size(), world.contacts.size()), 0);
  const auto markLastStep = [&](std::uint8_t mark) {
    if (!haveLast_) return;
    for (const ConstraintRef& ref : lastRefs_) {
      if (std::size_t(ref.contact) < touchedLastStep_.size()) touchedLastStep_[std::size_t(ref.contact)] = mark;
    }
  };
  markLastStep(1);
  startable_.assign(refs.size(), 0);
  bool any = false;
  for (const std::int32_t i : startCandidates_) {
    if (touchedLastStep_[std::size_t(refs[std::size_t(i)].contact)] != 0) continue;
    startable_[std::size_t(i)] = 1;
    any = true;
  }
  markLastStep(0);
  return any;
}

// A new contact's start load: the weight its upper body leans on it with,
// each body's carried mass (its own and its shares of the bodies leaning
// on it, top level first) shared over the contacts it leans on by their
// upward normals, and the normal impulse that holds that share up with the
// friction's help: share / (up . n + friction * |up . t|).
// Only a hanging body's contacts start (support_pass.h), and only where
// the body stands on two points or more: on one (a card on its corner) the
// load would spin it.
void SupportPass::estimateStartLoads(const WorldData& world, std::span<const ConstraintRef> refs) {
  if (!markStartable(world, refs)) return;
  const Vec2 up = upwards(world.settings.gravity);
  const std::size_t stateCount = level_.size();
  leanings_.clear();
  upwardSum_.assign(stateCount, 0);
  standingPoints_.assign(stateCount, 0);
  startCarried_.assign(stateCount, 0);
  std::int32_t topLevel = 0;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const ConstraintRef& ref = refs[i];
    if (ref.jointed()) continue;
    const Manifold& manifold = world.contacts[ref.contact].manifold;
    const Real upward = manifold.normal.dot(up);
    const bool upperIsB = upward > 0;
    const std::int32_t upper = upperIsB ? ref.stateB : ref.stateA;
    const std::int32_t lower = upperIsB ? ref.stateA : ref.stateB;
    if (std::abs(upward) < kMinLeaningUpward || upper == 0) continue;
    const std::int32_t upperLevel = level_[std::size_t(upper)];
    if (upperLevel == kUnreached || level_[std::size_t(lower)] == kUnreached || upperLevel <= level_[std::size_t(lower)])
      continue;
    const std::int32_t touching = pointsAtRest(world, ref, manifold);
    if (touching == 0) continue;
    leanings_.push_back({std::int32_t(i), upper, lower, std::abs(upward), touching});
    upwardSum_[std::size_t(upper)] += std::abs(upward);
    standingPoints_[std::size_t(upper)] += touching;
    startCarried_[std::size_t(upper)] = massOf(upperIsB ? ref.invMassB : ref.invMassA);
    if (lower != 0) startCarried_[std::size_t(lower)] = massOf(upperIsB ? ref.invMassA : ref.invMassB);
    topLevel = std::max(topLevel, upperLevel);
  }
  // Top level first.
  leaningDepth_.clear();
  for (const Leaning& l : leanings_) leaningDepth_.push_back(topLevel - level_[std::size_t(l.upper)]);
  storeyStart_.resize(std::size_t(topLevel) + 2);
  countingSort(leaningDepth_, storeyStart_, leaningOrder_);
  for (const std::int32_t k : leaningOrder_) {
    const Leaning& l = leanings_[std::size_t(k)];
    const Real share = startCarried_[std::size_t(l.upper)] * l.upward / upwardSum_[std::size_t(l.upper)];
    if (l.lower != 0) startCarried_[std::size_t(l.lower)] += share;
    if (startable_[std::size_t(l.ref)] == 0 || hangs_[std::size_t(l.upper)] == 0 || standingPoints_[std::size_t(l.upper)] < 2)
      continue;
    const ContactSolverPart& contact = world.contacts[refs[std::size_t(l.ref)].contact];
    const Real across = std::sqrt(std::max(Real(1) - l.upward * l.upward, Real(0)));
    const Real normal = weightPerMass_ * share / (l.upward + contact.staticFriction * across);
    if (startImpulse_.empty()) startImpulse_.assign(refs.size(), 0);
    startImpulse_[std::size_t(l.ref)] = normal / Real(l.touching);
  }
}

void SupportPass::order(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount,
                        const ContactSoftness& softness, Real h) {
  rows_.clear();
  leaningRows_ = 0;
  groupStart_.assign(1, 0);
  storeyGroupStart_.assign(1, 0);
  if (refs.empty() || world.settings.gravity.squaredNorm() == 0) {
    haveLast_ = false;
    return;
  }
  weightPerMass_ = world.settings.gravity.norm() * h;
  compliance_ = {complianceOf(softness.statics), complianceOf(softness.dynamic)};
  startImpulse_.clear();
  const bool graphChanged = !sameGraphAsLastStep(world, refs);
  if (graphChanged) {
    findCandidates(world, refs, stateCount);
    carryWeights(refs);
  }
  estimateSinks(refs);
  keepStacksThatSink();
  for (const SupportRow& row : rows_) refs[std::size_t(row.ref)].holdsUp = true;
  if (anyHangs_) {
    // Without a branch: in a crowd, whether a body hangs is a coin toss.
    for (ConstraintRef& ref : refs) {
      ref.hangs = (hangs_[std::size_t(ref.stateA)] | hangs_[std::size_t(ref.stateB)]) != 0;
    }
    listWhere(
        refs.size(),
        [&](std::size_t i) {
          return (int(refs[i].hangs) & int(refs[i].touchesUnloaded) & int(!refs[i].jointed())) != 0;
        },
        startCandidates_);
    // New contacts change the graph.
    if (graphChanged) estimateStartLoads(world, refs);
  }
  if (graphChanged) remember(world, refs);
}

void SupportPass::findCandidates(const WorldData& world, std::span<const ConstraintRef> refs,
                                 std::size_t stateCount) {
  candidates_.clear();
  candidateGroupStart_.assign(1, 0);
  candidateStoreyStart_.assign(1, 0);
  candidateLinks_.clear();
  anyHangs_ = false;
  // Levels count up from the static world: with no level contact on it (a
  // pile in a kinematic drum), no body has one and nothing is a candidate.
  // Nor where no moving body is free of joints (a pile of ragdolls): a
  // row's upper body is a free one (ConstraintRef::freeA, freeB), and the
  // levels of bodies that never stand on a row would be walked for nothing.
  const bool standsOnStatic = std::any_of(refs.begin(), refs.end(), [](const ConstraintRef& ref) {
    return ref.facing != 0 && (ref.stateA == 0 || ref.stateB == 0);
  });
  const bool anyFreeBody =
      std::any_of(refs.begin(), refs.end(), [](const ConstraintRef& ref) { return ref.freeA() || ref.freeB(); });
  if (!standsOnStatic || !anyFreeBody) {
    level_.assign(stateCount, kUnreached);
    return;
  }
  levelBodies(world, refs, stateCount);

  unsorted_.clear();
  rowLevel_.clear();
  std::int32_t topLevel = 0;
  for (const std::int32_t i : levelRefs_) {
    const ConstraintRef& ref = refs[std::size_t(i)];
    const bool upperIsB = ref.facing > 0;
    std::int32_t lower = level_[std::size_t(upperIsB ? ref.stateA : ref.stateB)];
    std::int32_t upper = level_[std::size_t(upperIsB ? ref.stateB : ref.stateA)];
    if (lower == kUnreached || upper <= lower || hangs_[std::size_t(upperIsB ? ref.stateA : ref.stateB)] != 0 ||
        !(upperIsB ? ref.freeB() : ref.freeA())) {
      continue;
    }
    SupportRow row;
    row.ref = i;
    row.upperIsB = upperIsB;
    row.leans = lower > 0 && std::abs(ref.facing) != kFlat;
    unsorted_.push_back(row);
    rowLevel_.push_back(lower);
    topLevel = std::max(topLevel, lower);
  }
  // Counting sort by the lower body's level, stable: the ground's contacts
  // first, then each storey in contact order.
  storeyStart_.assign(std::size_t(topLevel) + 2, 0);
  for (std::int32_t level : rowLevel_) ++storeyStart_[std::size_t(level) + 1];
  for (std::size_t l = 1; l < storeyStart_.size(); ++l) storeyStart_[l] += storeyStart_[l - 1];
  byStorey_.resize(unsorted_.size());
  cursor_.assign(storeyStart_.begin(), storeyStart_.end() - 1);
  for (std::size_t r = 0; r < unsorted_.size(); ++r) {
    byStorey_[std::size_t(cursor_[std::size_t(rowLevel_[r])]++)] = unsorted_[r];
  }
  candidates_.resize(byStorey_.size());
  rowGroup_.resize(byStorey_.size());
  upperStorey_.assign(stateCount, -1);
  upperRows_.resize(stateCount);
  for (std::size_t storey = 0; storey + 1 < storeyStart_.size(); ++storey) {
    groupStorey(refs, storey);
  }
  linkCandidates(refs, stateCount);
}

// Each candidate's bodies and stack (the bodies the candidate rows join
// above the ground, by union-find): they change only with the graph, so a
// resting stack's steps read them instead of walking the refs and the
// union-find again.
void SupportPass::linkCandidates(std::span<const ConstraintRef> refs, std::size_t stateCount) {
  candidateLinks_.resize(candidates_.size());
  stack_.resize(stateCount);
  for (std::size_t s = 0; s < stateCount; ++s) stack_[s] = std::int32_t(s);
  for (std::size_t r = 0; r < candidates_.size(); ++r) {
    CandidateLink& link = candidateLinks_[r];
    link.upper = upperOf(candidates_[r], refs);
    link.lower = lowerOf(candidates_[r], refs);
    if (link.lower == 0) continue;
    stack_[std::size_t(unionFindRoot(stack_, link.upper))] = unionFindRoot(stack_, link.lower);
  }
  for (CandidateLink& link : candidateLinks_) link.stack = unionFindRoot(stack_, link.upper);
}

// A body's k-th row in the storey goes to group k; the groups are then laid
// out in order (a stable counting sort), each keeping contact order.
void SupportPass::groupStorey(std::span<const ConstraintRef> refs, std::size_t storey) {
  const std::size_t first = std::size_t(storeyStart_[storey]);
  const std::size_t end = std::size_t(storeyStart_[storey + 1]);
  std::int32_t groups = 0;
  for (std::size_t r = first; r < end; ++r) {
    const ConstraintRef& ref = refs[std::size_t(byStorey_[r].ref)];
    const std::size_t upper = std::size_t(byStorey_[r].upperIsB ? ref.stateB : ref.stateA);
    if (upperStorey_[upper] != std::int32_t(storey)) {
      upperStorey_[upper] = std::int32_t(storey);
      upperRows_[upper] = 0;
    }
    rowGroup_[r] = upperRows_[upper]++;
    groups = std::max(groups, rowGroup_[r] + 1);
  }
  const std::size_t base = candidateGroupStart_.size() - 1;  // the storey's first group
  candidateGroupStart_.resize(base + std::size_t(groups) + 1, 0);
  for (std::size_t r = first; r < end; ++r) ++candidateGroupStart_[base + std::size_t(rowGroup_[r]) + 1];
  for (std::size_t g = base + 1; g < candidateGroupStart_.size(); ++g) candidateGroupStart_[g] += candidateGroupStart_[g - 1];
  cursor_.assign(candidateGroupStart_.begin() + std::ptrdiff_t(base), candidateGroupStart_.end() - 1);
  for (std::size_t r = first; r < end; ++r) {
    candidates_[std::size_t(cursor_[std::size_t(rowGroup_[r])]++)] = byStorey_[r];
  }
  candidateStoreyStart_.push_back(std::int32_t(candidateGroupStart_.size() - 1));
}

}  // namespace impulse
