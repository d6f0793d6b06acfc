#include "joint_tree_pass.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <type_traits>

#include "union_find.h"

namespace impulse {

namespace {

// Two fifths of a rigid row's position error are taken out per sub-step:
// the error the linearised rows leave in a swinging chain stays under a
// millimetre (joint_accuracy_test; a fifth left 1.3 mm).
constexpr double kErrorShare = 0.4;
// The correction never moves a row faster than this (m/s or rad/s), so a
// joint made far apart is pulled together, not thrown. The exact relax takes
// the correction's speed out again each sub-step (it moves positions only);
// faster, piles of ragdolls stir (the bench's ragdoll-pile ends with its
// fastest body at 0.14 m/s at 2, 0.10-0.15 at 3-20), slower, a landing
// ragdoll's knee closes slowly (v3's rain: widest gap 0.20 m at 1 m/s,
// 0.197 at 2, 0.187 at 4).
constexpr double kMaxCorrectionSpeed = 2;
// Each row gives way by this share of its own inverse mass (it ends the pass
// with a speed of 1e-5 of its impulse's own effect): that keeps the
// elimination regular where rows repeat each other (two pins at one point,
// both ends of a bridge), far below anything a step can show.
constexpr double kCompliance = 1e-5;
// Rows per range of the side-by-side passes over every row (comparing it,
// marking it): a row costs a few nanoseconds.
constexpr std::int32_t kRowsPerRange = 1024;

// The speed a row is given to take out its share of position error, lane
// by lane.
template <class T>
T correctionSpeed(double errorRate, const T& position) {
  return clampLanes(splat<T>(errorRate) * position, -kMaxCorrectionSpeed, kMaxCorrectionSpeed);
}

bool isBody(std::int32_t state, Real invMass) { return state != 0 && invMass > 0; }
bool hasBodyA(const JointRow& row) { return isBody(row.stateA, row.invMassA); }
bool hasBodyB(const JointRow& row) { return isBody(row.stateB, row.invMassB); }

// A joint's rows on one body, row by row (vx, vy, w).
using SideRows = std::array<std::array<double, 3>, 3>;

// The joint's N rows acting on one of its bodies (by vx, vy, w).
void fillSide(const RigidRows& rows, int count, bool sideB, SideRows& side) {
  const double sign = sideB ? 1 : -1;
  for (int r = 0; r < count; ++r) {
    const Jacobian& row = rows[std::size_t(r)].jacobian;
    side[std::size_t(r)] = {sign * row.linear.x(), sign * row.linear.y(),
                            sideB ? double(row.angularB) : -double(row.angularA)};
  }
}

// A joint's two bodies' velocities (vx, vy, w), A's then B's, lane by lane
// in float.
template <class T>
struct LaneVelocities {
  FloatsOf<T> of[2][3];
};

LaneVelocities<double> velocitiesOf(const SolverState& a, const SolverState& b) {
  return {{{a.linearVelocity.x(), a.linearVelocity.y(), a.angularVelocity},
           {b.linearVelocity.x(), b.linearVelocity.y(), b.angularVelocity}}};
}

// A row's speed, lane by lane, from its rows on A and B (which hold its
// float Jacobian exactly: A's linear part is B's negated, so only A's
// angular part is read), worked out in float by the soft rows' own
// rowVelocity (joint_row.h): the bench's ragdoll pile, whose widest pin gap
// comes from one moment, opened 14.6 cm instead of 5.3 with the speeds in
// double. `OnB` is a row of three T.
template <class T, class OnB>
T rowSpeed(const T& onAAngular, const OnB& onB, const LaneVelocities<T>& v) {
  return toDoubles(rowVelocity(toFloats(onB[0]), toFloats(onB[1]), toFloats(-onAAngular), toFloats(onB[2]), v.of[0],
                               v.of[1]));
}

// The numbers below are the pass's arithmetic on a T, one group's (double)
// or four's (Quad), written out element by element in one order.

// The blocks D_i are symmetric: their inverse by cofactors, read from the
// upper triangle, in place.
template <int N, class T>
[[gnu::always_inline]] inline void invertSymmetric(T (&a)[3][3]) {
  if constexpr (N == 1) {
    a[0][0] = splat<T>(1) / a[0][0];
  } else if constexpr (N == 2) {
    const T scale = splat<T>(1) / (a[0][0] * a[1][1] - a[0][1] * a[0][1]);
    const T offDiagonal = -a[0][1] * scale;
    const T first = a[1][1] * scale;
    a[1][1] = a[0][0] * scale;
    a[0][0] = first;
    a[0][1] = offDiagonal;
    a[1][0] = offDiagonal;
  } else {
    const T xx = a[1][1] * a[2][2] - a[1][2] * a[1][2];
    const T xy = a[0][2] * a[1][2] - a[0][1] * a[2][2];
    const T xz = a[0][1] * a[1][2] - a[0][2] * a[1][1];
    const T scale = splat<T>(1) / (a[0][0] * xx + a[0][1] * xy + a[0][2] * xz);
    const T yy = (a[0][0] * a[2][2] - a[0][2] * a[0][2]) * scale;
    const T yz = (a[0][2] * a[0][1] - a[0][0] * a[1][2]) * scale;
    const T zz = (a[0][0] * a[1][1] - a[0][1] * a[0][1]) * scale;
    a[0][0] = xx * scale;
    a[0][1] = xy * scale;
    a[0][2] = xz * scale;
    a[1][0] = a[0][1];
    a[1][1] = yy;
    a[1][2] = yz;
    a[2][0] = a[0][2];
    a[2][1] = yz;
    a[2][2] = zz;
  }
}

// Element (i, j) of left * right, the sum over k in order.
template <int K, class T>
[[gnu::always_inline]] inline T productAt(const T (&left)[3][3], const T (&right)[3][3], int i, int j) {
  T sum = left[i][0] * right[0][j];
  for (int k = 1; k < K; ++k) sum += left[i][k] * right[k][j];
  return sum;
}

// One node's elimination, for its size N and its parent's P (0: a root),
// fixed at compile time (a chain's pins are 2 x 2): D_i^-1, then
// D_i^-1 H_{i,parent}, and the parent's block less H_{i,parent}^T D_i^-1
// H_{i,parent} (symmetric: its upper triangle, mirrored).
template <int N, int P, class T>
[[gnu::always_inline]] inline void eliminateNode(TreeNodeNumbers<T>& node, TreeNodeNumbers<T>& parent) {
  invertSymmetric<N>(node.diagonal);
  if constexpr (P > 0) {
    T lower[3][3];
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j < P; ++j) lower[i][j] = productAt<N>(node.diagonal, node.toParent, i, j);
    }
    for (int i = 0; i < P; ++i) {
      for (int j = i; j < P; ++j) {
        T product = node.toParent[0][i] * lower[0][j];
        for (int k = 1; k < N; ++k) product += node.toParent[k][i] * lower[k][j];
        parent.diagonal[i][j] -= product;
        if (j != i) parent.diagonal[j][i] -= product;
      }
    }
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j < P; ++j) node.toParent[i][j] = lower[i][j];
    }
  }
}

