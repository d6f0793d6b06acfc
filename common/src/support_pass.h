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

#include <cstdint>
#include <span>
#include <vector>

#include "contact_constraint.h"

namespace impulse {

struct WorldData;

/// One supporting contact: its ConstraintRef and which side holds the upper
/// body.
struct SupportRow {
  std::int32_t ref = 0;
  bool upperIsB = false;
};

/// Which contacts hold which bodies up, and in what order. The pass itself
/// runs on bundles of rows (the wide contact kernels, contact_solver_wide.h):
/// rows are grouped so that the rows of one group share no upper body, and
/// the lower bodies of a storey are never moved within it, so a group's rows
/// can be solved side by side with the same result at any lane width.
class SupportPass {
 public:
  /// Levels every awake body by its distance from the static world over
  /// level contacts (normal within 25 degrees of up: a box on the ground is
  /// 1, a box on it 2), and takes as rows the level contacts whose upper
  /// body is a level above the lower one and has no joints, lowest storey
  /// first; marks those refs `holdsUp`. Within a storey, a body's k-th row
  /// goes to the storey's k-th group. No gravity, no rows.
  ///
  /// The rows depend only on the contacts, which of them are level and
  /// which way up, the awake bodies and which bodies are jointed: when none
  /// of these changed since the last step (a resting stack), last step's
  /// rows are kept.
  void order(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount);
  /// The rows, group by group.
  std::span<const SupportRow> rows() const { return rows_; }
  /// Group g holds rows [groupStarts()[g], groupStarts()[g + 1]).
  std::span<const std::int32_t> groupStarts() const { return groupStart_; }
  /// Storey s holds groups [storeyStarts()[s], storeyStarts()[s + 1]): the
  /// pass runs storey by storey from the ground up, each storey's groups
  /// backwards on alternate sub-steps (so no side is favoured).
  std::span<const std::int32_t> storeyStarts() const { return storeyGroupStart_; }

 private:
  void classifyContacts(const WorldData& world, std::span<const ConstraintRef> refs);
  bool sameGraphAsLastStep(const WorldData& world, std::span<const ConstraintRef> refs) const;
  void remember(const WorldData& world, std::span<const ConstraintRef> refs);
  void levelBodies(std::span<const ConstraintRef> refs, std::size_t stateCount);
  void groupStorey(std::span<const ConstraintRef> refs, std::size_t storey);

  /// By ref: +1 level with B above, -1 level with A above, 0 not level.
  std::vector<std::int8_t> facing_;
  /// What last step's rows were built from (sameGraphAsLastStep).
  std::vector<ConstraintRef> lastRefs_;
  std::vector<std::int8_t> lastFacing_;
  std::vector<std::int32_t> lastAwake_;
  std::uint64_t lastJointLinkChanges_ = 0;
  bool haveLast_ = false;
  std::vector<std::int32_t> level_;
  std::vector<std::int32_t> edgeStart_;
  std::vector<std::int32_t> neighbours_;
  std::vector<std::int32_t> queue_;
  /// Fill positions of a counting sort (adjacency lists, storeys, groups).
  std::vector<std::int32_t> cursor_;
  std::vector<SupportRow> unsorted_;
  std::vector<std::int32_t> rowLevel_;
  /// By storey, then by group: rows sorted by storey, and each row's group.
  std::vector<SupportRow> byStorey_;
  std::vector<std::int32_t> rowGroup_;
  /// Per state: rows seen so far in the storey being grouped, and which.
  std::vector<std::int32_t> upperRows_;
  std::vector<std::int32_t> upperStorey_;
  std::vector<std::int32_t> storeyStart_;
  std::vector<SupportRow> rows_;
  std::vector<std::int32_t> groupStart_;
  std::vector<std::int32_t> storeyGroupStart_;
};

}  // namespace impulse
