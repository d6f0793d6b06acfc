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

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "contact_constraint.h"

namespace impulse {

struct WorldData;

/// One supporting contact, with what the pass needs of its constraint.
struct SupportRow {
  struct Point {
    Vec2 anchorA = Vec2::Zero();
    Vec2 anchorB = Vec2::Zero();
    Real baseSeparation = 0;
    /// The upper body's lever arm about the normal; 0 for a missing point.
    Real arm = 0;
    bool present = false;
  };
  std::int32_t ref = 0;  ///< its ConstraintRef
  std::int32_t stateA = 0;
  std::int32_t stateB = 0;
  bool upperIsB = false;
  Vec2 normal = Vec2::Zero();
  Real invMass = 0;  ///< the upper body's
  Real invInertia = 0;
  std::array<Point, 2> points{};
  /// The upper body's response K (impulse to normal speed) at the points,
  /// inverted once per step: both points together (inverse of K, zero when
  /// singular), and each alone (1 / K_jj).
  Real pairInverse11 = 0, pairInverse12 = 0, pairInverse22 = 0;
  std::array<Real, 2> singleMass{0, 0};
  Real k12 = 0;
  /// The pass's impulse per point in the last sub-step.
  std::array<Real, 2> impulse{0, 0};
};

class SupportPass {
 public:
  /// Levels every awake body by its distance from the static world over
  /// level contacts (normal within 25 degrees of up: a box on the ground is
  /// 1, a box on it 2), and takes as rows the level contacts whose upper
  /// body is a level above the lower one and has no joints, lowest storey
  /// first; marks those refs `holdsUp`. No gravity, no rows.
  void order(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount);
  std::span<const SupportRow> rows() const { return rows_; }
  /// Takes a row's geometry from its prepared constraint.
  void load(std::size_t row, const ContactConstraint& constraint);
  /// The pass: storey by storey from the ground up, each storey backwards
  /// when `reverse` (alternate sub-steps, so no side is favoured).
  void solve(std::span<SolverState> states, Real inverseSubStep, bool reverse);
  /// Writes the last impulses into the manifolds (for friction next step).
  void store(WorldData& world, std::span<const ConstraintRef> refs) const;

 private:
  void levelBodies(std::span<const ConstraintRef> refs, std::size_t stateCount);

  std::vector<Real> upward_;  ///< by ref: the normal's share of up
  std::vector<std::int32_t> level_;
  std::vector<std::int32_t> edgeStart_;
  std::vector<std::int32_t> neighbours_;
  std::vector<std::int32_t> queue_;
  /// Fill positions of a counting sort (adjacency lists, then storeys).
  std::vector<std::int32_t> cursor_;
  std::vector<SupportRow> unsorted_;
  std::vector<std::int32_t> rowLevel_;
  std::vector<std::int32_t> storeyStart_;
  std::vector<SupportRow> rows_;
};

}  // namespace impulse
