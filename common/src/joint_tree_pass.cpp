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

// The joint's rows acting on one of its bodies (3 rows by vx, vy, w).
Eigen::Matrix3d jacobianOn(const RigidRows& rows, int count, bool sideB) {
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  for (int r = 0; r < count; ++r) {
    const Jacobian& row = rows[r].jacobian;
    const double sign = sideB ? 1 : -1;
    g(r, 0) = sign * row.linear.x();
    g(r, 1) = sign * row.linear.y();
    g(r, 2) = sideB ? row.angularB : -row.angularA;
  }
  return g;
}

// The blocks D_i are symmetric: their inverse by cofactors, six of them.
Eigen::Matrix3d symmetricInverse(const Eigen::Matrix3d& a) {
  const double xx = a(1, 1) * a(2, 2) - a(1, 2) * a(1, 2);
  const double xy = a(0, 2) * a(1, 2) - a(0, 1) * a(2, 2);
  const double xz = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1);
  const double scale = 1 / (a(0, 0) * xx + a(0, 1) * xy + a(0, 2) * xz);
  const double yy = (a(0, 0) * a(2, 2) - a(0, 2) * a(0, 2)) * scale;
  const double yz = (a(0, 2) * a(0, 1) - a(0, 0) * a(1, 2)) * scale;
  const double zz = (a(0, 0) * a(1, 1) - a(0, 1) * a(0, 1)) * scale;
  Eigen::Matrix3d inverse;
  inverse << xx * scale, xy * scale, xz * scale, xy * scale, yy, yz, xz * scale, yz, zz;
  return inverse;
}

// target -= coupling^T * lower, which is symmetric (coupling^T D^-1
// coupling): six dot products instead of nine.
void subtractSymmetricProduct(const Eigen::Matrix3d& coupling, const Eigen::Matrix3d& lower,
                              Eigen::Matrix3d& target) {
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      const double product = coupling.col(i).dot(lower.col(j));
      target(i, j) -= product;
      if (j != i) target(j, i) -= product;
    }
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
  std::size_t begin = 0;
  for (std::size_t g = 0; g < groupEnds_.size(); ++g) {
    const std::span<const Node> group(nodes_.data() + begin, std::size_t(groupEnds_[g]) - begin);
    begin = std::size_t(groupEnds_[g]);
    if (!needsExactPass(group, rows, compliance)) continue;
    solvedGroups_.push_back(std::int32_t(g));
    for (const Node& node : group) {
      if (!node.isJoint) continue;
      rows[node.row].inTree = true;
      ++jointCount_;
    }
  }
}

