#pragma once
// The joint tree pass: solves the rigid rows of every acyclic group of
// joints exactly, once per sub-step, after the soft rows.
//
// Soft Gauss-Seidel passes a load along a chain one link per iteration, and
// rigid rows are springs of a quarter of the sub-step rate: a 300:1 weight
// on 20 light links stretched the chain by 16 %. Where the joints between
// the awake bodies form a tree (a chain, a bridge, a car, a ragdoll), the
// system of bodies and joints can be solved directly in linear time
// (Baraff, "Linear-time dynamics using Lagrange multipliers", 1996): the
// matrix [M G^T; G -eps] of body masses and joint Jacobians has the tree's
// sparsity, and eliminating it from the leaves inwards makes no fill-in.
// The pass sets the velocity of every rigid row to what removes 40 % of
// its position error per sub-step; its impulses join the joints' warm start.
// Groups with a loop keep the soft rows alone. Limits, motors, springs,
// ropes and mouse joints stay soft rows: they are inequalities or are soft
// by design.
//
// Only groups that need it are solved so: every group held by the world (a
// chain, a bridge, a pendulum), and free groups (a ragdoll, a car) while
// they touch anything or carry a load. A soft rigid row holding a load L
// gives way by about L times its compliance (Softness: impulseScale /
// (massScale * biasRate), over the row's effective mass), and a group by the
// sum over its joints; each step the pass estimates that from the loads the
// joints carried last step, and a free group in flight is solved exactly
// while it would give way by kExactTreeStretch or more. A ragdoll falling
// keeps the soft rows alone; from the step it lands, it does not.
//
// Groups of one shape (the same nodes, sizes and links: a pile of one
// ragdoll) are solved four at a time, a group a lane (tree_lanes.h): the
// same arithmetic, in the same order, as alone: the same bits.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "joint_row.h"
#include "task_runner.h"
#include "tree_lanes.h"

namespace impulse {

/// Free groups whose joints the soft rows would let give way by less than
/// this (m), summed over the group, keep the soft rows alone.
inline constexpr Real kExactTreeStretch = Real(0.0001);

class JointTreePass {
 public:
  /// Once per step: finds the acyclic groups among `rows` (bodies are their
  /// solver states, state 0 and massless bodies are the world) and orders
  /// each group's bodies and joints from the leaves to a root. Last step's
  /// groups are kept while every row joins the same states with the same
  /// masses. Then marks `inTree` the rows of the groups it solves this
  /// step (needsExactPass; `rigid` is the soft rigid rows' softness),
  /// `relaxedExactly` those of them in groups of rigid rows alone that
  /// nothing else acts on, and `pinInLoop` the plain pins of the groups with
  /// a loop.
  void order(std::span<JointRow> rows, std::size_t stateCount, const Softness& rigid, const TaskRunner& tasks);
  /// Forgets the groups, for a step with no joint on an awake body.
  void clear() {
    blocks_.clear();
    joints_.clear();
    bodies_.clear();
    groupEnds_.clear();
    solvedGroups_.clear();
    groupShape_.clear();
    shapeCount_ = 0;
    batches_.clear();
    batchedGroups_.clear();
    orderedFrom_.clear();
    jointCount_ = 0;
    factorsCurrent_ = false;
  }
  /// The joints in the groups: what the pass solves each sub-step.
  int jointCount() const { return jointCount_; }
  /// The pass on the states' real velocities: per group, builds and factors
  /// the system at the sub-step's geometry, solves it with position
  /// correction and applies the impulses, which join the joints' warm start.
  /// Groups share no body, so they run side by side on `tasks`.
  void solve(std::span<JointRow> rows, std::span<SolverState> states, Real h, const TaskRunner& tasks);
  /// The pass without position correction, after every kind's relax: the
  /// rows end the sub-step exactly satisfied, whatever the contacts' relax
  /// did to one side, and the correction's speed is taken out again.
  void relax(std::span<JointRow> rows, std::span<SolverState> states, const TaskRunner& tasks);
  /// The pass on the split impulse's pseudo velocities, which only the rows'
  /// speeds are taken out of. The bodies have not moved since this
  /// sub-step's `solve`, so its factors are reused: only the right-hand
  /// side is new.
  void push(std::span<SolverState> states, const TaskRunner& tasks);

