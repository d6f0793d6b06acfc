#pragma once
// The support pass (shock propagation): holds each body up on what is
// under it, from the ground upwards.
//
// Soft Gauss-Seidel passes a load down a stack one contact per iteration,
// and a light body under a heavy one passes almost none of it: at 300:1 the
// heavy body sank through. After the soft rows of each sub-step, this pass
// walks the supporting contacts storey by storey from the ground and,
// treating the lower body as immovable, stops every upper body from moving
// into its support. The soft rows still carry the loads (their impulses are
// what the lower bodies feel); the support pass removes the sinking they
// leave behind, and its impulse raises the friction limit to the whole load.
// On the static world a row is a rigid contact: where friction holds its
// body sideways, the row also keeps its lift from making the points slip.
//
// A row lifts its upper body along the contact's normal and leaves the
// lower one as it is. Off level, that lift also pushes the upper body
// sideways, with nothing pushing the lower one back: run after the soft
// rows, it left each sub-step's slide to the next, and an arch's stones,
// leaning 7 to 23 degrees on each other, crept apart at 1 cm/s. The rows
// between two bodies that lean more than 5 degrees therefore run before the
// soft rows, whose friction then has the last word on how they slide; the
// others (flat ones, and all on the static world) after them.
//
// Only stacks that need it get rows. A soft contact holding a load L sinks
// by about L times its compliance, and a stack's top by the sum of those
// down the stack: a box on the ground sinks 0.07 mm, a 20-row pyramid's top
// 3 cm, a box under one 180 times heavier 3 cm. Each step the pass estimates
// that sink from the stack itself (every body's weight shared out over the
// bodies it stands on, down to the ground: stack height and mass ratio, or
// the load each contact carried last step where that is more) and keeps the
// rows of the stacks that would sink more than kSupportedSink (and every
// row on the static world).
//
// A body that no chain of level contacts joins to the ground, but steep
// contacts between moving bodies do (an arch's upper stones), is levelled
// through those, so that what stands level on it (four slabs on an arch's
// top, each on the one below) is held up storey by storey as any stack is:
// on their soft contacts alone the slabs sank 7.5 mm into each other and
// bounced as the arch took their load. Such a body hangs on its joints'
// friction and thrust, and moves along them while that thrust builds, so no
// row lifts off it: a row holds its lower body immovable, and rows lifting
// the slabs off the arch's top stones took the slabs' load off the
// keystone, and the arch crept apart at 2-4 mm/s. Not through a round
// shape's steep contacts: a circle in a pile's hollow rests where its
// contacts, all through its centre, put it, and rows on the circles found
// standing on such circles (most of a pile, most of them leaning) stirred
// the pile, which took a sixth longer to fall asleep.
//
// A hanging body's joints carry its weight only as the thrust that presses
// them builds. Built at rest (an arch), their contacts had nothing to warm
// start from: the arch's top fell almost freely in the first step and the
// stones beside the keystone slid 9.5 mm down their joints while the
// thrust built (Solver2D's arch: 1.3 cm). So a new contact that a hanging
// body leans on, touching and at rest, starts from the load the pass
// estimates for it (SupportPass::startImpulses), and the step that starts
// one takes kStartPasses more soft passes in its first sub-step, which
// settle the thrust (0.42 cm). Either alone does not: the start loads
// alone 1.25 cm, 30 more passes every sub-step alone 1.05 cm. Started on
// every body at rest, a pyramid under heavy boxes ended 4 cm from its
// place instead of 2.6, so a body that does not hang starts as before.

#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "contact_constraint.h"