// A group held by the world (a chain, a bridge, a pendulum, a crane) hangs
// its weight on its joints all the time, and swings through unloaded
// moments: it is always solved exactly. So is a group touching anything: a
// contact loads its joints in the step it begins, before any load is
// measured. A group in flight is measured: each joint's linear load last
// step (its stored impulses, warm started or not) over its rows' effective
// mass, the pair's masses taken as points.
bool JointTreePass::needsExactPass(std::span<const Node> group, std::span<const JointRow> rows, Real compliance) {
  // The walk roots a group at a joint to the world when it has one.
  const Node& root = group.back();
  if (root.sides[0] < 0 || root.sides[1] < 0) return true;
  Real give = 0;
  for (const Node& node : group) {
    if (!node.isJoint) continue;
    const JointRow& row = rows[node.row];
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
  jointsStart_.assign(stateCount + 1, 0);
  loopBodies_.clear();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const JointRow& row = rows[r];
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

void JointTreePass::storeReversed(std::span<const JointRow> rows) {
  const auto base = static_cast<std::int32_t>(nodes_.size());
  const auto last = static_cast<std::int32_t>(walk_.size()) - 1;
  auto nodeOf = [&](std::int32_t walked) { return walked < 0 ? -1 : base + last - walked; };
  for (std::int32_t at = last; at >= 0; --at) {
    const Visit& visit = walk_[at];
    Node node;
    node.parent = nodeOf(visit.parent);
    node.state = visit.state;
    node.row = visit.row;
    node.isJoint = visit.row >= 0;
    if (node.isJoint) {
      const JointRow& row = rows[visit.row];
      if (hasBodyA(row)) node.sides[0] = nodeOf(bodyVisit_[row.stateA]);
      if (hasBodyB(row)) node.sides[1] = nodeOf(bodyVisit_[row.stateB]);
    } else {
      node.mass = bodyMass(rows, visit);
    }
    nodes_.push_back(node);
  }
  groupEnds_.push_back(static_cast<std::int32_t>(nodes_.size()));
}

// m, m and I of a body, from the joint that reached it or that it reached.
Eigen::Vector3d JointTreePass::bodyMass(std::span<const JointRow> rows, const Visit& body) const {
  const Visit& joint = walk_[body.parent];
  const JointRow& row = rows[joint.row];
  const bool sideB = row.stateB == body.state;
  const Real invMass = sideB ? row.invMassB : row.invMassA;
  const Real invInertia = sideB ? row.invInertiaB : row.invInertiaA;
  // A body that cannot turn has an inertia beyond any lever.
  return {1.0 / invMass, 1.0 / invMass, invInertia > 0 ? 1.0 / invInertia : 1e30};
}

// Solved groups per range when they run side by side: a ragdoll's group
// takes a microsecond or two a pass, a hand-off to a thread about one.
constexpr std::int32_t kGroupsPerRange = 4;

template <class Pass>
void JointTreePass::forEachSolvedGroup(const TaskRunner& tasks, Pass&& pass) {
  tasks.forRanges(std::int32_t(solvedGroups_.size()), kGroupsPerRange, [&](std::int32_t first, std::int32_t last) {
    for (std::int32_t k = first; k < last; ++k) {
      const auto g = std::size_t(solvedGroups_[std::size_t(k)]);
      const auto begin = std::size_t(g == 0 ? 0 : groupEnds_[g - 1]);
      pass(std::span<Node>(nodes_).subspan(begin, std::size_t(groupEnds_[g]) - begin));
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

// Group by group, so that a group's nodes stay in cache through the passes.
// The factors made here are this geometry's until the positions move: the
// push reuses them, and so does the next sub-step's solve after a relax
// (only velocities change in between).
void JointTreePass::solveGroups(std::span<JointRow> rows, std::span<SolverState> states, double errorRate,
                                const TaskRunner& tasks) {
  const bool factored = factorsCurrent_;
  forEachSolvedGroup(tasks, [&](std::span<Node> group) {
    if (factored) {
      assembleCorrectedSpeeds(group, rows, states, errorRate);
    } else {
      assemble(group, rows, states, errorRate);
      factor(group);
    }
    substitute(group);
    applyVelocities(group, states, true);
  });
  factorsCurrent_ = true;
}

void JointTreePass::push(std::span<const JointRow> rows, std::span<SolverState> states,
                         const TaskRunner& tasks) {
  forEachSolvedGroup(tasks, [&](std::span<Node> group) {
    if (!assembleSpeeds(group, rows, states)) return;  // nothing pushed it: no change
    substitute(group);
    applyVelocities(group, states, false);
  });
}

void JointTreePass::assembleJoint(Node& node, JointRow& row, std::span<const SolverState> states,
                                  double errorRate) {
  const SolverState& a = states[row.stateA];
  const SolverState& b = states[row.stateB];
  RigidRows rigid;
  const int count = rigidRows(row, a, b, rigid);
  std::array<Eigen::Matrix3d, 2> jacobians{jacobianOn(rigid, count, false),
                                           jacobianOn(rigid, count, true)};
  node.diagonal = Eigen::Matrix3d::Identity();
  node.value.setZero();
  node.impulses = {};
  for (int r = 0; r < count; ++r) {
    const Jacobian& g = rigid[r].jacobian;
    const double inverseMass = (row.invMassA + row.invMassB) * g.linear.squaredNorm() +
                               row.invInertiaA * g.angularA * g.angularA +
                               row.invInertiaB * g.angularB * g.angularB;
    if (inverseMass <= 0) {  // moves nothing: an identity row, cut loose
      jacobians[0].row(r).setZero();
      jacobians[1].row(r).setZero();
      continue;
    }
    node.diagonal(r, r) = -kCompliance * inverseMass;
    node.value(r) = -(velocity(g, a, b) + correctionSpeed(errorRate, rigid[r].position));
    node.impulses[r] = rigid[r].impulse;
    node.jacobian[r] = g;
  }
  // The joint's rows couple it to its parent body, or its child bodies to it.
  for (std::size_t side = 0; side < 2; ++side) {
    const std::int32_t body = node.sides[side];
    if (body < 0) continue;
    if (body == node.parent) {
      node.toParent = jacobians[side];
    } else {
      nodes_[body].toParent = jacobians[side].transpose();
    }
  }
}

// H_ii, H_{i,parent} and the right-hand side at the sub-step's geometry.
void JointTreePass::assemble(std::span<Node> group, std::span<JointRow> rows,
                             std::span<const SolverState> states, double errorRate) {
  for (Node& node : group) {
    if (node.isJoint) {
      assembleJoint(node, rows[node.row], states, errorRate);
    } else {
      node.diagonal = node.mass.asDiagonal();
      node.value.setZero();
    }
  }
}

// The push's right-hand side: each used row's speed, without correction.
// Returns whether any row moves.
void JointTreePass::assembleCorrectedSpeeds(std::span<Node> group, std::span<JointRow> rows,
                                            std::span<const SolverState> states, double errorRate) {
  for (Node& node : group) {
    node.value.setZero();
    if (!node.isJoint) continue;
    JointRow& row = rows[node.row];
    const SolverState& a = states[row.stateA];
    const SolverState& b = states[row.stateB];
    RigidRows rigid;
    rigidRows(row, a, b, rigid);
    for (int r = 0; r < 3; ++r) {
      if (node.impulses[r] == nullptr) continue;
      node.value(r) = -(velocity(node.jacobian[r], a, b) + correctionSpeed(errorRate, rigid[r].position));
    }
  }
}

bool JointTreePass::assembleSpeeds(std::span<Node> group, std::span<const JointRow> rows,
                                   std::span<const SolverState> states) {
  bool moving = false;
  for (Node& node : group) {
    node.value.setZero();
    if (!node.isJoint) continue;
    const JointRow& row = rows[node.row];
    const SolverState& a = states[row.stateA];
    const SolverState& b = states[row.stateB];
    for (int r = 0; r < 3; ++r) {
      if (node.impulses[r] == nullptr) continue;
      node.value(r) = -velocity(node.jacobian[r], a, b);
      moving = moving || node.value(r) != 0;
    }
  }
  return moving;
}

// L D L^T of the tree, leaves first (every child before its parent): each
// node keeps D_i^-1 and D_i^-1 H_{i,parent}, all the substitutions need.
void JointTreePass::factor(std::span<Node> group) {
  for (Node& node : group) {
    node.diagonal = symmetricInverse(node.diagonal);
    if (node.parent < 0) continue;
    const Eigen::Matrix3d lower = node.diagonal * node.toParent;
    subtractSymmetricProduct(node.toParent, lower, nodes_[node.parent].diagonal);
    node.toParent = lower;
  }
}

// The two substitutions; the solution replaces each node's value: a body's
// velocity change, a joint's negated impulses.
void JointTreePass::substitute(std::span<Node> group) {
  for (Node& node : group) {
    const Eigen::Vector3d reduced = node.value;
    node.value.noalias() = node.diagonal * reduced;
    if (node.parent >= 0) nodes_[node.parent].value.noalias() -= node.toParent.transpose() * reduced;
  }
  for (auto node = group.rbegin(); node != group.rend(); ++node) {
    if (node->parent >= 0) node->value.noalias() -= node->toParent * nodes_[node->parent].value;
  }
}

// Bodies take their velocity change; joints' impulses join the warm start,
// except the push's, which belong to pseudo velocities.
void JointTreePass::applyVelocities(std::span<const Node> group, std::span<SolverState> states,
                                    bool keepImpulses) {
  for (const Node& node : group) {
    if (!node.isJoint) {
      SolverState& state = states[node.state];
      state.linearVelocity += Vec2(Real(node.value(0)), Real(node.value(1)));
      state.angularVelocity += Real(node.value(2));
      continue;
    }
    if (!keepImpulses) continue;
    for (int r = 0; r < 3; ++r) {
      if (node.impulses[r] != nullptr) *node.impulses[r] -= Real(node.value(r));
    }
  }
}

}  // namespace impulse