 private:
  /// A node of a group's elimination: a joint (its rigid rows, 1 to 3) or
  /// a hub body (m, m, I). Bodies with one or two joints are eliminated
  /// first, into their joints' blocks (their mass is diagonal, which makes
  /// no fill-in while the joints stay a tree): a chain solves 2x2 blocks of
  /// its pins instead of 3x3 blocks of pins and links. Bodies with three or
  /// more joints (a ragdoll's torso) stay nodes, where eliminating them
  /// first would couple all their joints. Its numbers are TreeNodeNumbers.
  struct Block {
    std::int32_t parent = -1;  ///< position in blocks_, -1 for a root
    std::int8_t size = 3;
    std::int8_t parentSize = 0;  ///< 0 for a root
  };
  /// A joint node's rows, beside its block (unused for a hub).
  struct JointNode {
    std::int32_t row = -1;                       ///< its JointRow, -1: a hub body
    std::array<std::int32_t, 2> states{0, 0};    ///< its JointRow's stateA and stateB
    std::array<std::int32_t, 2> bodies{-1, -1};  ///< its bodies (A, B) in bodies_, -1: none
    std::int8_t parentSide = -1;                 ///< the side whose body leads to the parent, -1: root
    std::array<Real*, 3> impulses{};   ///< its rows' accumulated impulses; null: unused
    std::array<Real, 3> position{};    ///< its rows' errors at the blocks' geometry
  };
  /// A body of a group.
  struct TreeBody {
    std::int32_t state = 0;
    Real invMass = 0;
    Real invInertia = 0;
    std::int32_t node = -1;         ///< its hub block, -1: eliminated into its joints
    std::int32_t parentJoint = -1;  ///< the joint node that reached it
    std::int8_t parentSide = 0;     ///< which side of that joint it is
  };
  /// Where a group's blocks and bodies end.
  struct GroupEnd {
    std::int32_t nodes = 0;
    std::int32_t bodies = 0;
    bool otherJoints = false;  ///< a joint without rigid rows (a rope, a mouse) acts on a body
  };
  /// A group's nodes (blocks_ and joints_ from `begin`) and bodies.
  struct GroupView {
    std::int32_t begin = 0;
    std::int32_t end = 0;
    std::int32_t firstBody = 0;  ///< its first body's place in bodies_
    std::span<TreeBody> bodies;
    bool otherJoints = false;
  };
  /// Up to four solved groups of one shape (groupShape_), solved side by
  /// side, a lane each (tree_lanes.h); a lone group in double. `view` is
  /// its place among the views of its width (lone_, quad_).
  struct Batch {
    std::array<std::int32_t, kLanesOf<Quad>> groups{};
    int lanes = 0;
    std::int32_t view = 0;
  };
  /// A batch's groups and numbers: each lane its own rows, states and
  /// masses; node and body k of every group are alike.
  template <class T>
  struct BatchView {
    std::array<GroupView, kLanesOf<Quad>> lanes;
    int laneCount = 0;
    std::span<TreeNodeNumbers<T>> nodes;
    std::span<TreeBodyNumbers<T>> bodies;
    /// The first group: the shape (sizes, links) every lane shares.
    const GroupView& shape() const { return lanes[0]; }
  };
  /// The numbers and views of the batches of one width.
  template <class T>
  struct BatchStore {
    std::vector<TreeNodeNumbers<T>> nodes;
    std::vector<TreeBodyNumbers<T>> bodies;
    std::vector<BatchView<T>> views;
  };
  /// What the groups are built from, per row.
  struct RowShape {
    std::int32_t joint = -1;
    std::int32_t stateA = 0;
    std::int32_t stateB = 0;
    int rigidRowCount = 0;
    Real invMassA = 0;
    Real invInertiaA = 0;
    Real invMassB = 0;
    Real invInertiaB = 0;
    bool operator==(const RowShape&) const = default;
  };
  /// A node as the walk finds it (parent by walk position).
  struct Visit {
    std::int32_t parent = -1;
    std::int32_t state = 0;
    std::int32_t row = -1;
  };

