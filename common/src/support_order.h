#pragma once
// Which contacts hold a body up, from the ground upwards: the order of the
// support pass (shock propagation).
//
// Soft Gauss-Seidel passes a load down a stack one contact per iteration,
// and a light body under a heavy one passes almost none of it: at 300:1 the
// heavy body sinks through. The support pass walks the supporting contacts
// bottom-up and, treating the lower body as immovable, stops every upper
// body from moving further into its support. The regular passes still carry
// the loads (their impulses are what the lower bodies feel and what
// friction is limited by); the support pass only removes the sinking they
// leave behind.

#include <cstdint>
#include <span>
#include <vector>

#include "contact_constraint.h"

namespace impulse {

struct WorldData;

/// A supporting contact: the index of its ConstraintRef, and whether the
/// upper body (the one held up) is the contact's body B.
struct SupportRow {
  std::int32_t ref = 0;
  bool upperIsB = false;
};

class SupportOrder {
 public:
  /// Levels every awake body by its contact distance from the static world
  /// (a box on the ground is 1, a box on it 2) and lists the contacts whose
  /// normal is within 60 degrees of up and whose upper body is a level above
  /// the lower one, lowest support first, marking those refs `holdsUp`.
  /// No gravity, no rows.
  void build(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount);
  std::span<const SupportRow> rows() const { return rows_; }
  /// Where each storey's rows start in rows(), and (last) their end.
  std::span<const std::int32_t> storeyStarts() const { return levelStart_; }

 private:
  void levelBodies(std::span<const ConstraintRef> refs, std::size_t stateCount);

  std::vector<std::int32_t> level_;
  std::vector<std::int32_t> edgeStart_;
  std::vector<std::int32_t> neighbours_;
  std::vector<std::int32_t> queue_;
  std::vector<SupportRow> unsorted_;
  std::vector<std::int32_t> rowLevel_;
  std::vector<std::int32_t> levelStart_;
  std::vector<SupportRow> rows_;
};

}  // namespace impulse
