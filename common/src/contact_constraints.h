#pragma once
// Contacts as a constraint kind: each step takes the touching contacts of
// awake bodies, colours them and packs them into SIMD bundles
// (contact_solver_wide.h), and runs the soft contact passes over them.

#include <vector>

#include "constraint_kind.h"
#include "contact_constraint.h"
#include "support_pass.h"

namespace impulse {

struct WideContactKernels;

class ContactConstraints final : public ConstraintKind {
 public:
  /// Once per step, before any kind's prepare: takes the touching contacts
  /// of awake bodies and marks their bodies (touches), which the joints'
  /// prepare reads. prepare then colours and bundles them.
  void collect(const WorldData& world);
  bool prepare(const WorldData& world, const SolveStep& step, GraphColoring& coloring) override;
  bool empty() const override { return refs_.empty(); }
  void warmStart(const SubStep& sub) override;
  void solve(const SubStep& sub) override;
  void relax(const SubStep& sub) override;
  void push(const SubStep& sub) override;
  void restitution(const SubStep& sub) override;
  void store(WorldData& world) override;
  void countPasses(SolverPasses& passes) const override;
  /// Whether the awake body of solver state k is on a touching contact this
  /// step (false for the static dummy 0).
  bool touches(std::int32_t state) const { return state > 0 && touching_[std::size_t(state)] != 0; }

 private:
  ContactSolverContext contextFor(const SubStep& sub) const;

  std::vector<ConstraintRef> refs_;
  std::vector<std::uint8_t> touching_;  // per solver state
  SupportPass support_;
  WideContactSet wide_;
  const WideContactKernels* kernels_ = nullptr;
  ContactSolverContext context_;
};

}  // namespace impulse