// The forward substitution of a node: its value times D_i^-1, and the
// parent's value less H_{i,parent}^T times the node's value before.
template <int N, int P, class T>
[[gnu::always_inline]] inline void substituteForward(TreeNodeNumbers<T>& node, TreeNodeNumbers<T>& parent) {
  T reduced[3];
  for (int i = 0; i < N; ++i) reduced[i] = node.value[i];
  for (int i = 0; i < N; ++i) {
    T sum = node.diagonal[i][0] * reduced[0];
    for (int k = 1; k < N; ++k) sum += node.diagonal[i][k] * reduced[k];
    node.value[i] = sum;
  }
  if constexpr (P > 0) {
    for (int j = 0; j < P; ++j) {
      T sum = node.toParent[0][j] * reduced[0];
      for (int k = 1; k < N; ++k) sum += node.toParent[k][j] * reduced[k];
      parent.value[j] -= sum;
    }
  }
}

// The backward substitution of a node, its solution also into `solved`:
// read from there, not from the values just stored one by one (a load of two
// of them at once waited for both stores to leave).
template <int N, int P, class T>
[[gnu::always_inline]] inline void substituteBackward(TreeNodeNumbers<T>& node, const TreeNodeNumbers<T>& parent,
                                                      T (&solved)[3]) {
  for (int i = 0; i < N; ++i) {
    solved[i] = node.value[i];
    if constexpr (P > 0) {
      T sum = node.toParent[i][0] * parent.value[0];
      for (int k = 1; k < P; ++k) sum += node.toParent[i][k] * parent.value[k];
      solved[i] -= sum;
      node.value[i] = solved[i];
    }
  }
}

template <int V>
using Size = std::integral_constant<int, V>;

// visit(Size<N>, Size<P>) for the node's size and its parent's.
template <class Block, class Visit>
void withSizes(const Block& node, Visit&& visit) {
  switch (node.size * 4 + node.parentSize) {
    case 4: return visit(Size<1>{}, Size<0>{});
    case 5: return visit(Size<1>{}, Size<1>{});
    case 6: return visit(Size<1>{}, Size<2>{});
    case 7: return visit(Size<1>{}, Size<3>{});
    case 8: return visit(Size<2>{}, Size<0>{});
    case 9: return visit(Size<2>{}, Size<1>{});
    case 10: return visit(Size<2>{}, Size<2>{});
    case 11: return visit(Size<2>{}, Size<3>{});
    case 12: return visit(Size<3>{}, Size<0>{});
    case 13: return visit(Size<3>{}, Size<1>{});
    case 14: return visit(Size<3>{}, Size<2>{});
    default: return visit(Size<3>{}, Size<3>{});
  }
}

}  // namespace

void JointTreePass::order(std::span<JointRow> rows, std::size_t stateCount, const Softness& rigid,
                          const TaskRunner& tasks) {
  const bool reordered = !sameRowsAsOrdered(rows, tasks);
  if (reordered) orderAnew(rows, stateCount);
  const Real compliance = rigid.impulseScale / (rigid.massScale * rigid.biasRate);
  factorsCurrent_ = false;
  jointCount_ = 0;
  solvedGroups_.clear();
  tasks.forRanges(std::int32_t(rows.size()), kRowsPerRange,
                  [&](std::int32_t begin, std::int32_t end) {
                    for (std::int32_t r = begin; r < end; ++r) {
                      JointRow& row = rows[std::size_t(r)];
                      row.pinInLoop = row.plainPin && rowInLoop_[std::size_t(r)] != 0;
                    }
                  });
  for (std::size_t g = 0; g < groupEnds_.size(); ++g) {
    const GroupView group = groupAt(g);
    if (!needsExactPass(group, rows, compliance)) continue;
    solvedGroups_.push_back(std::int32_t(g));
    bool alone = !group.otherJoints;
    for (std::int32_t node = group.begin; node < group.end; ++node) {
      const std::int32_t row = joints_[std::size_t(node)].row;
      if (row < 0) continue;
      JointRow& joint = rows[std::size_t(row)];
      joint.inTree = true;
      alone = alone && !joint.touches && !joint.softRows;
      ++jointCount_;
    }
    if (alone) markRelaxedExactly(group, rows);
  }
  // Last step's batches stand while the same groups are solved.
  if (reordered || solvedGroups_ != batchedGroups_) {
    formBatches();
    batchedGroups_ = solvedGroups_;
  }
}

