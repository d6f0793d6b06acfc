#pragma once
// Plain pins (JointRow::plainPin: a revolute joint and nothing else, the
// joint of chains, ragdolls and grids) eight at a time. A block holds eight
// pins of one colour column by column, so the wide kernels
// (joint_pins_wide_impl.h) load each field of four or eight pins at once
// and gather their bodies the way the contact bundles do. Each lane does
// the scalar rows' arithmetic (joint_rows.cpp) in the same order: a pin
// gives the same bits solved here or one by one.

#include <cstdint>

#include "joint_row.h"

namespace impulse {

struct alignas(32) PinBlock {
  static constexpr int kLanes = 8;
  /// Lanes past the colour's last pin: the static dummy state, no mass.
  std::int32_t stateA[kLanes] = {};
  std::int32_t stateB[kLanes] = {};
  /// The lane's JointRow, where its impulse goes back after the step; -1
  /// for an empty lane.
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
  Real impulseX[kLanes] = {};  ///< accumulated over the step, warm started
  Real impulseY[kLanes] = {};
};

/// Puts `row` (rows' entry rowIndex, a plain pin) in the block's `lane`.
inline void placePin(PinBlock& block, int lane, const JointRow& row, std::int32_t rowIndex) {
  block.stateA[lane] = row.stateA;
  block.stateB[lane] = row.stateB;
  block.row[lane] = rowIndex;
  block.invMassA[lane] = row.invMassA;
  block.invInertiaA[lane] = row.invInertiaA;
  block.invMassB[lane] = row.invMassB;
  block.invInertiaB[lane] = row.invInertiaB;
  block.anchorAX[lane] = row.anchorA.x();
  block.anchorAY[lane] = row.anchorA.y();
  block.anchorBX[lane] = row.anchorB.x();
  block.anchorBY[lane] = row.anchorB.y();
  block.centerX[lane] = row.deltaCenter.x();
  block.centerY[lane] = row.deltaCenter.y();
  block.impulseX[lane] = row.impulses.point.x();
  block.impulseY[lane] = row.impulses.point.y();
}

}  // namespace impulse