namespace impulse {

struct WorldData;

/// Stacks whose soft contacts alone would let the top sink less than this
/// (m) leave the rows between their bodies to them (a box on another box,
/// circles on circles in a pile); three boxes in a column and anything
/// taller or heavier keep the pass. Rows on the static world always run.
inline constexpr Real kSupportedSink = Real(0.001);

/// Up: against gravity (zero without it).
Vec2 upwards(const Vec2& gravity);

// cos(25 degrees): a body stands on contacts this close to level. Steeper
// ones lean on their neighbour; among them the 30 degrees of circles packed
// in a pile, which lifting one-sidedly would keep stirring.
inline constexpr Real kMinUpwardNormal = Real(0.9);
// cos(5 degrees): a row between two bodies on a contact further off level
// than this leans, and runs before the soft rows (above).
inline constexpr Real kMinFlatNormal = Real(0.9962);
inline constexpr std::int8_t kFlat = 2;
// Start loads (SupportPass::estimateStartLoads). A contact closer to
// vertical than this (cos of its normal to up) carries no weight to start
// from (a box beside another on the ground).
inline constexpr Real kMinLeaningUpward = Real(0.05);
// A new contact's point within this gap (m) touches, and starts loaded...
inline constexpr Real kStartTouch = Real(0.0005);
// ... where its bodies meet or part slower than this (m/s): at rest.
inline constexpr Real kStartRestSpeed = Real(0.01);
// Soft passes added to the first sub-step of a step that started a hanging
// body's contact (a wedge built at rest: an arch's joints).
inline constexpr int kStartPasses = 5;

/// A contact of this normal is level enough to stand on (ConstraintRef::facing):
/// +1 with B above, -1 with A above, 0 not level; twice that when within
/// 5 degrees of level (flat: a row on it does not lean). Inline: the refs'
/// collection asks it of every contact every step.
inline std::int8_t facingOf(const Vec2& normal, const Vec2& up) {
  const Real upward = normal.dot(up);
  const std::int8_t side = upward >= kMinUpwardNormal ? 1 : upward <= -kMinUpwardNormal ? -1 : 0;
  return std::abs(upward) >= kMinFlatNormal ? std::int8_t(kFlat * side) : side;
}

/// One supporting contact: its ConstraintRef, which side holds the upper
/// body, and whether it leans (between two bodies, more than 5 degrees off
/// level).
struct SupportRow {
  std::int32_t ref = 0;
  bool upperIsB = false;
  bool leans = false;
};

/// Which of the pass's rows a run of it solves: the leaning ones, before
/// the soft rows of a sub-step, or the others, after them.
enum class SupportRows : std::uint8_t { Leaning, Standing };

/// Which contacts hold which bodies up, and in what order. The pass itself
/// runs on bundles of rows (the wide contact kernels, contact_solver_wide.h):
/// rows are grouped so that the rows of one group share no upper body, and
/// the lower bodies of a storey are never moved within it, so a group's rows
/// can be solved side by side with the same result at any lane width.
class SupportPass {
 public:
  /// Levels every awake body by its distance from the static world over
  /// level contacts (normal within 25 degrees of up: a box on the ground is
  /// 1, a box on it 2), then the bodies these leave unreached over any
  /// contact between two moving bodies but steep ones with a round shape
  /// (an arch's upper stones, leaning on each other, and the slabs on
  /// them); takes as rows the level contacts whose upper body is a level
  /// above the lower one and has no joints, and whose lower body was not
  /// reached over a steep contact, lowest storey
  /// first: those on the static world, and those of the stacks (bodies
  /// joined by such contacts) whose estimated sink under the soft contacts
  /// of `softness` reaches kSupportedSink;
  /// marks those refs `holdsUp`. Within a storey, a body's k-th row goes to
  /// the storey's k-th group. No gravity, no rows.
  ///
  /// The candidate rows (before the sink decides) depend only on the
  /// contacts, which of them are level and which way up, the awake bodies
  /// and which bodies are jointed, and the weight each body carries at rest
  /// on those and the bodies' masses: when none of these changed since the
  /// last step (a resting stack), last step's are kept, and only the sinks
  /// are estimated anew (from the loads the contacts carried last step).
  void order(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount,
             const ContactSoftness& softness, Real h);
  /// The rows, group by group.
  std::span<const SupportRow> rows() const { return rows_; }
  /// Group g holds rows [groupStarts()[g], groupStarts()[g + 1]).
  std::span<const std::int32_t> groupStarts() const { return groupStart_; }
  /// Storey s holds groups [storeyStarts()[s], storeyStarts()[s + 1]): the
  /// pass runs storey by storey from the ground up, each storey's groups
  /// backwards on alternate sub-steps (so no side is favoured).
  std::span<const std::int32_t> storeyStarts() const { return storeyGroupStart_; }
  /// How many of the rows lean (SupportRow::leans).
  int leaningRows() const { return leaningRows_; }
  /// Per ref, the normal impulse its touching points start from this step
  /// (estimateStartLoads): empty in a step that starts none, which is
  /// nearly every step of every world.
  std::span<const Real> startImpulses() const { return startImpulse_; }
  /// Extra soft passes the step's first sub-step takes: kStartPasses where
  /// a contact started from its estimated load this step, else none.
  int startPasses() const { return startImpulse_.empty() ? 0 : kStartPasses; }

 private:
  /// Compliance (impulseScale / (massScale * biasRate)) of the soft contacts
  /// against the static world and between bodies.
  struct Compliance {
    Real statics = 0;
    Real dynamic = 0;
  };