// The soft relax of such a group's rows moves its bodies only along the
// rows, which the exact relax then projects out again: it changes the end
// velocities by the compliance's share of its impulses (1e-5) alone.
void JointTreePass::markRelaxedExactly(const GroupView& group, std::span<JointRow> rows) const {
  for (std::int32_t node = group.begin; node < group.end; ++node) {
    const std::int32_t row = joints_[std::size_t(node)].row;
    if (row >= 0) rows[std::size_t(row)].relaxedExactly = true;
  }
}

JointTreePass::GroupView JointTreePass::groupAt(std::size_t g) {
  const GroupEnd begin = g == 0 ? GroupEnd{} : groupEnds_[g - 1];
  const GroupEnd end = groupEnds_[g];
  return {begin.nodes, end.nodes, begin.bodies,
          std::span<TreeBody>(bodies_).subspan(std::size_t(begin.bodies), std::size_t(end.bodies - begin.bodies)),
          end.otherJoints};
}

// A group held by the world (a chain, a bridge, a pendulum, a crane) hangs
// its weight on its joints all the time, and swings through unloaded
// moments: it is always solved exactly. So is a group touching anything: a
// contact loads its joints in the step it begins, before any load is
// measured. A group in flight is measured: each joint's linear load last
// step (its stored impulses, warm started or not) over its rows' effective
// mass, the pair's masses taken as points.
bool JointTreePass::needsExactPass(const GroupView& group, std::span<const JointRow> rows,
                                   Real compliance) const {
  // The walk roots a group at a joint to the world when it has one.
  const JointNode& root = joints_[std::size_t(group.end - 1)];
  if (root.bodies[0] < 0 || root.bodies[1] < 0) return true;
  Real give = 0;
  for (std::int32_t node = group.begin; node < group.end; ++node) {
    const std::int32_t index = joints_[std::size_t(node)].row;
    if (index < 0) continue;
    const JointRow& row = rows[std::size_t(index)];
    if (row.touches) return true;
    const JointImpulses& last = row.joint->impulses;
    const Real load = last.point.norm() + std::abs(last.perpendicular) + std::abs(last.axial);
    give += load * compliance * (row.invMassA + row.invMassB);
  }
  return give >= kExactTreeStretch;
}

JointTreePass::RowShape JointTreePass::shapeOf(const JointRow& row) {
  return {row.index,    row.stateA,      row.stateB,   row.rigidRowCount,
          row.invMassA, row.invInertiaA, row.invMassB, row.invInertiaB};
}

bool JointTreePass::sameRowsAsOrdered(std::span<const JointRow> rows, const TaskRunner& tasks) const {
  if (rows.size() != orderedFrom_.size()) return false;
  std::atomic<bool> differs{false};
  tasks.forRanges(
      std::int32_t(rows.size()), kRowsPerRange, [&](std::int32_t begin, std::int32_t end) {
        const bool same = std::equal(
            rows.begin() + begin, rows.begin() + end, orderedFrom_.begin() + begin,
            [](const JointRow& row, const RowShape& shape) { return shapeOf(row) == shape; });
        if (!same) differs.store(true, std::memory_order_relaxed);
      });
  return !differs.load(std::memory_order_relaxed);
}

void JointTreePass::orderAnew(std::span<const JointRow> rows, std::size_t stateCount) {
  clear();
  for (const JointRow& row : rows) orderedFrom_.push_back(shapeOf(row));
  buildGroups(rows, stateCount);
  findRowsInLoops(rows);
  jointTaken_.assign(rows.size(), 0);
  bodyVisit_.assign(stateCount, -1);
  // A joint to the world is the best root: then no leaf is a joint alone,
  // whose block is only the compliance. Other groups start anywhere.
  for (bool worldJointsOnly : {true, false}) {
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const JointRow& row = rows[r];
      if (jointTaken_[r] || row.rigidRowCount == 0) continue;
      if (!hasBodyA(row) && !hasBodyB(row)) continue;
      const bool toWorld = hasBodyA(row) != hasBodyB(row);
      if (worldJointsOnly && !toWorld) continue;
      const std::int32_t body = hasBodyA(row) ? row.stateA : row.stateB;
      if (groupHasLoop_[unionFindRoot(bodyGroup_, body)]) continue;
      orderGroup(static_cast<std::int32_t>(r), rows);
    }
  }
  findGroupShapes();
}

// Joints with a rigid row and a body are the edges; a joint that closes a
// loop marks its group, and counting sorts them by body for the walk.
void JointTreePass::buildGroups(std::span<const JointRow> rows, std::size_t stateCount) {
  bodyGroup_.resize(stateCount);
  for (std::size_t s = 0; s < stateCount; ++s) bodyGroup_[s] = static_cast<std::int32_t>(s);
  groupHasLoop_.assign(stateCount, 0);
  otherJointOn_.assign(stateCount, 0);
  jointsStart_.assign(stateCount + 1, 0);
  loopBodies_.clear();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
    if (row.rigidRowCount == 0) {
      otherJointOn_[std::size_t(row.stateA)] = 1;
      otherJointOn_[std::size_t(row.stateB)] = 1;
    }
    const bool a = hasBodyA(row) && row.rigidRowCount > 0;
    const bool b = hasBodyB(row) && row.rigidRowCount > 0;
    if (a) ++jointsStart_[row.stateA + 1];
    if (b) ++jointsStart_[row.stateB + 1];
    if (!a || !b) continue;
    const std::int32_t groupA = unionFindRoot(bodyGroup_, row.stateA);
    const std::int32_t groupB = unionFindRoot(bodyGroup_, row.stateB);
    if (groupA == groupB) loopBodies_.push_back(row.stateA);
    bodyGroup_[groupA] = groupB;
  }
  for (std::int32_t state : loopBodies_) groupHasLoop_[unionFindRoot(bodyGroup_, state)] = 1;
  for (std::size_t s = 0; s < stateCount; ++s) jointsStart_[s + 1] += jointsStart_[s];
  cursor_.assign(jointsStart_.begin(), jointsStart_.end() - 1);
  jointsOfBody_.resize(static_cast<std::size_t>(jointsStart_.back()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
    if (row.rigidRowCount == 0) continue;
    if (hasBodyA(row)) jointsOfBody_[cursor_[row.stateA]++] = static_cast<std::int32_t>(r);
    if (hasBodyB(row)) jointsOfBody_[cursor_[row.stateB]++] = static_cast<std::int32_t>(r);
  }
}

