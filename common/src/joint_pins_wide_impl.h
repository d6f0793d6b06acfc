#pragma once
// The plain pins' passes (joint_pins.h) for any lane type F, included by
// contact_solver_wide_impl.h (after its gather and scatter) into the file of
// each width. A block of eight is solved as 8 / F::kLanes runs of F's lanes.
// Every expression follows its scalar twin in joint_rows.cpp (frameOf,
// applyPoint, pointInverseMass, pointVelocity, solve22, pointRow) operation
// for operation, negations included (x * -1 keeps a zero's sign as the
// scalar minus does; 0 - x would not), so a pin's bits do not depend on
// which path solved it.

#include <span>

#include "joint_pins.h"

namespace impulse {
namespace {

template <class F>
struct PinLanes {
  std::int32_t first = 0;  ///< the block's lane where these start
  F invMassA, invInertiaA, invMassB, invInertiaB;
  F anchorAX, anchorAY, anchorBX, anchorBY;
  F centerX, centerY;
};

template <class F>
PinLanes<F> loadPinLanes(const PinBlock& block, int first) {
  return {first,
          simd::load<F>(block.invMassA + first),
          simd::load<F>(block.invInertiaA + first),
          simd::load<F>(block.invMassB + first),
          simd::load<F>(block.invInertiaB + first),
          simd::load<F>(block.anchorAX + first),
          simd::load<F>(block.anchorAY + first),
          simd::load<F>(block.anchorBX + first),
          simd::load<F>(block.anchorBY + first),
          simd::load<F>(block.centerX + first),
          simd::load<F>(block.centerY + first)};
}

template <class F>
F negated(F x) {
  return x * simd::broadcast<F>(-1);
}

/// frameOf: the anchors turned by the sub-step's rotations, and B's anchor
/// minus A's.
template <class F>
struct PinFrame {
  F rAx, rAy, rBx, rBy, dx, dy;
};

template <class F>
PinFrame<F> pinFrame(const PinLanes<F>& p, const WideBody<F>& a, const WideBody<F>& b) {
  PinFrame<F> f;
  f.rAx = a.dqc * p.anchorAX - a.dqs * p.anchorAY;
  f.rAy = a.dqs * p.anchorAX + a.dqc * p.anchorAY;
  f.rBx = b.dqc * p.anchorBX - b.dqs * p.anchorBY;
  f.rBy = b.dqs * p.anchorBX + b.dqc * p.anchorBY;
  f.dx = (((b.dpx - a.dpx) + p.centerX) + f.rBx) - f.rAx;
  f.dy = (((b.dpy - a.dpy) + p.centerY) + f.rBy) - f.rAy;
  return f;
}

/// applyPoint.
template <class F>
void applyPinImpulse(const PinLanes<F>& p, const PinFrame<F>& f, F ix, F iy, WideBody<F>& a, WideBody<F>& b) {
  applyPointImpulse(a, b, {p.invMassA, p.invInertiaA, p.invMassB, p.invInertiaB}, f.rAx, f.rAy, f.rBx, f.rBy, ix, iy);
}

/// The impulse solving pointInverseMass(row, f) * impulse = v (solve22):
/// zero where that matrix is singular.
template <class F>
void solvePinMatrix(const PinLanes<F>& p, const PinFrame<F>& f, F vx, F vy, F& sx, F& sy) {
  const F m = p.invMassA + p.invMassB;
  const F k00 = (m + (p.invInertiaA * f.rAy) * f.rAy) + (p.invInertiaB * f.rBy) * f.rBy;
  const F k01 = ((negated(p.invInertiaA) * f.rAx) * f.rAy) - ((p.invInertiaB * f.rBx) * f.rBy);
  const F k11 = (m + (p.invInertiaA * f.rAx) * f.rAx) + (p.invInertiaB * f.rBx) * f.rBx;
  const F det = k00 * k11 - k01 * k01;
  const F inv = simd::broadcast<F>(1) / det;
  const F regular = simd::notEqual(det, simd::broadcast<F>(0));
  sx = simd::select(regular, inv * (k11 * vx - k01 * vy), simd::broadcast<F>(0));
  sy = simd::select(regular, inv * (k00 * vy - k01 * vx), simd::broadcast<F>(0));
}

template <class F, class Run>
void forEachPinRun(std::span<SolverState> states, std::span<PinBlock> blocks, Run&& run) {
  for (PinBlock& block : blocks) {
    for (int first = 0; first < PinBlock::kLanes; first += F::kLanes) {
      const PinLanes<F> p = loadPinLanes<F>(block, first);
      WideBody<F> a = gather<F>(states, block.stateA + first);
      WideBody<F> b = gather<F>(states, block.stateB + first);
      run(block, p, pinFrame(p, a, b), a, b);
      scatter<F>(states, block.stateA + first, a);
      scatter<F>(states, block.stateB + first, b);
    }
  }
}

template <class F>
void warmStartPins(std::span<SolverState> states, std::span<PinBlock> blocks) {
  forEachPinRun<F>(states, blocks,
                   [](PinBlock& block, const PinLanes<F>& p, const PinFrame<F>& f, WideBody<F>& a, WideBody<F>& b) {
                     applyPinImpulse(p, f, simd::load<F>(block.impulseX + p.first), simd::load<F>(block.impulseY + p.first),
                                     a, b);
                   });
}

/// pointRow for a rigid point of softness `soft` (unbounded).
template <class F>
void solvePins(std::span<SolverState> states, std::span<PinBlock> blocks, const Softness& soft) {
  const F biasRate = simd::broadcast<F>(soft.biasRate);
  const F negativeMassScale = simd::broadcast<F>(-soft.massScale);
  const F impulseScale = simd::broadcast<F>(soft.impulseScale);
  forEachPinRun<F>(states, blocks, [&](PinBlock& block, const PinLanes<F>& p, const PinFrame<F>& f, WideBody<F>& a,
                                       WideBody<F>& b) {
    const F vx = (((b.vx + negated(b.w) * f.rBy) - a.vx) - negated(a.w) * f.rAy) + biasRate * f.dx;
    const F vy = (((b.vy + b.w * f.rBx) - a.vy) - a.w * f.rAx) + biasRate * f.dy;
    F sx, sy;
    solvePinMatrix(p, f, vx, vy, sx, sy);
    const F accumulatedX = simd::load<F>(block.impulseX + p.first);
    const F accumulatedY = simd::load<F>(block.impulseY + p.first);
    const F nextX = accumulatedX + (negativeMassScale * sx - impulseScale * accumulatedX);
    const F nextY = accumulatedY + (negativeMassScale * sy - impulseScale * accumulatedY);
    applyPinImpulse(p, f, nextX - accumulatedX, nextY - accumulatedY, a, b);
    simd::store(block.impulseX + p.first, nextX);
    simd::store(block.impulseY + p.first, nextY);
  });
}

}  // namespace
}  // namespace impulse