  bool sameGraphAsLastStep(const WorldData& world, std::span<const ConstraintRef> refs) const;
  void remember(const WorldData& world, std::span<const ConstraintRef> refs);
  void findCandidates(const WorldData& world, std::span<const ConstraintRef> refs, std::size_t stateCount);
  void linkBodies(std::span<const ConstraintRef> refs, std::size_t stateCount, std::span<const std::int32_t> joined);
  void walkLevels();
  void levelBodies(const WorldData& world, std::span<const ConstraintRef> refs, std::size_t stateCount);
  void groupStorey(std::span<const ConstraintRef> refs, std::size_t storey);
  void linkCandidates(std::span<const ConstraintRef> refs, std::size_t stateCount);
  void carryWeights(std::span<const ConstraintRef> refs);
  void estimateSinks(std::span<const ConstraintRef> refs);
  void keepStacksThatSink();
  bool markStartable(const WorldData& world, std::span<const ConstraintRef> refs);
  void estimateStartLoads(const WorldData& world, std::span<const ConstraintRef> refs);
  std::int32_t upperOf(const SupportRow& row, std::span<const ConstraintRef> refs) const;
  std::int32_t lowerOf(const SupportRow& row, std::span<const ConstraintRef> refs) const;

  Real weightPerMass_ = 0;  ///< g * h: a unit mass's weight per sub-step
  Compliance compliance_;
  /// What last step's candidates were built from (sameGraphAsLastStep).
  std::vector<ConstraintRef> lastRefs_;
  std::vector<std::int32_t> lastAwake_;
  std::uint64_t lastJointLinkChanges_ = 0;
  bool haveLast_ = false;
  std::vector<std::int32_t> level_;
  /// Per state: reached over a steep contact (levelBodies), so it hangs on
  /// its joints and holds no row up.
  std::vector<std::uint8_t> hangs_;
  /// Whether the second walk ran (some body may hang): only then are the
  /// refs marked (ConstraintRef::hangs).
  bool anyHangs_ = false;
  /// The level refs (ConstraintRef::facing not 0), by position.
  std::vector<std::int32_t> levelRefs_;
  std::vector<std::int32_t> edgeStart_;
  std::vector<std::int32_t> neighbours_;
  std::vector<std::uint8_t> steepEdge_;
  std::vector<std::int32_t> queue_;
  /// The refs the second walk may step over (levelBodies), by position.
  std::vector<std::int32_t> secondWalkRefs_;
  /// Fill positions of a counting sort (adjacency lists, storeys, groups).
  std::vector<std::int32_t> cursor_;
  std::vector<SupportRow> unsorted_;
  std::vector<std::int32_t> rowLevel_;
  /// By storey, then by group: rows sorted by storey, and each row's group.
  std::vector<SupportRow> byStorey_;
  /// Every row there could be, laid out as rows_ is (groups of storeys);
  /// kept while the graph stays the same.
  std::vector<SupportRow> candidates_;
  std::vector<std::int32_t> candidateGroupStart_;
  std::vector<std::int32_t> candidateStoreyStart_;
  std::vector<std::int32_t> rowGroup_;
  /// Per candidate (as candidates_): its upper and lower body's states and
  /// its stack (the root of the upper body's, union-find over stack_).
  struct CandidateLink {
    std::int32_t upper = 0;
    std::int32_t lower = 0;
    std::int32_t stack = 0;
  };
  std::vector<CandidateLink> candidateLinks_;
  /// Per state: rows seen so far in the storey being grouped, and which.
  std::vector<std::int32_t> upperRows_;
  std::vector<std::int32_t> upperStorey_;
  std::vector<std::int32_t> storeyStart_;
  /// Per state: the mass it carries (its own and its share of what stands
  /// on it), the rows it stands on, its estimated sink, and its stack
  /// (union-find, settled when the candidates are found) with, at the
  /// stack's root, the stack's deepest sink.
  std::vector<Real> carried_;
  std::vector<std::int32_t> supports_;
  std::vector<Real> sink_;
  std::vector<std::int32_t> stack_;
  std::vector<Real> stackSink_;
  /// New contacts' start loads (estimateStartLoads): the contacts a body
  /// stands or leans on, by its level, and per state the sum of their
  /// upward normals.
  struct Leaning {
    std::int32_t ref = 0;
    std::int32_t upper = 0;
    std::int32_t lower = 0;
    Real upward = 0;
    std::int32_t touching = 0;
  };
  std::vector<Leaning> leanings_;
  /// Per leaning, its upper body's depth below the top level, and the
  /// leanings in that order (countingSort).
  std::vector<std::int32_t> leaningDepth_;
  std::vector<std::int32_t> leaningOrder_;
  std::vector<Real> upwardSum_;
  std::vector<std::int32_t> standingPoints_;
  /// Per state, the mass it carries as carried_, counted over the leanings.
  std::vector<Real> startCarried_;
  /// Refs that may start but for being new, and per contact whether it
  /// was among last step's refs (markStartable).
  std::vector<std::int32_t> startCandidates_;
  std::vector<std::uint8_t> touchedLastStep_;
  /// Per ref: may start from an estimated load (markStartable).
  std::vector<std::uint8_t> startable_;
  std::vector<Real> startImpulse_;
  std::vector<SupportRow> rows_;
  int leaningRows_ = 0;
  std::vector<std::int32_t> groupStart_;
  std::vector<std::int32_t> storeyGroupStart_;
};

}  // namespace impulse