void JointTreePass::findRowsInLoops(std::span<const JointRow> rows) {
  rowInLoop_.assign(rows.size(), 0);
  auto inLoop = [&](std::int32_t state) {
    return groupHasLoop_[unionFindRoot(bodyGroup_, state)] != 0;
  };
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
    if (row.rigidRowCount == 0) continue;
    rowInLoop_[r] = (hasBodyA(row) && inLoop(row.stateA)) || (hasBodyB(row) && inLoop(row.stateB));
  }
}

// Breadth first from the root joint, then stored reversed: every node comes
// before its parent, as the elimination needs.
void JointTreePass::orderGroup(std::int32_t rootJoint, std::span<const JointRow> rows) {
  walk_.assign(1, {.row = rootJoint});
  jointTaken_[rootJoint] = 1;
  for (std::size_t at = 0; at < walk_.size(); ++at) {
    const Visit visit = walk_[at];
    const auto here = static_cast<std::int32_t>(at);
    if (visit.row >= 0) {
      const JointRow& row = rows[visit.row];
      for (bool sideB : {false, true}) {
        if (!(sideB ? hasBodyB(row) : hasBodyA(row))) continue;
        const std::int32_t state = sideB ? row.stateB : row.stateA;
        if (bodyVisit_[state] >= 0) continue;  // the parent
        bodyVisit_[state] = static_cast<std::int32_t>(walk_.size());
        walk_.push_back({.parent = here, .state = state});
      }
      continue;
    }
    for (std::int32_t k = jointsStart_[visit.state]; k < jointsStart_[visit.state + 1]; ++k) {
      const std::int32_t joint = jointsOfBody_[k];
      if (jointTaken_[joint]) continue;
      jointTaken_[joint] = 1;
      walk_.push_back({.parent = here, .row = joint});
    }
  }
  storeReversed(rows);
}

// A body with three or more joints stays a node of its own (JointTreePass::Block).
bool JointTreePass::isHub(const Visit& visit) const {
  return visit.row < 0 && jointsStart_[visit.state + 1] - jointsStart_[visit.state] > 2;
}

// Nodes in reverse walk order, so that every node comes before its parent;
// a body eliminated first is no node, and the joints it reached take its
// parent joint as theirs.
void JointTreePass::storeReversed(std::span<const JointRow> rows) {
  const auto last = static_cast<std::int32_t>(walk_.size()) - 1;
  nodeAt_.assign(walk_.size(), -1);
  bodyAt_.assign(walk_.size(), -1);
  auto node = static_cast<std::int32_t>(blocks_.size());
  auto body = static_cast<std::int32_t>(bodies_.size());
  for (std::int32_t at = last; at >= 0; --at) {
    const Visit& visit = walk_[std::size_t(at)];
    if (visit.row >= 0 || isHub(visit)) nodeAt_[std::size_t(at)] = node++;
    if (visit.row < 0) bodyAt_[std::size_t(at)] = body++;
  }
  for (std::int32_t at = last; at >= 0; --at) {
    if (walk_[std::size_t(at)].row >= 0) {
      storeJoint(rows, at);
    } else {
      storeBody(rows, at);
    }
  }
  const bool otherJoints = std::any_of(bodies_.begin() + (groupEnds_.empty() ? 0 : groupEnds_.back().bodies),
                                       bodies_.end(), [&](const TreeBody& b) { return otherJointOn_[std::size_t(b.state)] != 0; });
  groupEnds_.push_back({static_cast<std::int32_t>(blocks_.size()), static_cast<std::int32_t>(bodies_.size()), otherJoints});
}

void JointTreePass::storeJoint(std::span<const JointRow> rows, std::int32_t at) {
  const Visit& visit = walk_[std::size_t(at)];
  const JointRow& row = rows[std::size_t(visit.row)];
  JointNode joint;
  joint.row = visit.row;
  joint.states = {row.stateA, row.stateB};
  if (hasBodyA(row)) joint.bodies[0] = bodyAt_[std::size_t(bodyVisit_[row.stateA])];
  if (hasBodyB(row)) joint.bodies[1] = bodyAt_[std::size_t(bodyVisit_[row.stateB])];
  Block block;
  block.size = static_cast<std::int8_t>(row.rigidRowCount);
  if (visit.parent >= 0) {
    const Visit& parentBody = walk_[std::size_t(visit.parent)];
    joint.parentSide = parentBody.state == row.stateB ? 1 : 0;
    // A parent body eliminated first hands on its own parent joint.
    const std::int32_t parent = isHub(parentBody) ? visit.parent : parentBody.parent;
    block.parent = nodeAt_[std::size_t(parent)];
    const Visit& parentNode = walk_[std::size_t(parent)];
    block.parentSize = static_cast<std::int8_t>(parentNode.row >= 0 ? rows[std::size_t(parentNode.row)].rigidRowCount : 3);
  }
  blocks_.push_back(block);
  joints_.push_back(joint);
}

