#pragma once
// Joints as a constraint kind: each step takes the joints with an awake
// body, colours them in the shared colouring (before the contacts take
// theirs) and solves them soft-step style: rigid rows with the joint
// softness, warm started; springs as exact-stiffness implicit rows.

#include <cstdint>
#include <vector>

#include "constraint_kind.h"
#include "joint_data.h"

namespace impulse {

/// One joint as the solver sees it during a step.
struct JointRow {
  const Joint* joint = nullptr;
  std::int32_t index = kNullIndex;
  std::int32_t stateA = 0;
  std::int32_t stateB = 0;
  Real invMassA = 0;
  Real invInertiaA = 0;
  Real invMassB = 0;
  Real invInertiaB = 0;
  Vec2 anchorA = Vec2::Zero();  ///< from A's centre, world-rotated at step start
  Vec2 anchorB = Vec2::Zero();
  Vec2 deltaCenter = Vec2::Zero();  ///< B's centre minus A's at step start
  Real deltaAngle = 0;              ///< joint angle at step start
  Vec2 axis = Vec2(1, 0);           ///< world axis at step start (prismatic, wheel)
  Vec2 lastAxis = Vec2(1, 0);       ///< for the reaction force
  JointImpulses impulses;
};

/// What every row's pass needs besides the row and its two states.
struct JointPass {
  Real h = 0;
  Real invH = 0;
  Softness rigid;
  bool useBias = true;
};

class JointConstraints final : public ConstraintKind {
 public:
  bool prepare(const WorldData& world, const SolveStep& step, GraphColoring& coloring) override;
  void warmStart(const SubStep& sub) override;
  void solve(const SubStep& sub) override;
  void relax(const SubStep& sub) override;
  void store(WorldData& world) override;

 private:
  void run(const SubStep& sub, bool useBias);

  std::vector<JointRow> rows_;
  std::vector<JointRow> gathered_;
  std::vector<std::int32_t> colorOf_;
  std::vector<std::int32_t> order_;
  JointPass pass_;
};

/// The rows of one kind (joint_rows.cpp).
void warmStartJoint(JointRow& row, SolverState& a, SolverState& b);
void solveJoint(JointRow& row, SolverState& a, SolverState& b, const JointPass& pass);
/// The reaction on B (N, N*m) from the last sub-step's impulses.
void jointReaction(const JointRow& row, Real invH, Vec2& force, Real& torque);
/// The joint angle B relative to A since creation, wrapped to [-pi, pi].
Real jointAngle(const Joint& joint, const Rot& qA, const Rot& qB);

}  // namespace impulse
