// Plain pins, and revolute joints with limits, motors and springs, solved
// eight at a time (joint_pins.h) give the bits the scalar rows give
// (joint_rows.cpp), at every lane width the CPU runs: the wide kernels are
// an evaluation order, not an approximation.

#include "joint_pins.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "contact_solver_wide.h"
#include "joint_constraints.h"
#include "joint_data.h"

namespace impulse {
namespace {

constexpr Real kH = Real(1.0 / 240);

// Pins of one colour: row i joins states 2i + 1 and 2i + 2; every third row
// holds its body to the world (the static dummy, state 0) instead.
struct PinScene {
  std::vector<JointRow> rows;
  std::vector<SolverState> states;
};

PinScene makeScene(int pinCount, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> any(-2, 2);
  std::uniform_real_distribution<Real> positive(Real(0.1), 3);
  PinScene scene;
  scene.states.resize(std::size_t(2 * pinCount + 1));
  for (std::size_t i = 1; i < scene.states.size(); ++i) {
    SolverState& s = scene.states[i];
    s.linearVelocity = Vec2(any(random), any(random));
    s.angularVelocity = any(random);
    s.deltaPosition = Vec2(any(random), any(random)) * Real(0.01);
    const Real turn = any(random) * Real(0.05);
    s.deltaRotation = {std::cos(turn), std::sin(turn)};
  }
  for (int i = 0; i < pinCount; ++i) {
    JointRow row;
    row.plainPin = true;
    const bool toWorld = i % 3 == 2;
    row.stateA = toWorld ? 0 : 2 * i + 1;
    row.stateB = 2 * i + 2;
    row.invMassA = toWorld ? 0 : positive(random);
    row.invInertiaA = toWorld ? 0 : positive(random);
    row.invMassB = positive(random);
    row.invInertiaB = positive(random);
    row.anchorA = Vec2(any(random), any(random));
    row.anchorB = Vec2(any(random), any(random));
    row.deltaCenter = row.anchorA - row.anchorB + Vec2(any(random), any(random)) * Real(0.01);
    row.impulses.point = Vec2(any(random), any(random));
    scene.rows.push_back(row);
  }
  return scene;
}

std::vector<PinBlock> blocksOf(const std::vector<JointRow>& rows) {
  std::vector<PinBlock> blocks((rows.size() + PinBlock::kLanes - 1) / PinBlock::kLanes);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    placePin(blocks[r / PinBlock::kLanes], int(r % PinBlock::kLanes), rows[r], std::int32_t(r));
  }
  return blocks;
}

// The scalar rows, as the joint solver visits them (state 0 through a copy).
template <class Visit>
void forEachRow(PinScene& scene, Visit&& visit) {
  SolverState sink = scene.states[0];
  for (JointRow& row : scene.rows) {
    visit(row, row.stateA != 0 ? scene.states[std::size_t(row.stateA)] : sink,
          scene.states[std::size_t(row.stateB)]);
  }
}

void expectSameBits(const PinScene& scalar, const std::vector<SolverState>& wideStates,
                    const std::vector<PinBlock>& blocks, const char* stage) {
  ASSERT_EQ(
      std::memcmp(scalar.states.data(), wideStates.data(), wideStates.size() * sizeof(SolverState)),
      0)
      << "states differ after " << stage;
  for (std::size_t r = 0; r < scalar.rows.size(); ++r) {
    const PinBlock& block = blocks[r / PinBlock::kLanes];
    const int lane = int(r % PinBlock::kLanes);
    const Vec2 wide(block.impulseX[lane], block.impulseY[lane]);
    ASSERT_EQ(std::memcmp(&wide, &scalar.rows[r].impulses.point, sizeof(Vec2)), 0)
        << "pin " << r << "'s impulse differs after " << stage;
  }
}

void checkKernels(const WideContactKernels& kernels) {
  // 29 pins: three full blocks and one with three empty lanes.
  PinScene scalar = makeScene(29, 11);
  std::vector<SolverState> wideStates = scalar.states;
  std::vector<PinBlock> blocks = blocksOf(scalar.rows);
  JointPass pass = jointPassAt(kH);

  forEachRow(scalar, [](JointRow& row, SolverState& a, SolverState& b) { warmStartJoint(row, a, b); });
  kernels.warmStartPins(wideStates, blocks);
  expectSameBits(scalar, wideStates, blocks, "the warm start");
  for (int iteration = 0; iteration < 4; ++iteration) {
    for (bool useBias : {true, false}) {
      pass.useBias = useBias;
      forEachRow(scalar, [&](JointRow& row, SolverState& a, SolverState& b) { solveJoint(row, a, b, pass); });
      kernels.solvePins(wideStates, blocks, rowSoftness(pass));
      expectSameBits(scalar, wideStates, blocks, useBias ? "a biased pass" : "a relax pass");
    }
  }
  // The pins really moved their bodies: the check compares something.
  EXPECT_NE(std::memcmp(scalar.states.data(), makeScene(29, 11).states.data(), wideStates.size() * sizeof(SolverState)),
            0);
}

TEST(JointPins, FourLanes_GiveTheScalarRowsBits) { checkKernels(sse2WideContactKernels()); }

TEST(JointPins, WidestLanes_GiveTheScalarRowsBits) { checkKernels(wideContactKernels(SimdWidth::Best)); }

// Revolute joints with every mix of limit, motor and spring: row i's
// settings are bits of i (a spring, a motor, a limit), the limits tight
// enough that some are reached and some not, the motors weak enough that
// some saturate; every fourth row's pin belongs to the tree pass (which the
// biased pass leaves alone). Joint angles from the states' turns and the
// joints' start angles.
struct RevoluteScene {
  PinScene pins;
  std::vector<Joint> joints;
};

RevoluteScene makeRevoluteScene(int jointCount, unsigned seed) {
  RevoluteScene scene{makeScene(jointCount, seed), std::vector<Joint>(std::size_t(jointCount))};
  std::mt19937 random(seed + 1);
  std::uniform_real_distribution<Real> any(-1, 1);
  for (int i = 0; i < jointCount; ++i) {
    RevoluteJointSettings settings;
    settings.stiffness = (i & 1) != 0 ? Real(40) * (1 + any(random)) : 0;
    settings.damping = (i & 1) != 0 ? Real(0.5) : 0;
    settings.enableMotor = (i & 2) != 0;
    settings.motorSpeed = any(random);
    settings.maxMotorTorque = Real(20) * (1 + any(random));
    settings.enableLimit = (i & 4) != 0 || i % 7 == 0;
    settings.lowerAngle = Real(-0.05) + Real(0.05) * any(random);
    settings.upperAngle = Real(0.05) + Real(0.05) * any(random);
    Joint& joint = scene.joints[std::size_t(i)];
    joint.settings = settings;
    JointRow& row = scene.pins.rows[std::size_t(i)];
    row.joint = &joint;
    row.plainPin = false;
    row.softRows = true;
    row.inTree = i % 4 == 1;
    row.deltaAngle = Real(0.08) * any(random);
    row.impulses.motor = Real(0.1) * any(random);
    row.impulses.lower = std::max(any(random), Real(0));
    row.impulses.upper = std::max(any(random), Real(0));
  }
  return scene;
}

std::vector<RevoluteBlock> revoluteBlocksOf(const std::vector<JointRow>& rows) {
  std::vector<RevoluteBlock> blocks((rows.size() + RevoluteBlock::kLanes - 1) /
                                    RevoluteBlock::kLanes);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    placeRevolute(blocks[r / RevoluteBlock::kLanes], int(r % RevoluteBlock::kLanes), rows[r],
                  std::int32_t(r), kH);
  }
  return blocks;
}