// A body's masses, from the joint that reached it.
void JointTreePass::storeBody(std::span<const JointRow> rows, std::int32_t at) {
  const Visit& visit = walk_[std::size_t(at)];
  const Visit& reachedBy = walk_[std::size_t(visit.parent)];
  const JointRow& row = rows[std::size_t(reachedBy.row)];
  const bool sideB = row.stateB == visit.state;
  TreeBody body;
  body.state = visit.state;
  body.invMass = sideB ? row.invMassB : row.invMassA;
  body.invInertia = sideB ? row.invInertiaB : row.invInertiaA;
  body.node = nodeAt_[std::size_t(at)];
  body.parentJoint = nodeAt_[std::size_t(visit.parent)];
  body.parentSide = sideB ? 1 : 0;
  bodies_.push_back(body);
  if (body.node < 0) return;
  Block block;
  block.parent = body.parentJoint;
  block.parentSize = static_cast<std::int8_t>(row.rigidRowCount);
  blocks_.push_back(block);
  joints_.emplace_back();
}

// A group's shape: its nodes' sizes and links and its bodies' places, each
// relative to the group's own start. Groups of one shape (a pile's
// ragdolls) are solved four at a time (formBatches).
void JointTreePass::findGroupShapes() {
  std::map<std::vector<std::int32_t>, std::int32_t> shapes;
  std::vector<std::int32_t> key;
  groupShape_.resize(groupEnds_.size());
  for (std::size_t g = 0; g < groupEnds_.size(); ++g) {
    const GroupView group = groupAt(g);
    const auto nodeAt = [&](std::int32_t node) { return node < 0 ? -1 : node - group.begin; };
    const auto bodyAt = [&](std::int32_t body) { return body < 0 ? -1 : body - group.firstBody; };
    key.clear();
    for (std::int32_t node = group.begin; node < group.end; ++node) {
      const Block& block = blocks_[std::size_t(node)];
      const JointNode& joint = joints_[std::size_t(node)];
      key.insert(key.end(), {block.size, block.parentSize, nodeAt(block.parent), joint.row < 0 ? 0 : 1,
                             bodyAt(joint.bodies[0]), bodyAt(joint.bodies[1]), joint.parentSide});
    }
    key.push_back(-2);  // no node's entry: the nodes end here
    for (const TreeBody& body : group.bodies) {
      key.insert(key.end(), {nodeAt(body.node), nodeAt(body.parentJoint), body.parentSide});
    }
    groupShape_[g] = shapes.try_emplace(key, std::int32_t(shapes.size())).first->second;
  }
  shapeCount_ = std::int32_t(shapes.size());
}

// This step's solved groups in batches of one shape, up to four, in the
// order the groups come: the same batches whatever the thread count. Then
// their numbers' storage, their views of it and their bodies' masses.
void JointTreePass::formBatches() {
  batches_.clear();
  openBatch_.assign(std::size_t(shapeCount_), -1);
  for (const std::int32_t g : solvedGroups_) {
    std::int32_t& open = openBatch_[std::size_t(groupShape_[std::size_t(g)])];
    if (open < 0 || batches_[std::size_t(open)].lanes == kLanesOf<Quad>) {
      open = std::int32_t(batches_.size());
      batches_.emplace_back();
    }
    Batch& batch = batches_[std::size_t(open)];
    batch.groups[std::size_t(batch.lanes++)] = g;
  }
  storeBatches(lone_);
  storeBatches(quad_);
}

// The batches of T's width (a lone group's for double, two to four groups'
// for Quad): their numbers' storage, their views of it, which `view`
// names, and their bodies' masses.
template <class T>
void JointTreePass::storeBatches(BatchStore<T>& store) {
  const auto ofWidth = [](const Batch& batch) { return (batch.lanes == 1) == std::is_same_v<T, double>; };
  std::size_t nodes = 0;
  std::size_t bodies = 0;
  for (const Batch& batch : batches_) {
    if (!ofWidth(batch)) continue;
    const GroupView group = groupAt(std::size_t(batch.groups[0]));
    nodes += std::size_t(group.end - group.begin);
    bodies += group.bodies.size();
  }
  store.nodes.resize(nodes);
  store.bodies.resize(bodies);
  store.views.clear();
  nodes = 0;
  bodies = 0;
  for (Batch& batch : batches_) {
    if (!ofWidth(batch)) continue;
    batch.view = std::int32_t(store.views.size());
    BatchView<T>& view = store.views.emplace_back();
    view.laneCount = batch.lanes;
    for (int lane = 0; lane < batch.lanes; ++lane) {
      view.lanes[std::size_t(lane)] = groupAt(std::size_t(batch.groups[std::size_t(lane)]));
    }
    const auto nodeCount = std::size_t(view.shape().end - view.shape().begin);
    view.nodes = std::span(store.nodes).subspan(nodes, nodeCount);
    view.bodies = std::span(store.bodies).subspan(bodies, view.shape().bodies.size());
    nodes += nodeCount;
    bodies += view.shape().bodies.size();
    loadBodyNumbers(view);
  }
}

