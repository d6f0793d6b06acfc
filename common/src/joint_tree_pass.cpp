#include "joint_tree_pass.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

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

// The speed a row is given to take out its share of position error.
double correctionSpeed(double errorRate, Real position) {
  return std::clamp(errorRate * position, -kMaxCorrectionSpeed, kMaxCorrectionSpeed);
}

bool isBody(std::int32_t state, Real invMass) { return state != 0 && invMass > 0; }
bool hasBodyA(const JointRow& row) { return isBody(row.stateA, row.invMassA); }
bool hasBodyB(const JointRow& row) { return isBody(row.stateB, row.invMassB); }

// The joint's N rows acting on one of its bodies (by vx, vy, w).
template <class SideRows>
void fillSide(const RigidRows& rows, int count, bool sideB, SideRows& side) {
  const double sign = sideB ? 1 : -1;
  for (int r = 0; r < count; ++r) {
    const Jacobian& row = rows[std::size_t(r)].jacobian;
    side[std::size_t(r)] = {sign * row.linear.x(), sign * row.linear.y(),
                            sideB ? double(row.angularB) : -double(row.angularA)};
  }
}

// A row's speed, from its rows on A and B (which hold its float Jacobian
// exactly), worked out in float as the soft rows do: the bench's ragdoll
// pile, whose widest pin gap comes from one moment, opened 14.6 cm instead
// of 5.3 with the speeds in double.
double rowSpeed(const std::array<double, 3>& onA, const std::array<double, 3>& onB, const SolverState& a,
                const SolverState& b) {
  const Jacobian row{Vec2(Real(onB[0]), Real(onB[1])), Real(-onA[2]), Real(onB[2])};
  return velocity(row, a, b);
}

template <int N>
using Square = Eigen::Matrix<double, N, N>;

// The blocks D_i are symmetric: their inverse by cofactors, read from the
// upper triangle.
template <int N>
[[gnu::always_inline]] inline Square<N> symmetricInverse(const Square<N>& a) {
  if constexpr (N == 1) {
    return Square<1>(1 / a(0, 0));
  } else if constexpr (N == 2) {
    const double scale = 1 / (a(0, 0) * a(1, 1) - a(0, 1) * a(0, 1));
    Square<2> inverse;
    inverse << a(1, 1) * scale, -a(0, 1) * scale, -a(0, 1) * scale, a(0, 0) * scale;
    return inverse;
  } else {
    const double xx = a(1, 1) * a(2, 2) - a(1, 2) * a(1, 2);
    const double xy = a(0, 2) * a(1, 2) - a(0, 1) * a(2, 2);
    const double xz = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1);
    const double scale = 1 / (a(0, 0) * xx + a(0, 1) * xy + a(0, 2) * xz);
    const double yy = (a(0, 0) * a(2, 2) - a(0, 2) * a(0, 2)) * scale;
    const double yz = (a(0, 2) * a(0, 1) - a(0, 0) * a(1, 2)) * scale;
    const double zz = (a(0, 0) * a(1, 1) - a(0, 1) * a(0, 1)) * scale;
    Square<3> inverse;
    inverse << xx * scale, xy * scale, xz * scale, xy * scale, yy, yz, xz * scale, yz, zz;
    return inverse;
  }
}

// target -= left^T * right where the product is symmetric (left^T D^-1
// left, left^T M^-1 left): its upper triangle, mirrored.
template <int Cols, class Left, class Right, class Target>
[[gnu::always_inline]] inline void subtractSymmetricProduct(const Left& left, const Right& right, Target& target) {
  for (int i = 0; i < Cols; ++i) {
    for (int j = i; j < Cols; ++j) {
      const double product = left.col(i).dot(right.col(j));
      target(i, j) -= product;
      if (j != i) target(j, i) -= product;
    }
  }
}

// One node's elimination and substitutions, for its size N and its
// parent's P (0: a root), fixed at compile time: a chain's pins are 2 x 2.
template <int N, int P, class Block>
[[gnu::always_inline]] inline void eliminateNode(Block& node, Block& parent) {
  const Square<N> inverse = symmetricInverse<N>(node.diagonal.template topLeftCorner<N, N>());
  node.diagonal.template topLeftCorner<N, N>() = inverse;
  if constexpr (P > 0) {
    const Eigen::Matrix<double, N, P> coupling = node.toParent.template topLeftCorner<N, P>();
    const Eigen::Matrix<double, N, P> lower = inverse * coupling;
    subtractSymmetricProduct<P>(coupling, lower, parent.diagonal);
    node.toParent.template topLeftCorner<N, P>() = lower;
  }
}

