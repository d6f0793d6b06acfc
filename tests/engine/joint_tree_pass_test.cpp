// The joint tree pass (joint_tree_pass.h) solves [M G^T; G -eps] of a tree
// of bodies and joints exactly: its relax gives the impulses and velocities
// a dense solve of the same system gives, whichever way it eliminates the
// tree (bodies with one or two joints folded into their joints, hubs with
// more kept as nodes), for every kind of rigid row.

#include "joint_tree_pass.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstring>
#include <deque>
#include <random>
#include <vector>

#include "joint_data.h"
#include "task_runner.h"

namespace impulse {
namespace {

constexpr Real kH = Real(1.0 / 240);
// The pass's own regularisation: each row gives way by this share of its
// inverse mass (joint_tree_pass.cpp).
constexpr double kCompliance = 1e-5;

struct TreeScene {
  std::deque<Joint> joints;  // stable addresses: rows point at them
  std::vector<JointRow> rows;
  std::vector<SolverState> states;
};

class SceneBuilder {
 public:
  explicit SceneBuilder(unsigned seed, int bodies) : random_(seed) {
    scene_.states.resize(std::size_t(bodies) + 1);  // state 0: the world
    invMass_.assign(scene_.states.size(), 0);
    invInertia_.assign(scene_.states.size(), 0);
    for (std::size_t s = 1; s < scene_.states.size(); ++s) {
      SolverState& state = scene_.states[s];
      state.linearVelocity = Vec2(any(), any());
      state.angularVelocity = any();
      state.deltaPosition = Vec2(any(), any()) * Real(0.01);
      const Real turn = any() * Real(0.05);
      state.deltaRotation = {std::cos(turn), std::sin(turn)};
      // Masses from 0.03 to 30 kg: a heavy weight on light links.
      invMass_[s] = std::pow(Real(10), any() * Real(0.75));
      invInertia_[s] = invMass_[s] * std::pow(Real(10), any() * Real(0.5));
    }
  }

  void join(int a, int b, const JointSettings& settings) {
    Joint& joint = scene_.joints.emplace_back();
    joint.settings = settings;
    joint.length = Real(0.5);
    JointRow row;
    row.joint = &joint;
    row.index = std::int32_t(scene_.rows.size());
    row.stateA = a;
    row.stateB = b;
    row.invMassA = invMass_[std::size_t(a)];
    row.invInertiaA = invInertia_[std::size_t(a)];
    row.invMassB = invMass_[std::size_t(b)];
    row.invInertiaB = invInertia_[std::size_t(b)];
    row.anchorA = Vec2(any(), any()) * Real(0.3);
    row.anchorB = Vec2(any(), any()) * Real(0.3);
    row.deltaCenter = row.anchorA - row.anchorB + Vec2(any(), any()) * Real(0.01);
    row.axis = Vec2(1, any()).normalized();
    row.lastAxis = row.axis;
    row.plainPin = std::holds_alternative<RevoluteJointSettings>(settings);
    row.touches = true;  // every group gets the exact pass
    RigidRows scratch;
    row.rigidRowCount = rigidRows(row, SolverState{}, SolverState{}, scratch);
    scene_.rows.push_back(row);
  }

  TreeScene take() { return std::move(scene_); }

 private:
  Real any() { return std::uniform_real_distribution<Real>(-1, 1)(random_); }