// A lane without a group holds bodies of unit masses under rows of zeros:
// it makes no impulse and divides by nothing that is zero.
template <class T>
void JointTreePass::loadBodyNumbers(const BatchView<T>& view) {
  for (std::size_t b = 0; b < view.bodies.size(); ++b) {
    const auto invMass = [&](int lane) {
      return lane < view.laneCount ? double(view.lanes[std::size_t(lane)].bodies[b].invMass) : 1.0;
    };
    const auto invInertia = [&](int lane) {
      return lane < view.laneCount ? double(view.lanes[std::size_t(lane)].bodies[b].invInertia) : 1.0;
    };
    TreeBodyNumbers<T>& numbers = view.bodies[b];
    numbers.invMass = lanesOf<T>(invMass);
    numbers.invInertia = lanesOf<T>(invInertia);
    // A body that cannot turn has an inertia beyond any lever.
    numbers.hubInertia = lanesOf<T>([&](int lane) { return invInertia(lane) > 0 ? 1.0 / invInertia(lane) : 1e30; });
  }
}

// Batches per range when they run side by side: a ragdoll's group takes a
// microsecond or two a pass, a batch up to four of them, a hand-off to a
// thread about one.
constexpr std::int32_t kBatchesPerRange = 2;

template <class Pass>
void JointTreePass::forEachBatch(const TaskRunner& tasks, Pass&& pass) {
  tasks.forRanges(std::int32_t(batches_.size()), kBatchesPerRange, [&](std::int32_t first, std::int32_t last) {
    for (std::int32_t k = first; k < last; ++k) {
      const Batch& batch = batches_[std::size_t(k)];
      if (batch.lanes == 1) {
        pass(lone_.views[std::size_t(batch.view)]);
      } else {
        pass(quad_.views[std::size_t(batch.view)]);
      }
    }
  });
}

void JointTreePass::solve(std::span<JointRow> rows, std::span<SolverState> states, Real h,
                          const TaskRunner& tasks) {
  solveGroups(rows, states, kErrorShare / h, tasks);
}

void JointTreePass::relax(std::span<JointRow> rows, std::span<SolverState> states, const TaskRunner& tasks) {
  // The positions moved since the solve: its factors are another geometry's
  // (reused, they let a long bridge's rows drift apart).
  factorsCurrent_ = false;
  solveGroups(rows, states, 0, tasks);
}

// Batch by batch, so that a batch's numbers stay in cache through the
// passes. The factors made here are this geometry's until the positions
// move: the push reuses them, and so does the next sub-step's solve after a
// relax (only velocities change in between).
void JointTreePass::solveGroups(std::span<JointRow> rows, std::span<SolverState> states, double errorRate,
                                const TaskRunner& tasks) {
  const bool factored = factorsCurrent_;
  forEachBatch(tasks, [&](auto& view) {
    if (factored) {
      if (!assembleSpeeds(view, states, errorRate)) return;  // no row moves: no impulse
      reduce(view);
    } else {
      assemble(view, rows, states, errorRate);
      factorAndReduce(view);
    }
    backSubstituteAndApply(view, states, true);
  });
  factorsCurrent_ = true;
}

void JointTreePass::push(std::span<SolverState> states, const TaskRunner& tasks) {
  forEachBatch(tasks, [&](auto& view) {
    if (!assembleSpeeds(view, states, 0)) return;  // nothing pushed it: no change
    reduce(view);
    backSubstituteAndApply(view, states, false);
  });
}

// A joint's block at the sub-step's geometry, lane by lane: its rows'
// compliance, and the right-hand side that takes out their share of
// position error; then what its bodies add, all lanes at once.
template <class T, int N, int P>
void JointTreePass::assembleJoint(BatchView<T>& view, std::int32_t k, std::span<JointRow> rows,
                                  std::span<const SolverState> states, double errorRate) {
  TreeNodeNumbers<T>& numbers = view.nodes[std::size_t(k)];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) numbers.diagonal[i][j] = splat<T>(i == j ? 1 : 0);
    numbers.value[i] = splat<T>(0);
  }
  for (int lane = 0; lane < kLanesOf<T>; ++lane) {
    SideRows onA{};
    SideRows onB{};
    if (lane < view.laneCount) {
      JointNode& joint = joints_[std::size_t(view.lanes[std::size_t(lane)].begin + k)];
      JointRow& row = rows[std::size_t(joint.row)];
      const SolverState& a = states[row.stateA];
      const SolverState& b = states[row.stateB];
      RigidRows rigid;
      if (row.plainPin) {
        plainPinRows(row, a, b, rigid);
      } else {
        rigidRows(row, a, b, rigid);
      }
      fillSide(rigid, N, false, onA);
      fillSide(rigid, N, true, onB);
      const LaneVelocities<double> velocities = velocitiesOf(a, b);
      joint.impulses = {};
      for (int r = 0; r < N; ++r) {
        const auto i = std::size_t(r);
        const Jacobian& g = rigid[i].jacobian;
        const double inverseMass = (row.invMassA + row.invMassB) * g.linear.squaredNorm() +
                                   row.invInertiaA * g.angularA * g.angularA +
                                   row.invInertiaB * g.angularB * g.angularB;
        if (inverseMass <= 0) {  // moves nothing: an identity row, cut loose
          onA[i] = {};
          onB[i] = {};
          continue;
        }
        setLane(numbers.diagonal[r][r], lane, -kCompliance * inverseMass);
        setLane(numbers.value[r], lane,
                -(rowSpeed(onA[i][2], onB[i], velocities) + correctionSpeed(errorRate, double(rigid[i].position))));
        joint.impulses[i] = rigid[i].impulse;
        joint.position[i] = rigid[i].position;
      }
    }
    for (int r = 0; r < N; ++r) {
      for (int c = 0; c < 3; ++c) {
        setLane(numbers.side[0][r][c], lane, onA[std::size_t(r)][std::size_t(c)]);
        setLane(numbers.side[1][r][c], lane, onB[std::size_t(r)][std::size_t(c)]);
      }
    }
  }
  coupleSide<T, N, P>(view, k, 0);
  coupleSide<T, N, P>(view, k, 1);
}

