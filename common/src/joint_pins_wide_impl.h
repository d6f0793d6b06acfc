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
PinLanes<F> loadPinLanes(const PinGeometry& pin, int first) {
  return {first,
          simd::load<F>(pin.invMassA + first),
          simd::load<F>(pin.invInertiaA + first),
          simd::load<F>(pin.invMassB + first),
          simd::load<F>(pin.invInertiaB + first),
          simd::load<F>(pin.anchorAX + first),
          simd::load<F>(pin.anchorAY + first),
          simd::load<F>(pin.anchorBX + first),
          simd::load<F>(pin.anchorBY + first),
          simd::load<F>(pin.centerX + first),
          simd::load<F>(pin.centerY + first)};
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

// run(block, lanes, frame, a, b) on each run of F's lanes of each block
// (PinBlock or RevoluteBlock), its bodies gathered before and scattered after.
template <class F, class Block, class Run>
void forEachPinRun(std::span<SolverState> states, std::span<Block> blocks, Run&& run) {
  for (Block& block : blocks) {
    const PinGeometry& pin = block.pin;
    for (int first = 0; first < PinGeometry::kLanes; first += F::kLanes) {
      const PinLanes<F> p = loadPinLanes<F>(pin, first);
      WideBody<F> a = gather<F>(states, pin.stateA + first);
      WideBody<F> b = gather<F>(states, pin.stateB + first);
      run(block, p, pinFrame(p, a, b), a, b);
      scatter<F>(states, pin.stateA + first, a);
      scatter<F>(states, pin.stateB + first, b);
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

/// The point row's step: rigidPoint's pointRow (unbounded) at `soft`, from
/// the accumulated impulse (ax, ay); returns the next one.
template <class F>
struct PinStep {
  F nextX, nextY;
};

template <class F>
PinStep<F> stepPin(const PinLanes<F>& p, const PinFrame<F>& f, const WideBody<F>& a,
                   const WideBody<F>& b, const Softness& soft, F ax, F ay) {
  const F biasRate = simd::broadcast<F>(soft.biasRate);
  const F negativeMassScale = simd::broadcast<F>(-soft.massScale);
  const F impulseScale = simd::broadcast<F>(soft.impulseScale);
  const F vx = (((b.vx + negated(b.w) * f.rBy) - a.vx) - negated(a.w) * f.rAy) + biasRate * f.dx;
  const F vy = (((b.vy + b.w * f.rBx) - a.vy) - a.w * f.rAx) + biasRate * f.dy;
  F sx, sy;
  solvePinMatrix(p, f, vx, vy, sx, sy);
  return {ax + (negativeMassScale * sx - impulseScale * ax),
          ay + (negativeMassScale * sy - impulseScale * ay)};
}

/// pointRow for a rigid point of softness `soft` (unbounded).
template <class F>
void solvePins(std::span<SolverState> states, std::span<PinBlock> blocks, const Softness& soft) {
  forEachPinRun<F>(states, blocks,
                   [&](PinBlock& block, const PinLanes<F>& p, const PinFrame<F>& f, WideBody<F>& a,
                       WideBody<F>& b) {
                     const F accumulatedX = simd::load<F>(block.impulseX + p.first);
                     const F accumulatedY = simd::load<F>(block.impulseY + p.first);
                     const PinStep<F> next = stepPin(p, f, a, b, soft, accumulatedX, accumulatedY);
                     applyPinImpulse(p, f, next.nextX - accumulatedX, next.nextY - accumulatedY, a,
                                     b);
                     simd::store(block.impulseX + p.first, next.nextX);
                     simd::store(block.impulseY + p.first, next.nextY);
                   });
}

/// The pins' accumulated impulses of a run of lanes where they stay in the
/// JointRows (the tree pass reads and writes them there): gathered lane by
/// lane, zero for an empty lane.
template <class F>
struct PointImpulses {
  F x, y;
};

template <class F>
PointImpulses<F> loadPointImpulses(const PinGeometry& pin, int first, std::span<const JointRow> rows) {
  float x[F::kLanes] = {};
  float y[F::kLanes] = {};
  for (int l = 0; l < F::kLanes; ++l) {
    const std::int32_t r = pin.row[first + l];
    if (r < 0) continue;
    const Vec2& point = rows[std::size_t(r)].impulses.point;
    x[l] = point.x();
    y[l] = point.y();
  }
  return {simd::load<F>(x), simd::load<F>(y)};
}

template <class F>
void storePointImpulses(const PinGeometry& pin, int first, const PointImpulses<F>& impulses,
                        std::span<JointRow> rows) {
  float x[F::kLanes];
  float y[F::kLanes];
  simd::store(x, impulses.x);
  simd::store(y, impulses.y);
  for (int l = 0; l < F::kLanes; ++l) {
    const std::int32_t r = pin.row[first + l];
    if (r >= 0) rows[std::size_t(r)].impulses.point = Vec2(x[l], y[l]);
  }
}

// ---- plain pins of the tree pass (TreePinBlock) ------------------------------

template <class F>
void warmStartTreePins(std::span<SolverState> states, std::span<TreePinBlock> blocks,
                       std::span<JointRow> rows) {
  forEachPinRun<F>(states, blocks,
                   [&](TreePinBlock& block, const PinLanes<F>& p, const PinFrame<F>& f, WideBody<F>& a,
                       WideBody<F>& b) {
                     const PointImpulses<F> i = loadPointImpulses<F>(block.pin, p.first, rows);
                     applyPinImpulse(p, f, i.x, i.y, a, b);
                   });
}

/// solvePins on pins whose impulses stay in `rows`.
template <class F>
void solveTreePins(std::span<SolverState> states, std::span<TreePinBlock> blocks, std::span<JointRow> rows,
                   const Softness& soft) {
  forEachPinRun<F>(states, blocks,
                   [&](TreePinBlock& block, const PinLanes<F>& p, const PinFrame<F>& f, WideBody<F>& a,
                       WideBody<F>& b) {
                     const PointImpulses<F> i = loadPointImpulses<F>(block.pin, p.first, rows);
                     const PinStep<F> next = stepPin(p, f, a, b, soft, i.x, i.y);
                     applyPinImpulse(p, f, next.nextX - i.x, next.nextY - i.y, a, b);
                     storePointImpulses<F>(block.pin, p.first, {next.nextX, next.nextY}, rows);
                   });
}

// ---- revolute joints with turning rows (RevoluteBlock) ----------------------

/// The turn row's Jacobian (angularJacobian or its negation): a zero
/// linear part (negated: minus zero, whose sign the scalar arithmetic
/// carries) and +-1 on both angular velocities.
template <class F>
struct TurnJacobian {
  F linear;
  F angular;
};

template <class F>
TurnJacobian<F> turnJacobian(bool reversed) {
  return {simd::broadcast<F>(reversed ? -0.0f : 0.0f), simd::broadcast<F>(reversed ? -1.0f : 1.0f)};
}

/// velocity(j, a, b).
template <class F>
[[gnu::always_inline]] inline F turnVelocity(const TurnJacobian<F>& j, const WideBody<F>& a,
                                             const WideBody<F>& b) {
  const F linear = j.linear * (b.vx - a.vx) + j.linear * (b.vy - a.vy);
  return (linear + j.angular * b.w) - j.angular * a.w;
}

/// apply(row, j, impulse) on the lanes of `on`; like the scalar, a zero
/// impulse changes nothing (not even a zero's sign).
template <class F>
[[gnu::always_inline]] inline void applyTurn(const PinLanes<F>& p, const TurnJacobian<F>& j,
                                             F impulse, F on, WideBody<F>& a, WideBody<F>& b) {
  const F acts = simd::both(on, simd::notEqual(impulse, simd::broadcast<F>(0)));
  const F linearA = p.invMassA * impulse;
  const F linearB = p.invMassB * impulse;
  a.vx = simd::select(acts, a.vx - linearA * j.linear, a.vx);
  a.vy = simd::select(acts, a.vy - linearA * j.linear, a.vy);
  a.w = simd::select(acts, a.w - (p.invInertiaA * impulse) * j.angular, a.w);
  b.vx = simd::select(acts, b.vx + linearB * j.linear, b.vx);
  b.vy = simd::select(acts, b.vy + linearB * j.linear, b.vy);
  b.w = simd::select(acts, b.w + (p.invInertiaB * impulse) * j.angular, b.w);
}

/// A lane's impulses: the pin's gathered from its JointRow (the tree pass
/// works on it there during the step) and scattered back, the others the
/// block's columns.
template <class F>
struct TurnImpulses {
  F pointX, pointY, angular, axial, spring, motor, lower, upper;
};

template <class F>
TurnImpulses<F> loadImpulses(const RevoluteBlock& block, int first,
                             std::span<const JointRow> rows) {
  const PointImpulses<F> point = loadPointImpulses<F>(block.pin, first, rows);
  return {point.x,
          point.y,
          simd::load<F>(block.angularImpulse + first),
          simd::load<F>(block.axialImpulse + first),
          simd::load<F>(block.springImpulse + first),
          simd::load<F>(block.motorImpulse + first),
          simd::load<F>(block.lowerImpulse + first),
          simd::load<F>(block.upperImpulse + first)};
}

/// Writes back what the solve changes: the pin's, spring's, motor's and
/// limits' impulses.
template <class F>
void storeImpulses(RevoluteBlock& block, int first, const TurnImpulses<F>& impulses,
                   std::span<JointRow> rows) {
  storePointImpulses<F>(block.pin, first, {impulses.pointX, impulses.pointY}, rows);
  simd::store(block.springImpulse + first, impulses.spring);
  simd::store(block.motorImpulse + first, impulses.motor);
  simd::store(block.lowerImpulse + first, impulses.lower);
  simd::store(block.upperImpulse + first, impulses.upper);
}

/// Frame::angle() on the lanes that read it (needsAngle), zero on the others; atan2 lane by
/// lane, the scalar call itself.
template <class F>
F jointAngles(const RevoluteBlock& block, int first, const WideBody<F>& a, const WideBody<F>& b) {
  float c[F::kLanes];
  float s[F::kLanes];
  simd::store(c, a.dqc * b.dqc + a.dqs * b.dqs);
  simd::store(s, a.dqc * b.dqs - a.dqs * b.dqc);
  float angle[F::kLanes] = {};
  for (int l = 0; l < F::kLanes; ++l) {
    if (block.needsAngle[first + l])
      angle[l] = block.startAngle[first + l] + Rot{c[l], s[l]}.angle();
  }
  return simd::load<F>(angle);
}

template <class F>
void warmStartRevolutes(std::span<SolverState> states, std::span<RevoluteBlock> blocks,
                        std::span<JointRow> rows) {
  const TurnJacobian<F> turn = turnJacobian<F>(false);
  const F all = simd::maskOfBits<F>(0xff);
  forEachPinRun<F>(states, blocks,
                   [&](RevoluteBlock& block, const PinLanes<F>& p, const PinFrame<F>& f,
                       WideBody<F>& a, WideBody<F>& b) {
                     const TurnImpulses<F> i = loadImpulses<F>(block, p.first, rows);
                     applyPinImpulse(p, f, i.pointX, i.pointY, a, b);
                     applyTurn(p, turn, i.angular, all, a, b);
                     applyTurn(p, turn, (i.axial + i.lower) - i.upper, all, a, b);
                     applyTurn(p, turn, i.motor, all, a, b);
                   });
}

/// springRow on the turn row, at the block's spring constants.
template <class F>
[[gnu::always_inline]] inline void turnSpring(const RevoluteBlock& block, const PinLanes<F>& p,
                                              F angle, F on, TurnImpulses<F>& i, WideBody<F>& a,
                                              WideBody<F>& b) {
  const TurnJacobian<F> turn = turnJacobian<F>(false);
  const int first = p.first;
  const F mass = simd::load<F>(block.turnMass + first);
  const F drive = simd::load<F>(block.springStep + first) * angle +
                  simd::load<F>(block.springWeight + first) * turnVelocity(turn, a, b);
  const F impulse = (negated(drive) * mass) / simd::load<F>(block.springDivisor + first);
  i.spring = simd::select(on, impulse, i.spring);
  applyTurn(p, turn, impulse, on, a, b);
}

/// motorRow on the turn row; std::clamp's comparisons, in its order.
template <class F>
[[gnu::always_inline]] inline void turnMotor(const RevoluteBlock& block, const PinLanes<F>& p, F on,
                                             TurnImpulses<F>& i, WideBody<F>& a, WideBody<F>& b) {
  const TurnJacobian<F> turn = turnJacobian<F>(false);
  const int first = p.first;
  const F maxImpulse = simd::load<F>(block.maxMotorImpulse + first);
  const F impulse = negated(simd::load<F>(block.turnMass + first)) *
                    (turnVelocity(turn, a, b) - simd::load<F>(block.motorSpeed + first));
  const F sum = i.motor + impulse;
  const F floor = negated(maxImpulse);
  const F raised = simd::select(simd::less(sum, floor), floor, sum);
  const F next = simd::select(simd::less(maxImpulse, raised), maxImpulse, raised);
  applyTurn(p, turn, next - i.motor, on, a, b);
  i.motor = simd::select(on, next, i.motor);
}

/// limitRow on the turn row (`reversed`: its negation) keeping c >= 0.
template <class F>
[[gnu::always_inline]] inline void turnLimit(const PinLanes<F>& p, bool reversed, F mass, F c,
                                             const JointPass& pass, F on, F& accumulated,
                                             WideBody<F>& a, WideBody<F>& b) {
  const TurnJacobian<F> turn = turnJacobian<F>(reversed);
  const Softness soft = rowSoftness(pass);
  const F zero = simd::broadcast<F>(0);
  const F open = simd::greater(c, zero);
  const F bias =
      simd::select(open, c * simd::broadcast<F>(pass.invH), simd::broadcast<F>(soft.biasRate) * c);
  const F massScale = simd::select(open, simd::broadcast<F>(1), simd::broadcast<F>(soft.massScale));
  const F impulseScale = simd::select(open, zero, simd::broadcast<F>(soft.impulseScale));
  const F impulse = ((negated(mass) * massScale) * (turnVelocity(turn, a, b) + bias)) -
                    impulseScale * accumulated;
  const F sum = accumulated + impulse;
  const F next = simd::select(simd::less(sum, zero), zero, sum);
  applyTurn(p, turn, next - accumulated, on, a, b);
  accumulated = simd::select(on, next, accumulated);
}

/// The velocities of `from` on the lanes of `on`.
template <class F>
void keepLanes(F on, const WideBody<F>& from, WideBody<F>& body) {
  body.vx = simd::select(on, from.vx, body.vx);
  body.vy = simd::select(on, from.vy, body.vy);
  body.w = simd::select(on, from.w, body.w);
}

/// solveKind for a revolute joint, row for row: spring (biased pass only),
/// motor, lower and upper limit, then the pin (left to the tree pass in the
/// biased pass where it holds it).
template <class F>
void solveRevolutes(std::span<SolverState> states, std::span<RevoluteBlock> blocks,
                    std::span<JointRow> rows, const JointPass& pass) {
  const Softness soft = rowSoftness(pass);
  forEachPinRun<F>(
      states, blocks,
      [&](RevoluteBlock& block, const PinLanes<F>& p, const PinFrame<F>& f, WideBody<F>& a,
          WideBody<F>& b) {
        const int first = p.first;
        TurnImpulses<F> i = loadImpulses<F>(block, first, rows);
        const F angle = jointAngles(block, first, a, b);
        if (pass.useBias) turnSpring(block, p, angle, simd::load<F>(block.springOn + first), i, a, b);
        turnMotor(block, p, simd::load<F>(block.motorOn + first), i, a, b);
        const F limits = simd::load<F>(block.limitOn + first);
        turnLimit(p, false, simd::load<F>(block.turnMass + first),
                  angle - simd::load<F>(block.lowerAngle + first), pass, limits, i.lower, a, b);
        turnLimit(p, true, simd::load<F>(block.reverseMass + first),
                  simd::load<F>(block.upperAngle + first) - angle, pass, limits, i.upper, a, b);
        const F pins = pass.useBias ? simd::load<F>(block.biasedPinOn + first) : simd::maskOfBits<F>(0xff);
        const PinStep<F> next = stepPin(p, f, a, b, soft, i.pointX, i.pointY);
        WideBody<F> pinned = a;
        WideBody<F> pinnedB = b;
        applyPinImpulse(p, f, next.nextX - i.pointX, next.nextY - i.pointY, pinned, pinnedB);
        keepLanes(pins, pinned, a);
        keepLanes(pins, pinnedB, b);
        i.pointX = simd::select(pins, next.nextX, i.pointX);
        i.pointY = simd::select(pins, next.nextY, i.pointY);
        storeImpulses<F>(block, first, i, rows);
      });
}

}  // namespace
}  // namespace impulse