  std::mt19937 random_;
  TreeScene scene_;
  std::vector<Real> invMass_;
  std::vector<Real> invInertia_;
};

// Two groups. Held by the world: a pin to the world, then a pin and a weld
// to a hub (body 3, four joints) with a distance rod and a pin chain, a
// leaf and a prismatic slide off it. Free: a hub (body 10) with three pin
// chains, one of them two links long and ending in a weld.
TreeScene makeTree(unsigned seed) {
  SceneBuilder build(seed, 15);
  const RevoluteJointSettings pin;
  build.join(1, 0, pin);
  build.join(1, 2, pin);
  build.join(2, 3, WeldJointSettings{});
  build.join(3, 4, pin);
  build.join(4, 7, DistanceJointSettings{});
  build.join(7, 8, pin);
  build.join(5, 3, pin);
  build.join(3, 6, PrismaticJointSettings{});
  build.join(6, 9, pin);
  build.join(10, 11, pin);
  build.join(12, 10, pin);
  build.join(10, 13, pin);
  build.join(11, 14, pin);
  build.join(14, 15, WeldJointSettings{});
  return build.take();
}

// Each body's inverse mass (m, m, I) from the rows that reach it.
Eigen::VectorXd inverseMasses(const TreeScene& scene) {
  Eigen::VectorXd inverse = Eigen::VectorXd::Zero(Eigen::Index(3 * scene.states.size()));
  for (const JointRow& row : scene.rows) {
    inverse.segment<3>(3 * row.stateA) << row.invMassA, row.invMassA, row.invInertiaA;
    inverse.segment<3>(3 * row.stateB) << row.invMassB, row.invMassB, row.invInertiaB;
  }
  inverse.head<3>().setZero();  // the world
  return inverse;
}

Eigen::VectorXd velocities(const std::vector<SolverState>& states) {
  Eigen::VectorXd v(Eigen::Index(3 * states.size()));
  for (std::size_t s = 0; s < states.size(); ++s) {
    v.segment<3>(Eigen::Index(3 * s)) << states[s].linearVelocity.x(), states[s].linearVelocity.y(),
        states[s].angularVelocity;
  }
  return v;
}

TEST(JointTreePass, RelaxOnTreesOfEveryRowKind_GivesTheDenseSolvesImpulsesAndVelocities) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    TreeScene scene = makeTree(seed);
    // Every row's Jacobian at the states' geometry, and where its impulse
    // accumulates.
    std::vector<RigidRow> rigid;
    for (JointRow& row : scene.rows) {
      RigidRows rows;
      const int count = rigidRows(row, scene.states[row.stateA], scene.states[row.stateB], rows);
      rigid.insert(rigid.end(), rows.begin(), rows.begin() + count);
    }
    const Eigen::VectorXd inverseMass = inverseMasses(scene);
    const auto rowCount = Eigen::Index(rigid.size());
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(rowCount, inverseMass.size());
    std::size_t k = 0;
    for (const JointRow& row : scene.rows) {
      for (int r = 0; r < row.rigidRowCount; ++r, ++k) {
        const Jacobian& j = rigid[k].jacobian;
        const auto i = Eigen::Index(k);
        g.block<1, 3>(i, 3 * row.stateA) << -j.linear.x(), -j.linear.y(), -j.angularA;
        g.block<1, 3>(i, 3 * row.stateB) << j.linear.x(), j.linear.y(), j.angularB;
      }
    }
    g.leftCols<3>().setZero();  // the world takes nothing
    const Eigen::VectorXd v0 = velocities(scene.states);
    Eigen::MatrixXd system = g * inverseMass.asDiagonal() * g.transpose();
    system.diagonal() += kCompliance * system.diagonal();
    const Eigen::VectorXd impulse = system.ldlt().solve(-g * v0);
    const Eigen::VectorXd expected = v0 + inverseMass.asDiagonal() * (g.transpose() * impulse);

    std::vector<Real> before;
    for (const RigidRow& row : rigid) before.push_back(*row.impulse);
    TaskRunner tasks;
    JointTreePass pass;
    pass.order(scene.rows, scene.states.size(), makeSoftness(60, 2, kH), tasks);
    ASSERT_EQ(pass.jointCount(), int(scene.rows.size()));
    pass.relax(scene.rows, scene.states, tasks);