// What one side's body adds to the joint's block: a body eliminated first
// its inverse mass through the joint's rows, and a coupling to the joint of
// its parent when that is the joint's parent; a hub its coupling to the
// joint, as the joint's parent or child.
template <class T, int N, int P>
[[gnu::always_inline]] inline void JointTreePass::coupleSide(BatchView<T>& view, std::int32_t k, int side) {
  const JointNode& joint = joints_[std::size_t(view.shape().begin + k)];
  const std::int32_t bodyIndex = joint.bodies[std::size_t(side)];
  if (bodyIndex < 0) return;
  const TreeBody& body = bodies_[std::size_t(bodyIndex)];
  const TreeBodyNumbers<T>& mass = view.bodies[std::size_t(bodyIndex - view.shape().firstBody)];
  TreeNodeNumbers<T>& numbers = view.nodes[std::size_t(k)];
  const T(&rows)[3][3] = numbers.side[side];
  const bool towardsParent = side == joint.parentSide;
  if (body.node >= 0) {
    TreeNodeNumbers<T>& hub = view.nodes[std::size_t(body.node - view.shape().begin)];
    if (!towardsParent) {
      const T inverse = splat<T>(1) / mass.invMass;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) hub.diagonal[i][j] = splat<T>(0);
        hub.value[i] = splat<T>(0);
      }
      hub.diagonal[0][0] = inverse;
      hub.diagonal[1][1] = inverse;
      hub.diagonal[2][2] = mass.hubInertia;
    }
    for (int r = 0; r < N; ++r) {
      for (int c = 0; c < 3; ++c) {
        if (towardsParent) {
          numbers.toParent[r][c] = rows[r][c];
        } else {
          hub.toParent[c][r] = rows[r][c];
        }
      }
    }
    return;
  }
  const T inverseMass[3] = {mass.invMass, mass.invMass, mass.invInertia};
  const T(&parentRows)[3][3] = view.nodes[std::size_t(body.parentJoint - view.shape().begin)].side[body.parentSide];
  for (int i = 0; i < N; ++i) {
    T weighted[3];
    for (int c = 0; c < 3; ++c) weighted[c] = rows[i][c] * inverseMass[c];
    auto dot = [&](const T(&other)[3]) { return weighted[0] * other[0] + weighted[1] * other[1] + weighted[2] * other[2]; };
    for (int j = i; j < N; ++j) {
      const T product = dot(rows[j]);
      numbers.diagonal[i][j] -= product;
      if (j != i) numbers.diagonal[j][i] -= product;
    }
    if (!towardsParent) continue;
    for (int j = 0; j < P; ++j) numbers.toParent[i][j] = -dot(parentRows[j]);
  }
}

// Every block at the sub-step's geometry, parents first: a joint's coupling
// through a body eliminated first reads its parent joint's rows.
template <class T>
void JointTreePass::assemble(BatchView<T>& view, std::span<JointRow> rows, std::span<const SolverState> states,
                             double errorRate) {
  for (std::int32_t node = view.shape().end - 1; node >= view.shape().begin; --node) {
    if (joints_[std::size_t(node)].row < 0) continue;
    withSizes(blocks_[std::size_t(node)], [&](auto n, auto p) {
      assembleJoint<T, n(), p()>(view, node - view.shape().begin, rows, states, errorRate);
    });
  }
}

// The right-hand side alone, on blocks made at this geometry: each used
// row's speed and its correction (none in the push), all lanes at once
// (lane by lane, reading each lane's rows back out of its lanes had been a
// fifth of the pass on the ragdoll pile). Returns whether any row of any
// lane moves.
template <class T>
bool JointTreePass::assembleSpeeds(BatchView<T>& view, std::span<const SolverState> states, double errorRate) {
  bool moving = false;
  for (std::int32_t k = 0; k < view.shape().end - view.shape().begin; ++k) {
    TreeNodeNumbers<T>& numbers = view.nodes[std::size_t(k)];
    for (T& value : numbers.value) value = splat<T>(0);
    if (joints_[std::size_t(view.shape().begin + k)].row < 0) continue;
    const int size = blocks_[std::size_t(view.shape().begin + k)].size;
    // The lanes' joints (none past the batch's groups: no velocity, no
    // rows used).
    const JointNode* laneJoints[kLanesOf<T>];
    for (int lane = 0; lane < kLanesOf<T>; ++lane) {
      laneJoints[lane] =
          lane < view.laneCount ? &joints_[std::size_t(view.lanes[std::size_t(lane)].begin + k)] : nullptr;
    }
    const auto velocityOf = [&](int side, int component) {
      return floatLanesOf<T>([&](int lane) {
        if (laneJoints[lane] == nullptr) return 0.0f;
        const SolverState& state = states[std::size_t(laneJoints[lane]->states[std::size_t(side)])];
        return component < 2 ? state.linearVelocity[component] : state.angularVelocity;
      });
    };
    const LaneVelocities<T> velocities{{{velocityOf(0, 0), velocityOf(0, 1), velocityOf(0, 2)},
                                        {velocityOf(1, 0), velocityOf(1, 1), velocityOf(1, 2)}}};
    const T(&onA)[3][3] = numbers.side[0];
    const T(&onB)[3][3] = numbers.side[1];
    for (int r = 0; r < size; ++r) {
      const T position = lanesOf<T>([&](int lane) {
        return laneJoints[lane] == nullptr ? 0.0 : double(laneJoints[lane]->position[std::size_t(r)]);
      });
      const T used = lanesOf<T>([&](int lane) {
        return laneJoints[lane] != nullptr && laneJoints[lane]->impulses[std::size_t(r)] != nullptr ? 1.0 : 0.0;
      });
      numbers.value[r] = keepWhere(used, -(rowSpeed(onA[r][2], onB[r], velocities) + correctionSpeed(errorRate, position)));
      moving = moving || anyNonZero(numbers.value[r]);
    }
  }
  return moving;
}

