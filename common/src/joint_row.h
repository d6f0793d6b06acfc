#pragma once
// A joint as the solver sees it during a step, and the rows of each kind
// (joint_rows.cpp): shared by the soft passes (joint_constraints.h) and the
// exact tree pass (joint_tree_pass.h).

#include <array>
#include <cstdint>

#include "joint_data.h"
#include "solver_data.h"

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
  /// Its rigid rows belong to the tree pass (joint_tree_pass.h), which solves
  /// them exactly after the soft pass: the soft pass skips them.
  bool inTree = false;
  /// In the tree pass, in a group whose rows are all rigid and whose bodies
  /// nothing else acts on (no contact, no other joint): the exact relax
  /// leaves the rows' velocities what it would after the soft relax, which
  /// moves the bodies only along the rows, so the soft relax skips it.
  bool relaxedExactly = false;
  /// A plain pin in a group with a loop (a grid): the tree pass never
  /// solves it, so its soft rows alone hold the load, at JointPass::loop.
  bool pinInLoop = false;
  /// How many rigid rows it has (rigidRows), and whether it has others (a
  /// motor, a limit, a spring): fixed by its settings, found once a step.
  int rigidRowCount = 0;
  bool softRows = false;
  /// A revolute joint with no limit, motor or spring: a pin and nothing
  /// else, the commonest joint (chains, ragdolls, grids). Its rows need
  /// neither its settings nor its angle, so they skip both.
  bool plainPin = false;
  /// One of its awake bodies touches something this step: its group gets
  /// the exact tree pass (joint_tree_pass.h).
  bool touches = false;
};

/// What every row's pass needs besides the row and its two states.
struct JointPass {
  Real h = 0;
  Real invH = 0;
  Softness rigid;
  /// The plain pins of groups with loops (JointRow::pinInLoop): stiffer.
  Softness loop;
  bool useBias = true;
};


/// A scalar row: Cdot = linear . (vB - vA) + angularB * wB - angularA * wA.
struct Jacobian {
  Vec2 linear = Vec2::Zero();
  Real angularA = 0;
  Real angularB = 0;
  Jacobian operator-() const { return {-linear, -angularA, -angularB}; }
};

/// A row's speed Cdot from its Jacobian's parts and the bodies' velocities
/// (v, w of A, then of B), in float or in float lanes (the exact tree pass
/// works several groups' rows at once, as the soft rows do, in float).
template <class F>
F rowVelocity(F linearX, F linearY, F angularA, F angularB, const F (&a)[3], const F (&b)[3]) {
  return linearX * (b[0] - a[0]) + linearY * (b[1] - a[1]) + angularB * b[2] - angularA * a[2];
}

/// The row's speed Cdot at the states' velocities.
inline Real velocity(const Jacobian& j, const SolverState& a, const SolverState& b) {
  const Real velocityA[3] = {a.linearVelocity.x(), a.linearVelocity.y(), a.angularVelocity};
  const Real velocityB[3] = {b.linearVelocity.x(), b.linearVelocity.y(), b.angularVelocity};
  return rowVelocity(j.linear.x(), j.linear.y(), j.angularA, j.angularB, velocityA, velocityB);
}

/// A rigid (equality) row of a joint at the sub-step's geometry: its error
/// `position`; `impulse` is where its impulse accumulates.
struct RigidRow {
  Jacobian jacobian;
  Real position = 0;
  Real* impulse = nullptr;
};
using RigidRows = std::array<RigidRow, 3>;

/// A joint's point now: its anchors from the centres, turned by the
/// sub-step's rotations, and B's anchor minus A's.
struct PointFrame {
  Vec2 rA;
  Vec2 rB;
  Vec2 d;
};
inline PointFrame pointFrameOf(const JointRow& row, const SolverState& a, const SolverState& b) {
  const Vec2 rA = a.deltaRotation.apply(row.anchorA);
  const Vec2 rB = b.deltaRotation.apply(row.anchorB);
  return {rA, rB, (b.deltaPosition - a.deltaPosition) + row.deltaCenter + rB - rA};
}
/// A point's two rigid rows, along x then y, whose impulses are `impulse`'s.
inline void pointRows(const PointFrame& f, Vec2& impulse, RigidRow* out) {
  out[0] = {{Vec2(1, 0), -f.rA.y(), -f.rB.y()}, f.d.x(), &impulse.x()};
  out[1] = {{Vec2(0, 1), f.rA.x(), f.rB.x()}, f.d.y(), &impulse.y()};
}
/// rigidRows of a plain pin (JointRow::plainPin), inline for the tree
/// pass, which makes them every sub-step.
inline int plainPinRows(JointRow& row, const SolverState& a, const SolverState& b, RigidRows& out) {
  pointRows(pointFrameOf(row, a, b), row.impulses.point, out.data());
  return 2;
}

/// A rigid row's softness in `pass`: the soft step's, with position
/// feedback, in the biased pass; hard (velocity only) in the relax pass.
Softness rowSoftness(const JointPass& pass);
/// A pin in a loop's softness in `pass`: JointPass::loop in the biased pass,
/// hard in the relax pass.
Softness loopPinSoftness(const JointPass& pass);
/// A rigid point row's softness in `pass`: loopPinSoftness for a pin in a
/// loop, rowSoftness otherwise.
Softness pointSoftness(const JointRow& row, const JointPass& pass);

/// The rows of one kind (joint_rows.cpp).
void warmStartJoint(JointRow& row, SolverState& a, SolverState& b);
void solveJoint(JointRow& row, SolverState& a, SolverState& b, const JointPass& pass);
/// Whether a joint of these settings has rows besides its rigid ones (a
/// motor, a limit, a spring; every rope and mouse joint).
bool hasSoftRows(const JointSettings& settings);
/// Fills `out` with the joint's rigid rows at the states' geometry and
/// returns how many (0 to 3): the pin of a revolute or rigid weld, a rod's
/// length, a rigid weld's angle, a prismatic's angle and offset, a wheel's
/// offset (and its travel when rigid).
int rigidRows(JointRow& row, const SolverState& a, const SolverState& b, RigidRows& out);
/// The reaction on B (N, N*m) from the last sub-step's impulses.
void jointReaction(const JointRow& row, Real invH, Vec2& force, Real& torque);
/// The joint angle B relative to A since creation, wrapped to [-pi, pi].
Real jointAngle(const Joint& joint, const Rot& qA, const Rot& qB);

}  // namespace impulse