template <int N, int P, class Block>
[[gnu::always_inline]] inline void substituteForward(Block& node, Block& parent) {
  const Eigen::Matrix<double, N, 1> reduced = node.value.template head<N>();
  node.value.template head<N>().noalias() = node.diagonal.template topLeftCorner<N, N>() * reduced;
  if constexpr (P > 0) {
    parent.value.template head<P>().noalias() -=
        node.toParent.template topLeftCorner<N, P>().transpose() * reduced;
  }
}

template <int N, int P, class Block>
[[gnu::always_inline]] inline void substituteBackward(Block& node, const Block& parent) {
  if constexpr (P > 0) {
    node.value.template head<N>().noalias() -=
        node.toParent.template topLeftCorner<N, P>() * parent.value.template head<P>();
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
  if (!sameRowsAsOrdered(rows, tasks)) orderAnew(rows, stateCount);
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
  return {begin.nodes, end.nodes,
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

// Solved groups per range when they run side by side: a ragdoll's group
// takes a microsecond or two a pass, a hand-off to a thread about one.
constexpr std::int32_t kGroupsPerRange = 4;

template <class Pass>
void JointTreePass::forEachSolvedGroup(const TaskRunner& tasks, Pass&& pass) {
  tasks.forRanges(std::int32_t(solvedGroups_.size()), kGroupsPerRange, [&](std::int32_t first, std::int32_t last) {
    for (std::int32_t k = first; k < last; ++k) pass(groupAt(std::size_t(solvedGroups_[std::size_t(k)])));
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

// Group by group, so that a group's nodes stay in cache through the passes.
// The factors made here are this geometry's until the positions move: the
// push reuses them, and so does the next sub-step's solve after a relax
// (only velocities change in between).
void JointTreePass::solveGroups(std::span<JointRow> rows, std::span<SolverState> states, double errorRate,
                                const TaskRunner& tasks) {
  const bool factored = factorsCurrent_;
  forEachSolvedGroup(tasks, [&](const GroupView& group) {
    if (factored) {
      if (!assembleSpeeds(group, states, errorRate)) return;  // no row moves: no impulse
      reduce(group);
    } else {
      assemble(group, rows, states, errorRate);
      factorAndReduce(group);
    }
    backSubstituteAndApply(group, states, true);
  });
  factorsCurrent_ = true;
}

void JointTreePass::push(std::span<SolverState> states, const TaskRunner& tasks) {
  forEachSolvedGroup(tasks, [&](const GroupView& group) {
    if (!assembleSpeeds(group, states, 0)) return;  // nothing pushed it: no change
    reduce(group);
    backSubstituteAndApply(group, states, false);
  });
}

// A joint's block at the sub-step's geometry: its rows' compliance, and the
// right-hand side that takes out their share of position error.
template <int N, int P>
void JointTreePass::assembleJoint(std::int32_t node, JointRow& row, std::span<const SolverState> states,
                                  double errorRate) {
  Block& block = blocks_[std::size_t(node)];
  JointNode& joint = joints_[std::size_t(node)];
  const SolverState& a = states[row.stateA];
  const SolverState& b = states[row.stateB];
  RigidRows rigid;
  if (row.plainPin) {
    plainPinRows(row, a, b, rigid);
  } else {
    rigidRows(row, a, b, rigid);
  }
  SideRows& onA = joint.sideJacobian[0];
  SideRows& onB = joint.sideJacobian[1];
  fillSide(rigid, N, false, onA);
  fillSide(rigid, N, true, onB);
  block.diagonal.setIdentity();
  block.value.setZero();
  joint.impulses = {};
  for (int r = 0; r < N; ++r) {
    const auto k = std::size_t(r);
    const Jacobian& g = rigid[k].jacobian;
    const double inverseMass = (row.invMassA + row.invMassB) * g.linear.squaredNorm() +
                               row.invInertiaA * g.angularA * g.angularA +
                               row.invInertiaB * g.angularB * g.angularB;
    if (inverseMass <= 0) {  // moves nothing: an identity row, cut loose
      onA[k] = {};
      onB[k] = {};
      continue;
    }
    block.diagonal(r, r) = -kCompliance * inverseMass;
    block.value(r) = -(rowSpeed(onA[k], onB[k], a, b) + correctionSpeed(errorRate, rigid[k].position));
    joint.impulses[k] = rigid[k].impulse;
    joint.position[k] = rigid[k].position;
  }
  coupleSide<N, P>(node, 0);
  coupleSide<N, P>(node, 1);
}

// What one side's body adds to the joint's block: a body eliminated first
// its inverse mass through the joint's rows, and a coupling to the joint of
// its parent when that is the joint's parent; a hub its coupling to the
// joint, as the joint's parent or child.
template <int N, int P>
[[gnu::always_inline]] inline void JointTreePass::coupleSide(std::int32_t node, int side) {
  Block& block = blocks_[std::size_t(node)];
  const JointNode& joint = joints_[std::size_t(node)];
  if (joint.bodies[std::size_t(side)] < 0) return;
  const TreeBody& body = bodies_[std::size_t(joint.bodies[std::size_t(side)])];
  const SideRows& rows = joint.sideJacobian[std::size_t(side)];
  const bool towardsParent = side == joint.parentSide;
  if (body.node >= 0) {
    Block& hub = blocks_[std::size_t(body.node)];
    if (!towardsParent) {
      // A body that cannot turn has an inertia beyond any lever.
      const double inertia = body.invInertia > 0 ? 1.0 / body.invInertia : 1e30;
      hub.diagonal = Eigen::Vector3d(1.0 / body.invMass, 1.0 / body.invMass, inertia).asDiagonal();
      hub.value.setZero();
    }
    for (int r = 0; r < N; ++r) {
      for (int k = 0; k < 3; ++k) {
        const double entry = rows[std::size_t(r)][std::size_t(k)];
        if (towardsParent) {
          block.toParent(r, k) = entry;
        } else {
          hub.toParent(k, r) = entry;
        }
      }
    }
    return;
  }
  const std::array<double, 3> inverseMass{body.invMass, body.invMass, body.invInertia};
  const SideRows& parentRows =
      joints_[std::size_t(body.parentJoint)].sideJacobian[std::size_t(body.parentSide)];
  for (int i = 0; i < N; ++i) {
    std::array<double, 3> weighted;
    for (std::size_t k = 0; k < 3; ++k) weighted[k] = rows[std::size_t(i)][k] * inverseMass[k];
    auto dot = [&](const std::array<double, 3>& other) {
      return weighted[0] * other[0] + weighted[1] * other[1] + weighted[2] * other[2];
    };
    for (int j = i; j < N; ++j) {
      const double product = dot(rows[std::size_t(j)]);
      block.diagonal(i, j) -= product;
      if (j != i) block.diagonal(j, i) -= product;
    }
    if (!towardsParent) continue;
    for (int j = 0; j < P; ++j) block.toParent(i, j) = -dot(parentRows[std::size_t(j)]);
  }
}

// Every block at the sub-step's geometry, parents first: a joint's coupling
// through a body eliminated first reads its parent joint's rows.
void JointTreePass::assemble(const GroupView& group, std::span<JointRow> rows,
                             std::span<const SolverState> states, double errorRate) {
  for (std::int32_t node = group.end - 1; node >= group.begin; --node) {
    const std::int32_t row = joints_[std::size_t(node)].row;
    if (row < 0) continue;
    withSizes(blocks_[std::size_t(node)], [&](auto n, auto p) {
      assembleJoint<n(), p()>(node, rows[std::size_t(row)], states, errorRate);
    });
  }
}

// The right-hand side alone, on blocks made at this geometry: each used
// row's speed and its correction (none in the push). Returns whether any
// row moves.
bool JointTreePass::assembleSpeeds(const GroupView& group, std::span<const SolverState> states,
                                   double errorRate) {
  bool moving = false;
  for (std::int32_t node = group.begin; node < group.end; ++node) {
    Block& block = blocks_[std::size_t(node)];
    const JointNode& joint = joints_[std::size_t(node)];
    block.value.setZero();
    if (joint.row < 0) continue;
    const SolverState& a = states[std::size_t(joint.states[0])];
    const SolverState& b = states[std::size_t(joint.states[1])];
    for (int r = 0; r < block.size; ++r) {
      const auto k = std::size_t(r);
      if (joint.impulses[k] == nullptr) continue;
      block.value(r) = -(rowSpeed(joint.sideJacobian[0][k], joint.sideJacobian[1][k], a, b) +
                         correctionSpeed(errorRate, joint.position[k]));
      moving = moving || block.value(r) != 0;
    }
  }
  return moving;
}

// L D L^T of the tree, leaves first (every child before its parent): each
// node keeps D_i^-1 and D_i^-1 H_{i,parent}, all the substitutions need,
// and takes its forward substitution at once (its children's are in). A
// root's parent is itself, unread.
void JointTreePass::factorAndReduce(const GroupView& group) {
  for (std::int32_t node = group.begin; node < group.end; ++node) {
    Block& block = blocks_[std::size_t(node)];
    Block& parent = blocks_[std::size_t(block.parent >= 0 ? block.parent : node)];
    withSizes(block, [&](auto n, auto p) {
      eliminateNode<n(), p()>(block, parent);
      substituteForward<n(), p()>(block, parent);
    });
  }
}

// The forward substitution alone, on factors already made.
void JointTreePass::reduce(const GroupView& group) {
  for (std::int32_t node = group.begin; node < group.end; ++node) {
    Block& block = blocks_[std::size_t(node)];
    Block& parent = blocks_[std::size_t(block.parent >= 0 ? block.parent : node)];
    withSizes(block, [&](auto n, auto p) { substituteForward<n(), p()>(block, parent); });
  }
}

// The backward substitution, root first; each node's solution is then
// final: a joint's negated impulses, applied at once (a hub's velocity
// change is unread). Bodies take the velocity change of their joints'
// impulses, summed in double (a light link between two heavily loaded pins
// takes two large, nearly opposite ones); joints' impulses join the warm
// start, except the push's, which belong to pseudo velocities.
void JointTreePass::backSubstituteAndApply(const GroupView& group, std::span<SolverState> states,
                                           bool keepImpulses) {
  for (TreeBody& body : group.bodies) body.change.setZero();
  for (std::int32_t node = group.end - 1; node >= group.begin; --node) {
    Block& block = blocks_[std::size_t(node)];
    const Block& parent = blocks_[std::size_t(block.parent >= 0 ? block.parent : node)];
    const JointNode& joint = joints_[std::size_t(node)];
    withSizes(block, [&](auto n, auto p) {
      substituteBackward<n(), p()>(block, parent);
      if (joint.row >= 0) applyImpulses<n()>(joint, block.value, keepImpulses);
    });
  }
  for (const TreeBody& body : group.bodies) {
    SolverState& state = states[body.state];
    state.linearVelocity += Vec2(Real(body.change(0)), Real(body.change(1)));
    state.angularVelocity += Real(body.change(2));
  }
}

template <int N>
void JointTreePass::applyImpulses(const JointNode& joint, const Eigen::Vector3d& negated, bool keepImpulses) {
  for (int side = 0; side < 2; ++side) {
    if (joint.bodies[std::size_t(side)] < 0) continue;
    TreeBody& body = bodies_[std::size_t(joint.bodies[std::size_t(side)])];
    const SideRows& rows = joint.sideJacobian[std::size_t(side)];
    std::array<double, 3> push{};
    for (int r = 0; r < N; ++r) {
      for (std::size_t k = 0; k < 3; ++k) push[k] += rows[std::size_t(r)][k] * negated(r);
    }
    body.change(0) -= body.invMass * push[0];
    body.change(1) -= body.invMass * push[1];
    body.change(2) -= body.invInertia * push[2];
  }
  if (!keepImpulses) return;
  for (int r = 0; r < N; ++r) {
    if (joint.impulses[std::size_t(r)] != nullptr) *joint.impulses[std::size_t(r)] -= Real(negated(r));
  }
}

}  // namespace impulse