// visit(n, p, node, parent) for each node of the batch, with its size and
// its parent's, leaves first (every child before its parent). A root's
// parent is itself, unread.
template <class T, class NodeVisit>
void JointTreePass::forEachNodeLeavesFirst(BatchView<T>& view, NodeVisit&& visit) {
  for (std::int32_t k = 0; k < view.shape().end - view.shape().begin; ++k) {
    const Block& block = blocks_[std::size_t(view.shape().begin + k)];
    TreeNodeNumbers<T>& node = view.nodes[std::size_t(k)];
    TreeNodeNumbers<T>& parent = view.nodes[std::size_t(block.parent >= 0 ? block.parent - view.shape().begin : k)];
    withSizes(block, [&](auto n, auto p) { visit(n, p, node, parent); });
  }
}

// L D L^T of the tree, leaves first: each node keeps D_i^-1 and D_i^-1
// H_{i,parent}, all the substitutions need, and takes its forward
// substitution at once (its children's are in).
template <class T>
void JointTreePass::factorAndReduce(BatchView<T>& view) {
  forEachNodeLeavesFirst(view, [](auto n, auto p, TreeNodeNumbers<T>& node, TreeNodeNumbers<T>& parent) {
    eliminateNode<n(), p()>(node, parent);
    substituteForward<n(), p()>(node, parent);
  });
}

// The forward substitution alone, on factors already made.
template <class T>
void JointTreePass::reduce(BatchView<T>& view) {
  forEachNodeLeavesFirst(view, [](auto n, auto p, TreeNodeNumbers<T>& node, TreeNodeNumbers<T>& parent) {
    substituteForward<n(), p()>(node, parent);
  });
}

// The backward substitution, root first; each node's solution is then
// final: a joint's negated impulses, applied at once (a hub's velocity
// change is unread). Bodies take the velocity change of their joints'
// impulses, summed in double (a light link between two heavily loaded pins
// takes two large, nearly opposite ones); joints' impulses join the warm
// start, except the push's, which belong to pseudo velocities.
template <class T>
void JointTreePass::backSubstituteAndApply(BatchView<T>& view, std::span<SolverState> states, bool keepImpulses) {
  for (TreeBodyNumbers<T>& body : view.bodies) {
    for (T& change : body.change) change = splat<T>(0);
  }
  for (std::int32_t k = view.shape().end - view.shape().begin - 1; k >= 0; --k) {
    const Block& block = blocks_[std::size_t(view.shape().begin + k)];
    TreeNodeNumbers<T>& node = view.nodes[std::size_t(k)];
    const TreeNodeNumbers<T>& parent =
        view.nodes[std::size_t(block.parent >= 0 ? block.parent - view.shape().begin : k)];
    const bool joint = joints_[std::size_t(view.shape().begin + k)].row >= 0;
    withSizes(block, [&](auto n, auto p) {
      T solved[3]{};
      substituteBackward<n(), p()>(node, parent, solved);
      if (joint) applyImpulses<T, n()>(view, k, solved, keepImpulses);
    });
  }
  for (std::size_t b = 0; b < view.bodies.size(); ++b) {
    const TreeBodyNumbers<T>& numbers = view.bodies[b];
    for (int lane = 0; lane < view.laneCount; ++lane) {
      SolverState& state = states[std::size_t(view.lanes[std::size_t(lane)].bodies[b].state)];
      state.linearVelocity += Vec2(Real(laneOf(numbers.change[0], lane)), Real(laneOf(numbers.change[1], lane)));
      state.angularVelocity += Real(laneOf(numbers.change[2], lane));
    }
  }
}

// Inline, so that the solution comes in registers (substituteBackward).
template <class T, int N>
[[gnu::always_inline]] inline void JointTreePass::applyImpulses(BatchView<T>& view, std::int32_t k, const T (&negated)[3], bool keepImpulses) {
  const JointNode& joint = joints_[std::size_t(view.shape().begin + k)];
  const TreeNodeNumbers<T>& numbers = view.nodes[std::size_t(k)];
  for (int side = 0; side < 2; ++side) {
    if (joint.bodies[std::size_t(side)] < 0) continue;
    TreeBodyNumbers<T>& body = view.bodies[std::size_t(joint.bodies[std::size_t(side)] - view.shape().firstBody)];
    const T(&rows)[3][3] = numbers.side[side];
    T push[3] = {splat<T>(0), splat<T>(0), splat<T>(0)};
    for (int r = 0; r < N; ++r) {
      for (int c = 0; c < 3; ++c) push[c] += rows[r][c] * negated[r];
    }
    body.change[0] -= body.invMass * push[0];
    body.change[1] -= body.invMass * push[1];
    body.change[2] -= body.invInertia * push[2];
  }
  if (!keepImpulses) return;
  for (int lane = 0; lane < view.laneCount; ++lane) {
    const JointNode& laneJoint = joints_[std::size_t(view.lanes[std::size_t(lane)].begin + k)];
    for (int r = 0; r < N; ++r) {
      Real* impulse = laneJoint.impulses[std::size_t(r)];
      if (impulse != nullptr) *impulse -= Real(laneOf(negated[r], lane));
    }
  }
}

}  // namespace impulse
