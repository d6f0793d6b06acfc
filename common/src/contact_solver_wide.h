#pragma once
// The contact solver four (SSE2) or eight (AVX2) constraints at a time.
// Constraints are coloured so that no two of one colour share a dynamic body;
// each colour is cut into bundles of four or eight, whose lanes can then be
// solved together without one lane overwriting another's body. Constraints that find no free colour
// stay in an overflow list solved one by one (contact_solver.h).

#include <span>

#include "contact_solver.h"
#include "graph_coloring.h"
#include "joint_pins.h"
#include "support_pass.h"

namespace impulse {

/// The passes at one lane width. Every width gives bit-identical results:
/// lanes of one colour share no body, and each lane's arithmetic is the same.
struct WideContactKernels {
  int lanes;
  /// Prepares each of the touching contacts `refs`, coloured
  /// (WideContactSet::colorStart), straight into its bundle lane (or the
  /// overflow list), and each of the support pass's rows into its support
  /// lane from its prepared contact (support_pass.h). Returns whether any
  /// contact overlaps deeper than its load explains (the push pass is
  /// needed), and then joins the contacts' islands and chooses the push
  /// pass's contacts: those of the islands where one does.
  bool (*build)(const WorldData& world, std::span<const ConstraintRef> refs, const ContactSoftness& softness,
                const SupportPass& support, WideContactSet& set);
  void (*warmStart)(const ContactSolverContext& context, WideContactSet& set);
  void (*solve)(const ContactSolverContext& context, WideContactSet& set, bool useBias);
  /// The push pass (pushOverlap) on the contacts of the islands where one
  /// intruded when built (WideContactSet::pushBundles).
  void (*push)(const ContactSolverContext& context, WideContactSet& set);
  /// The support pass's `rows` of one sub-step, storey by storey from the
  /// ground.
  void (*solveSupport)(const ContactSolverContext& context, WideContactSet& set,
                       const SupportPass& pass, SupportRows rows);
  void (*restitution)(const ContactSolverContext& context, WideContactSet& set);
  /// Writes the impulses back into the manifolds for next step's warm start
  /// (the support pass's last, for next step's friction limit).
  void (*store)(WideContactSet& set, WorldData& world);
  /// The plain pins' warm start and one pass, biased or relaxing as
  /// `softness` says, on `blocks` (joint_pins.h); kept in this table to share
  /// its bodies' gather and scatter and its choice of width.
  void (*warmStartPins)(std::span<SolverState> states, std::span<PinBlock> blocks);
  void (*solvePins)(std::span<SolverState> states, std::span<PinBlock> blocks,
                    const Softness& softness);
  /// The same for the plain pins of the tree pass (joint_pins.h), whose
  /// impulses stay in `rows`; the pass is a relax (`softness`).
  void (*warmStartTreePins)(std::span<SolverState> states, std::span<TreePinBlock> blocks,
                            std::span<JointRow> rows);
  void (*solveTreePins)(std::span<SolverState> states, std::span<TreePinBlock> blocks,
                        std::span<JointRow> rows, const Softness& softness);
  /// The same for revolute joints with a limit, motor or spring (joint_pins.h),
  /// whose pins' impulses stay in `rows` (the tree pass's); a pass of `pass`.
  void (*warmStartRevolutes)(std::span<SolverState> states, std::span<RevoluteBlock> blocks,
                             std::span<JointRow> rows);
  void (*solveRevolutes)(std::span<SolverState> states, std::span<RevoluteBlock> blocks,
                         std::span<JointRow> rows, const JointPass& pass);
  /// Moves each of `states` by its velocity over a sub-step of `h`
  /// (integrateRotation, math.h, and the delta position's step), the same
  /// bit for bit; returns how many from the first it did (whole bundles),
  /// leaving the rest to the caller.
  std::size_t (*integratePositions)(std::span<SolverState> states, float h);
};

/// The bundle list of width F in a set (defined by the file of that width).
template <class F>
std::vector<WideConstraint<F>>& bundlesOf(WideContactSet& set);
/// Their cold parts, one per bundle (likewise).
template <class F>
std::vector<WideContactCold<F>>& coldPartsOf(WideContactSet& set);
/// The support bundle list of width F in a set (likewise).
template <class F>
std::vector<WideSupportRow<F>>& supportBundlesOf(WideContactSet& set);

const WideContactKernels& sse2WideContactKernels();  // contact_solver_wide_sse2.cpp
const WideContactKernels& avx2WideContactKernels();  // contact_solver_wide_avx2.cpp

/// The widest kernels the CPU runs, no wider than `requested`.
const WideContactKernels& wideContactKernels(SimdWidth requested);

}  // namespace impulse
