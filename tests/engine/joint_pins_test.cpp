// Plain pins solved eight at a time (joint_pins.h) give the bits the scalar
// rows give (joint_rows.cpp), at every lane width the CPU runs: the wide
// kernels are an evaluation order, not an approximation.

#include "joint_pins.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "contact_solver_wide.h"

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
  ASSERT_EQ(std::memcmp(scalar.states.data(), wideStates.data(), wideStates.size() * sizeof(SolverState)), 0)
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
  JointPass pass{kH, 1 / kH, makeSoftness(Real(0.25) / kH, 2, kH), true};

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

}  // namespace
}  // namespace impulse