    const double largestImpulse = impulse.cwiseAbs().maxCoeff();
    for (std::size_t r = 0; r < rigid.size(); ++r) {
      EXPECT_NEAR(*rigid[r].impulse - before[r], impulse(Eigen::Index(r)), 1e-5 * largestImpulse) << "row " << r;
    }
    const Eigen::VectorXd v1 = velocities(scene.states);
    const double largestSpeed = v0.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 3; i < v1.size(); ++i) EXPECT_NEAR(v1(i), expected(i), 1e-5 * largestSpeed) << "dof " << i;
  }
}

// `copies` copies of a scene side by side: copy c's bodies are states
// c * n + 1 to (c + 1) * n, the world's is still 0.
TreeScene copiesOf(const TreeScene& scene, int copies) {
  const auto bodies = std::int32_t(scene.states.size()) - 1;
  TreeScene copied;
  copied.states.push_back(scene.states[0]);
  for (int c = 0; c < copies; ++c) {
    copied.states.insert(copied.states.end(), scene.states.begin() + 1, scene.states.end());
    for (const JointRow& original : scene.rows) {
      JointRow row = original;
      row.joint = &copied.joints.emplace_back(*original.joint);
      row.index = std::int32_t(copied.rows.size());
      if (row.stateA != 0) row.stateA += c * bodies;
      if (row.stateB != 0) row.stateB += c * bodies;
      copied.rows.push_back(row);
    }
  }
  return copied;
}

// A sub-step of the pass as the solver runs it: the solve with position
// correction, the push on (here, the same) velocities, the relax.
void runSubStep(JointTreePass& pass, TreeScene& scene, const TaskRunner& tasks) {
  pass.order(scene.rows, scene.states.size(), makeSoftness(60, 2, kH), tasks);
  pass.solve(scene.rows, scene.states, kH, tasks);
  pass.push(scene.states, tasks);
  pass.relax(scene.rows, scene.states, tasks);
}

bool sameBits(Real a, Real b) { return std::memcmp(&a, &b, sizeof(Real)) == 0; }

// Five copies of each group: four are solved side by side in the lanes of
// one batch, the fifth alone, in double. Every copy ends with the bits of
// the scene solved on its own.
TEST(JointTreePass, GroupsOfOneShapeSolvedSideBySide_EndWithTheBitsOfOneSolvedAlone) {
  constexpr int kCopies = 5;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(seed);
    TreeScene alone = makeTree(seed);
    TreeScene copies = copiesOf(alone, kCopies);
    TaskRunner tasks;
    JointTreePass alonePass;
    JointTreePass copiesPass;
    for (int subStep = 0; subStep < 3; ++subStep) {
      runSubStep(alonePass, alone, tasks);
      runSubStep(copiesPass, copies, tasks);
    }
    const std::size_t bodies = alone.states.size() - 1;
    for (int c = 0; c < kCopies; ++c) {
      for (std::size_t s = 1; s <= bodies; ++s) {
        const SolverState& expected = alone.states[s];
        const SolverState& copy = copies.states[std::size_t(c) * bodies + s];
        EXPECT_TRUE(sameBits(copy.linearVelocity.x(), expected.linearVelocity.x()) &&
                    sameBits(copy.linearVelocity.y(), expected.linearVelocity.y()) &&
                    sameBits(copy.angularVelocity, expected.angularVelocity))
            << "copy " << c << " body " << s;
      }
      for (std::size_t r = 0; r < alone.rows.size(); ++r) {
        const JointImpulses& expected = alone.rows[r].joint->impulses;
        const JointImpulses& copy = copies.rows[std::size_t(c) * alone.rows.size() + r].joint->impulses;
        EXPECT_TRUE(sameBits(copy.point.x(), expected.point.x()) && sameBits(copy.point.y(), expected.point.y()) &&
                    sameBits(copy.perpendicular, expected.perpendicular) && sameBits(copy.angular, expected.angular) &&
                    sameBits(copy.axial, expected.axial))
            << "copy " << c << " joint " << r;
      }
    }
  }
}

}  // namespace
}  // namespace impulse
