#pragma once
// Plain pins (JointRow::plainPin: a revolute joint and nothing else, the
// joint of chains and grids) and revolute joints with a limit, motor or
// spring (ragdolls) eight at a time. A block holds eight joints of one
// colour column by column, so the wide kernels (joint_pins_wide_impl.h)
// load each field of four or eight joints at once and gather their bodies
// the way the contact bundles do. Each lane does the scalar rows'
// arithmetic (joint_rows.cpp) in the same order: a joint gives the same
// bits solved here or one by one.

#include <cstdint>
#include <span>

#include "joint_row.h"

namespace impulse {

/// Where a block's joints are: eight lanes, column by column.
struct alignas(32) PinGeometry {
  static constexpr int kLanes = 8;
  /// Lanes past the colour's last joint: the static dummy state, no mass.
  std::int32_t stateA[kLanes] = {};
  std::int32_t stateB[kLanes] = {};
  /// The lane's JointRow; -1 for an empty lane.
  std::int32_t row[kLanes] = {-1, -1, -1, -1, -1, -1, -1, -1};
  Real invMassA[kLanes] = {};
  Real invInertiaA[kLanes] = {};
  Real invMassB[kLanes] = {};
  Real invInertiaB[kLanes] = {};
  Real anchorAX[kLanes] = {};
  Real anchorAY[kLanes] = {};
  Real anchorBX[kLanes] = {};
  Real anchorBY[kLanes] = {};
  Real centerX[kLanes] = {};  ///< B's centre minus A's at step start
  Real centerY[kLanes] = {};
};

struct alignas(32) PinBlock {
  static constexpr int kLanes = PinGeometry::kLanes;
  PinGeometry pin;
  /// Accumulated over the step, warm started; back into the rows at its end.
  Real impulseX[kLanes] = {};
  Real impulseY[kLanes] = {};
};

/// Puts `row` (rows' entry rowIndex) in the geometry's `lane`.
inline void placeGeometry(PinGeometry& pin, int lane, const JointRow& row, std::int32_t rowIndex) {
  pin.stateA[lane] = row.stateA;
  pin.stateB[lane] = row.stateB;
  pin.row[lane] = rowIndex;
  pin.invMassA[lane] = row.invMassA;
  pin.invInertiaA[lane] = row.invInertiaA;
  pin.invMassB[lane] = row.invMassB;
  pin.invInertiaB[lane] = row.invInertiaB;
  pin.anchorAX[lane] = row.anchorA.x();
  pin.anchorAY[lane] = row.anchorA.y();
  pin.anchorBX[lane] = row.anchorB.x();
  pin.anchorBY[lane] = row.anchorB.y();
  pin.centerX[lane] = row.deltaCenter.x();
  pin.centerY[lane] = row.deltaCenter.y();
}

/// Puts `row` (rows' entry rowIndex, a plain pin) in the block's `lane`.
inline void placePin(PinBlock& block, int lane, const JointRow& row, std::int32_t rowIndex) {
  placeGeometry(block.pin, lane, row, rowIndex);
  block.impulseX[lane] = row.impulses.point.x();
  block.impulseY[lane] = row.impulses.point.y();
}

/// The block's pins' impulses back into `rows`.
inline void storePinImpulses(const PinBlock& block, std::span<JointRow> rows) {
  for (int lane = 0; lane < PinBlock::kLanes && block.pin.row[lane] >= 0; ++lane) {
    rows[std::size_t(block.pin.row[lane])].impulses.point = Vec2(block.impulseX[lane], block.impulseY[lane]);
  }
}

/// Plain pins the tree pass solves (JointRow::inTree), eight at a time: the
/// geometry alone, as the pins' impulses stay in their JointRows, where the
/// tree pass reads and writes them during the step. Their warm start, and
/// the relax of those the tree pass does not relax exactly, run as a
/// PinBlock's.
struct alignas(32) TreePinBlock {
  static constexpr int kLanes = PinGeometry::kLanes;
  PinGeometry pin;
};

/// Revolute joints with a limit, a motor or a spring (every ragdoll joint),
/// eight at a time: the pin as in PinBlock, then each lane's turning rows
/// (joint_rows.cpp's solveKind for a revolute joint, row for row). What a
/// row's arithmetic takes from the joint's settings and masses alone is
/// worked out once a step, by the scalar rows' own functions (placeRevolute).
/// The pin's impulse stays in the JointRow: the tree pass
/// (joint_tree_pass.h) reads and writes it during the step.
struct alignas(32) RevoluteBlock {
  static constexpr int kLanes = PinGeometry::kLanes;
  PinGeometry pin;
  Real startAngle[kLanes] = {};     ///< JointRow::deltaAngle
  Real turnMass[kLanes] = {};       ///< effective mass of the turn row
  Real reverseMass[kLanes] = {};    ///< and of its negation (the upper limit)
  Real springStep[kLanes] = {};     ///< h * stiffness
  Real springWeight[kLanes] = {};   ///< springVelocityWeight
  Real springDivisor[kLanes] = {};  ///< turnMass + springWeight
  Real motorSpeed[kLanes] = {};
  Real maxMotorImpulse[kLanes] = {};
  Real lowerAngle[kLanes] = {};
  Real upperAngle[kLanes] = {};
  /// The turning rows' impulses over the step (warm started; back into the
  /// rows at its end). The pin's stays in its JointRow.
  Real angularImpulse[kLanes] = {};
  Real axialImpulse[kLanes] = {};
  Real springImpulse[kLanes] = {};
  Real motorImpulse[kLanes] = {};
  Real lowerImpulse[kLanes] = {};
  Real upperImpulse[kLanes] = {};
  /// Per lane, which rows it has, and whether the biased pass solves its pin
  /// (the tree pass holds the pins of its groups there): masks, all bits
  /// set where so. Lane by lane, not bits of one byte: the lanes of a block
  /// are filled side by side.
  Real springOn[kLanes] = {};
  Real motorOn[kLanes] = {};
  Real limitOn[kLanes] = {};
  Real biasedPinOn[kLanes] = {};
  bool needsAngle[kLanes] = {};
};

/// Whether a row goes in a RevoluteBlock: a revolute joint that is not a
/// plain pin.
bool isTurningRevolute(const JointRow& row);
/// Puts `row` (rows' entry rowIndex, isTurningRevolute) in the block's
/// `lane`, for sub-steps of `h` (joint_rows.cpp).
void placeRevolute(RevoluteBlock& block, int lane, const JointRow& row, std::int32_t rowIndex,
                   Real h);
/// The block's turning rows' impulses back into `rows` (the pins' are there).
void storeRevoluteImpulses(const RevoluteBlock& block, std::span<JointRow> rows);

}  // namespace impulse