  static RowShape shapeOf(const JointRow& row);
  bool sameRowsAsOrdered(std::span<const JointRow> rows, const TaskRunner& tasks) const;
  void orderAnew(std::span<const JointRow> rows, std::size_t stateCount);
  void buildGroups(std::span<const JointRow> rows, std::size_t stateCount);
  void findRowsInLoops(std::span<const JointRow> rows);
  void orderGroup(std::int32_t rootJoint, std::span<const JointRow> rows);
  bool isHub(const Visit& visit) const;
  void storeReversed(std::span<const JointRow> rows);
  void storeJoint(std::span<const JointRow> rows, std::int32_t at);
  void storeBody(std::span<const JointRow> rows, std::int32_t at);
  GroupView groupAt(std::size_t g);
  void markRelaxedExactly(const GroupView& group, std::span<JointRow> rows) const;
  /// Whether a group is held by the world, touches anything, or the soft
  /// rows alone would let its joints give way by kExactTreeStretch or more.
  bool needsExactPass(const GroupView& group, std::span<const JointRow> rows, Real compliance) const;
  void findGroupShapes();
  void formBatches();
  template <class T>
  void storeBatches(BatchStore<T>& store);
  template <class T>
  void loadBodyNumbers(const BatchView<T>& view);
  /// Runs pass(view) for each batch of solved groups, side by side.
  template <class Pass>
  void forEachBatch(const TaskRunner& tasks, Pass&& pass);
  template <class T>
  void assemble(BatchView<T>& view, std::span<JointRow> rows, std::span<const SolverState> states, double errorRate);
  template <class T, int N, int P>
  void assembleJoint(BatchView<T>& view, std::int32_t k, std::span<JointRow> rows,
                     std::span<const SolverState> states, double errorRate);
  template <class T, int N, int P>
  void coupleSide(BatchView<T>& view, std::int32_t k, int side);
  template <class T>
  bool assembleSpeeds(BatchView<T>& view, std::span<const SolverState> states, double errorRate);
  void solveGroups(std::span<JointRow> rows, std::span<SolverState> states, double errorRate,
                   const TaskRunner& tasks);
  template <class T, class NodeVisit>
  void forEachNodeLeavesFirst(BatchView<T>& view, NodeVisit&& visit);
  template <class T>
  void factorAndReduce(BatchView<T>& view);
  template <class T>
  void reduce(BatchView<T>& view);
  template <class T>
  void backSubstituteAndApply(BatchView<T>& view, std::span<SolverState> states, bool keepImpulses);
  template <class T, int N>
  void applyImpulses(BatchView<T>& view, std::int32_t k, const T (&negated)[3], bool keepImpulses);

  std::vector<std::int32_t> bodyGroup_;     ///< union-find over solver states
  std::vector<std::uint8_t> groupHasLoop_;  ///< by union-find root
  std::vector<std::int32_t> bodyVisit_;     ///< by state: its walk position, -1 unseen
  std::vector<std::uint8_t> jointTaken_;    ///< by row
  std::vector<std::int32_t> jointsOfBody_;  ///< joints with rigid rows, by body
  std::vector<std::int32_t> jointsStart_;
  std::vector<std::int32_t> cursor_;
  std::vector<std::int32_t> loopBodies_;
  std::vector<std::uint8_t> rowInLoop_;  ///< by row: its group has a loop
  std::vector<std::uint8_t> otherJointOn_;  ///< by state: a joint without rigid rows acts on it
  std::vector<Visit> walk_;
  std::vector<std::int32_t> nodeAt_;  ///< by walk position: its node, -1 for a body eliminated first
  std::vector<std::int32_t> bodyAt_;  ///< by walk position: its place in bodies_
  std::vector<Block> blocks_;     ///< every group's nodes, each leaves first, root last
  std::vector<JointNode> joints_;  ///< beside blocks_
  std::vector<TreeBody> bodies_;  ///< every group's bodies
  std::vector<GroupEnd> groupEnds_;  ///< where each group ends in blocks_ and bodies_
  std::vector<std::int32_t> solvedGroups_;  ///< the groups that need the pass this step
  std::vector<std::int32_t> groupShape_;    ///< by group: its shape, groups of one shape alike node by node
  std::int32_t shapeCount_ = 0;
  std::vector<std::int32_t> openBatch_;     ///< by shape: the batch taking its next group, -1: none
  std::vector<Batch> batches_;              ///< this step's solved groups in batches
  std::vector<std::int32_t> batchedGroups_; ///< the solved groups batches_ holds
  BatchStore<double> lone_;  ///< the batches of one group
  BatchStore<Quad> quad_;    ///< the batches of two to four
  std::vector<RowShape> orderedFrom_;    ///< the rows the groups were built from
  int jointCount_ = 0;
  /// The solved groups' factors are at the states' current geometry: the
  /// next solve needs only its speeds.
  bool factorsCurrent_ = false;
};

}  // namespace impulse