void expectSameRevoluteBits(const PinScene& scalar, const std::vector<SolverState>& wideStates,
                            std::vector<JointRow>& wideRows,
                            const std::vector<RevoluteBlock>& blocks, const char* stage) {
  ASSERT_EQ(
      std::memcmp(scalar.states.data(), wideStates.data(), wideStates.size() * sizeof(SolverState)),
      0)
      << "states differ after " << stage;
  for (const RevoluteBlock& block : blocks) storeRevoluteImpulses(block, wideRows);
  for (std::size_t r = 0; r < scalar.rows.size(); ++r) {
    ASSERT_EQ(std::memcmp(&wideRows[r].impulses, &scalar.rows[r].impulses, sizeof(JointImpulses)),
              0)
        << "joint " << r << "'s impulses differ after " << stage;
  }
}

void checkRevoluteKernels(const WideContactKernels& kernels) {
  // 45 joints: five full blocks and one with three empty lanes.
  RevoluteScene scalar = makeRevoluteScene(45, 5);
  std::vector<SolverState> wideStates = scalar.pins.states;
  std::vector<JointRow> wideRows = scalar.pins.rows;
  std::vector<RevoluteBlock> blocks = revoluteBlocksOf(wideRows);
  JointPass pass = jointPassAt(kH);

  forEachRow(scalar.pins,
             [](JointRow& row, SolverState& a, SolverState& b) { warmStartJoint(row, a, b); });
  kernels.warmStartRevolutes(wideStates, blocks, wideRows);
  expectSameRevoluteBits(scalar.pins, wideStates, wideRows, blocks, "the warm start");
  for (int iteration = 0; iteration < 4; ++iteration) {
    for (bool useBias : {true, false}) {
      pass.useBias = useBias;
      forEachRow(scalar.pins, [&](JointRow& row, SolverState& a, SolverState& b) {
        solveJoint(row, a, b, pass);
      });
      kernels.solveRevolutes(wideStates, blocks, wideRows, pass);
      expectSameRevoluteBits(scalar.pins, wideStates, wideRows, blocks,
                             useBias ? "a biased pass" : "a relax pass");
    }
  }
  // Every kind of row acted: the check compares something.
  const auto acted = [&](auto impulseOf) {
    return std::any_of(scalar.pins.rows.begin(), scalar.pins.rows.end(),
                       [&](const JointRow& row) { return impulseOf(row.impulses) != 0; });
  };
  EXPECT_TRUE(acted([](const JointImpulses& i) { return i.spring; }));
  EXPECT_TRUE(acted([](const JointImpulses& i) { return i.motor; }));
  EXPECT_TRUE(acted([](const JointImpulses& i) { return i.lower; }));
  EXPECT_TRUE(acted([](const JointImpulses& i) { return i.upper; }));
  EXPECT_TRUE(
      std::any_of(scalar.pins.rows.begin(), scalar.pins.rows.end(),
                  [](const JointRow& row) {
                    const Real maxImpulse =
                        kH * std::get<RevoluteJointSettings>(row.joint->settings).maxMotorTorque;
                    return std::get<RevoluteJointSettings>(row.joint->settings).enableMotor &&
                           std::abs(row.impulses.motor) == maxImpulse;
                  }))
      << "no motor saturated";
}

TEST(JointPins, RevolutesOnFourLanes_GiveTheScalarRowsBits) {
  checkRevoluteKernels(sse2WideContactKernels());
}

TEST(JointPins, RevolutesOnWidestLanes_GiveTheScalarRowsBits) {
  checkRevoluteKernels(wideContactKernels(SimdWidth::Best));
}

}  // namespace
}  // namespace impulse
