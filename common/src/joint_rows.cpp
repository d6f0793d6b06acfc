// The rows of each joint kind, after Box2D v3's soft step: rigid rows are
// soft constraints with the joint softness in the biased pass and hard in
// the relax pass, warm started; limits are speculative (no push until
// reached); springs have the user's exact stiffness and damping.

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#include "joint_pins.h"
#include "joint_row.h"

namespace impulse {

namespace {

using Mat2 = Eigen::Matrix<Real, 2, 2>;

/// The joint's geometry now: anchors from the centres, B's anchor minus A's,
/// and the joint angle. The angle is read only by rows that turn: its atan2
/// is the costliest part of a frame, and a plain pin never needs it.
struct Frame {
  Vec2 rA;
  Vec2 rB;
  Vec2 d;
  Real startAngle;
  Rot qA;
  Rot qB;
  Real angle() const { return startAngle + relativeRotation(qA, qB).angle(); }
};

Frame frameOf(const JointRow& row, const SolverState& a, const SolverState& b) {
  const PointFrame point = pointFrameOf(row, a, b);
  return {point.rA, point.rB, point.d, row.deltaAngle, a.deltaRotation, b.deltaRotation};
}

Jacobian angularJacobian() { return {Vec2::Zero(), 1, 1}; }
// Along a line between the anchors (distance, rope).
Jacobian lineJacobian(const Frame& f, const Vec2& u) { return {u, cross(f.rA, u), cross(f.rB, u)}; }
// Along an axis fixed in A (prismatic, wheel): A's lever reaches B's anchor.
Jacobian slideJacobian(const Frame& f, const Vec2& u) {
  return {u, cross(f.d + f.rA, u), cross(f.rB, u)};
}

Vec2 unitOr(const Vec2& v, const Vec2& fallback) {
  Real length = v.norm();
  return length > Real(1e-6) ? Vec2(v / length) : fallback;
}

void apply(const JointRow& row, const Jacobian& j, Real impulse, SolverState& a, SolverState& b) {
  if (impulse == 0) return;
  a.linearVelocity -= (row.invMassA * impulse) * j.linear;
  a.angularVelocity -= row.invInertiaA * impulse * j.angularA;
  b.linearVelocity += (row.invMassB * impulse) * j.linear;
  b.angularVelocity += row.invInertiaB * impulse * j.angularB;
}

Real effectiveMass(const JointRow& row, const Jacobian& j) {
  Real k = (row.invMassA + row.invMassB) * j.linear.squaredNorm() +
           row.invInertiaA * j.angularA * j.angularA + row.invInertiaB * j.angularB * j.angularB;
  return k > 0 ? 1 / k : 0;
}

Vec2 pointVelocity(const Frame& f, const SolverState& a, const SolverState& b) {
  return b.linearVelocity + cross(b.angularVelocity, f.rB) - a.linearVelocity -
         cross(a.angularVelocity, f.rA);
}

void applyPoint(const JointRow& row, const Frame& f, const Vec2& impulse, SolverState& a,
                SolverState& b) {
  a.linearVelocity -= row.invMassA * impulse;
  a.angularVelocity -= row.invInertiaA * cross(f.rA, impulse);
  b.linearVelocity += row.invMassB * impulse;
  b.angularVelocity += row.invInertiaB * cross(f.rB, impulse);
}

// The inverse mass matrix of a point constraint.
Mat2 pointInverseMass(const JointRow& row, const Frame& f) {
  Real m = row.invMassA + row.invMassB;
  Real iA = row.invInertiaA;
  Real iB = row.invInertiaB;
  Mat2 k;
  k(0, 0) = m + iA * f.rA.y() * f.rA.y() + iB * f.rB.y() * f.rB.y();
  k(0, 1) = -iA * f.rA.x() * f.rA.y() - iB * f.rB.x() * f.rB.y();
  k(1, 0) = k(0, 1);
  k(1, 1) = m + iA * f.rA.x() * f.rA.x() + iB * f.rB.x() * f.rB.x();
  return k;
}

Vec2 solve22(const Mat2& k, const Vec2& v) {
  Real det = k(0, 0) * k(1, 1) - k(0, 1) * k(1, 0);
  if (det == 0) return Vec2::Zero();
  Real inv = 1 / det;
  return Vec2(inv * (k(1, 1) * v.x() - k(0, 1) * v.y()), inv * (k(0, 0) * v.y() - k(1, 0) * v.x()));
}

void rigidRow(const JointRow& row, const Jacobian& j, Real c, Real& accumulated,
              const JointPass& pass, SolverState& a, SolverState& b) {
  if (row.inTree && pass.useBias) return;
  Softness soft = rowSoftness(pass);
  Real impulse = -effectiveMass(row, j) * soft.massScale * (velocity(j, a, b) + soft.biasRate * c) -
                 soft.impulseScale * accumulated;
  accumulated += impulse;
  apply(row, j, impulse, a, b);
}

// One-sided row keeping c >= 0. Speculative: while c > 0 it only stops the
// bodies from closing more than c within the sub-step.
void limitRow(const JointRow& row, const Jacobian& j, Real c, Real& accumulated,
              const JointPass& pass, SolverState& a, SolverState& b) {
  Softness soft = rowSoftness(pass);
  Real bias = soft.biasRate * c;
  if (c > 0) soft = {0, 1, 0}, bias = c * pass.invH;
  Real impulse = -effectiveMass(row, j) * soft.massScale * (velocity(j, a, b) + bias) -
                 soft.impulseScale * accumulated;
  Real next = std::max(accumulated + impulse, Real(0));
  apply(row, j, next - accumulated, a, b);
  accumulated = next;
}

void motorRow(const JointRow& row, const Jacobian& j, Real speed, Real maxImpulse,
              Real& accumulated, SolverState& a, SolverState& b) {
  Real impulse = -effectiveMass(row, j) * (velocity(j, a, b) - speed);
  Real next = std::clamp(accumulated + impulse, -maxImpulse, maxImpulse);
  apply(row, j, next - accumulated, a, b);
  accumulated = next;
}

// How much of the end-of-sub-step velocity the spring force sees, beyond
// the damping: none (symplectic Euler, no energy lost, period exact to
// second order) while the sub-step resolves the oscillation, half (stable at
// any stiffness) when it does not: undamped springs keep their amplitude.
Real springVelocityWeight(Real stiffness, Real damping, Real mass, Real h) {
  Real hOmega = h * std::sqrt(stiffness / mass);
  Real theta = hOmega < 1 ? Real(0) : Real(0.5);
  return h * damping + theta * h * h * stiffness;
}

// A spring of `stiffness` N/m and `damping` N*s/m on a row; solved once per
// sub-step in the biased pass (the relax pass would apply it twice).
void springRow(const JointRow& row, const Jacobian& j, Real c, Real stiffness, Real damping,
               Real& impulseOut, const JointPass& pass, SolverState& a, SolverState& b) {
  Real mass = effectiveMass(row, j);
  if (!pass.useBias || mass == 0) return;
  Real s = springVelocityWeight(stiffness, damping, mass, pass.h);
  Real impulse = -(pass.h * stiffness * c + s * velocity(j, a, b)) * mass / (mass + s);
  impulseOut = impulse;
  apply(row, j, impulse, a, b);
}

// A point row of softness `soft` on the error c, its accumulated impulse
// held within maxImpulse.
void pointRow(const JointRow& row, const Frame& f, const Vec2& c, Vec2& accumulated, const Softness& soft,
              Real maxImpulse, SolverState& a, SolverState& b) {
  Vec2 bias = soft.biasRate * c;
  Vec2 impulse =
      -soft.massScale * solve22(pointInverseMass(row, f), pointVelocity(f, a, b) + bias) -
      soft.impulseScale * accumulated;
  Vec2 next = accumulated + impulse;
  // A rigid point is unbounded: no square root for it.
  if (std::isfinite(maxImpulse) && next.norm() > maxImpulse) next *= maxImpulse / next.norm();
  applyPoint(row, f, next - accumulated, a, b);
  accumulated = next;
}

void rigidPoint(const JointRow& row, const Frame& f, const Vec2& c, Vec2& accumulated,
                const JointPass& pass, SolverState& a, SolverState& b) {
  if (row.inTree && pass.useBias) return;
  pointRow(row, f, c, accumulated, pointSoftness(row, pass), std::numeric_limits<Real>::infinity(),
           a, b);
}

// The share of its force a rigid mouse joint plans to brake with: the rest
// is left for the weight and other loads it may have to hold meanwhile.
constexpr Real kBrakingShare = Real(0.5);

// The fastest speed from which losing `brake` m/s per sub-step of h still
// stops within `distance`: moving v = n brake this sub-step, then braking,
// covers h brake n (n + 1) / 2. Near the target, no more than the distance
// in one sub-step.
Real stoppingSpeed(Real distance, Real brake, Real h) {
  const Real steps = std::sqrt(Real(0.25) + 2 * distance / (h * brake)) - Real(0.5);
  return std::min(distance / h, steps * brake);
}

// A rigid mouse joint is a drive, not a constraint: in both passes it asks
// the anchor for the speed towards the target from which its braking share
// of maxForce can still stop it there (the time-optimal approach), along the
// anchor's own inverse mass towards the target, so the body really moves,
// reports its velocity, and arrives without overshoot. A hard row would
// move it by position correction alone, its velocity wiped by the relax
// pass.
void drivePoint(JointRow& row, const Frame& f, Real maxForce, const JointPass& pass, SolverState& a,
                SolverState& b) {
  const Real distance = f.d.norm();
  Real rate = 0;  // the asked speed per metre of distance
  if (distance > 0) {
    const Vec2 u = f.d / distance;
    const Real brake = kBrakingShare * pass.h * maxForce * u.dot(pointInverseMass(row, f) * u);
    rate = brake > 0 ? stoppingSpeed(distance, brake, pass.h) / distance : 0;
  }
  pointRow(row, f, f.d, row.impulses.point, {rate, 1, 0}, pass.h * maxForce, a, b);
}

// A point constraint's mass for the spring terms: along its stiffer axis.
Real pointMass(const Mat2& inverseMass) { return 1 / std::max(inverseMass(0, 0), inverseMass(1, 1)); }

// The point spring: (1 + s K) impulse = -(h k c + s v), K the inverse mass.
void springPoint(const JointRow& row, const Frame& f, Real stiffness, Real damping,
                 Vec2& impulseOut, const JointPass& pass, SolverState& a, SolverState& b,
                 Real maxImpulse = std::numeric_limits<Real>::infinity()) {
  if (!pass.useBias) return;
  Mat2 k = pointInverseMass(row, f);
  Real s = springVelocityWeight(stiffness, damping, pointMass(k), pass.h);
  Vec2 impulse =
      -solve22(Mat2::Identity() + s * k, pass.h * stiffness * f.d + s * pointVelocity(f, a, b));
  if (impulse.norm() > maxImpulse) impulse *= maxImpulse / impulse.norm();
  impulseOut = impulse;
  applyPoint(row, f, impulse, a, b);
}

// A soft weld has no damping setting: critically damped.
Real criticalDamping(Real stiffness, Real mass) { return 2 * std::sqrt(stiffness * mass); }

struct Context {
  JointRow& row;
  SolverState& a;
  SolverState& b;
  const JointPass& pass;
  Frame f;
};

void solveKind(Context& x, const DistanceJointSettings& s) {
  Vec2 u = unitOr(x.f.d, x.row.lastAxis);
  x.row.lastAxis = u;
  Jacobian j = lineJacobian(x.f, u);
  Real c = x.f.d.norm() - x.row.joint->length;
  if (s.stiffness > 0) {
    springRow(x.row, j, c, s.stiffness, s.damping, x.row.impulses.spring, x.pass, x.a, x.b);
  } else {
    rigidRow(x.row, j, c, x.row.impulses.axial, x.pass, x.a, x.b);
  }
}

void solveKind(Context& x, const RopeJointSettings&) {
  Vec2 u = unitOr(x.f.d, x.row.lastAxis);
  x.row.lastAxis = u;
  Real c = x.row.joint->length - x.f.d.norm();
  limitRow(x.row, -lineJacobian(x.f, u), c, x.row.impulses.upper, x.pass, x.a, x.b);
}

// Spring, motor and limits on an axis row whose position is `value`.
template <class Settings>
void axisRows(Context& x, const Jacobian& j, Real value, const Settings& s, Real maxMotorImpulse) {
  JointImpulses& p = x.row.impulses;
  if (s.stiffness > 0)
    springRow(x.row, j, value, s.stiffness, s.damping, p.spring, x.pass, x.a, x.b);
  if (s.enableMotor) motorRow(x.row, j, s.motorSpeed, maxMotorImpulse, p.motor, x.a, x.b);
}

template <class Settings>
void limitRows(Context& x, const Jacobian& j, Real value, Real lower, Real upper,
               const Settings& s) {
  if (!s.enableLimit) return;
  limitRow(x.row, j, value - lower, x.row.impulses.lower, x.pass, x.a, x.b);
  limitRow(x.row, -j, upper - value, x.row.impulses.upper, x.pass, x.a, x.b);
}

void solveKind(Context& x, const RevoluteJointSettings& s) {
  const Real angle = s.stiffness > 0 || s.enableLimit ? x.f.angle() : Real(0);
  axisRows(x, angularJacobian(), angle, s, x.pass.h * s.maxMotorTorque);
  limitRows(x, angularJacobian(), angle, s.lowerAngle, s.upperAngle, s);
  rigidPoint(x.row, x.f, x.f.d, x.row.impulses.point, x.pass, x.a, x.b);
}

void solveKind(Context& x, const MouseJointSettings& s) {
  if (s.stiffness > 0) {
    springPoint(x.row, x.f, s.stiffness, s.damping, x.row.impulses.pointSpring, x.pass, x.a, x.b,
                x.pass.h * s.maxForce);
  } else {
    drivePoint(x.row, x.f, s.maxForce, x.pass, x.a, x.b);
  }
}

void solveKind(Context& x, const WeldJointSettings& s) {
  JointImpulses& p = x.row.impulses;
  Jacobian turn = angularJacobian();
  if (s.angularStiffness > 0) {
    Real damping = criticalDamping(s.angularStiffness, effectiveMass(x.row, turn));
    springRow(x.row, turn, x.f.angle(), s.angularStiffness, damping, p.spring, x.pass, x.a, x.b);
  } else {
    rigidRow(x.row, turn, x.f.angle(), p.angular, x.pass, x.a, x.b);
  }
  if (s.linearStiffness > 0) {
    Real damping = criticalDamping(s.linearStiffness, pointMass(pointInverseMass(x.row, x.f)));
    springPoint(x.row, x.f, s.linearStiffness, damping, p.pointSpring, x.pass, x.a, x.b);
  } else {
    rigidPoint(x.row, x.f, x.f.d, p.point, x.pass, x.a, x.b);
  }
}

// The axis turns with A; positions along and across it are measured from
// where they were at creation.
struct Slide {
  Jacobian along;
  Jacobian across;
  Real translation;
  Real offset;
};

Slide slideOf(JointRow& row, const Frame& f, const SolverState& a) {
  Vec2 u = a.deltaRotation.apply(row.axis);
  Vec2 n = leftPerp(u);
  row.lastAxis = u;
  return {slideJacobian(f, u), slideJacobian(f, n), u.dot(f.d) - row.joint->referenceTranslation,
          n.dot(f.d) - row.joint->referencePerpendicular};
}

void solveKind(Context& x, const PrismaticJointSettings& s) {
  Slide slide = slideOf(x.row, x.f, x.a);
  axisRows(x, slide.along, slide.translation, s, x.pass.h * s.maxMotorForce);
  limitRows(x, slide.along, slide.translation, s.lower, s.upper, s);
  rigidRow(x.row, angularJacobian(), x.f.angle(), x.row.impulses.angular, x.pass, x.a, x.b);
  rigidRow(x.row, slide.across, slide.offset, x.row.impulses.perpendicular, x.pass, x.a, x.b);
}

void solveKind(Context& x, const WheelJointSettings& s) {
  Slide slide = slideOf(x.row, x.f, x.a);
  JointImpulses& p = x.row.impulses;
  if (s.stiffness > 0) {
    springRow(x.row, slide.along, slide.translation, s.stiffness, s.damping, p.spring, x.pass, x.a,
              x.b);
  } else {
    rigidRow(x.row, slide.along, slide.translation, p.axial, x.pass, x.a, x.b);
  }
  if (s.enableMotor) {
    motorRow(x.row, angularJacobian(), s.motorSpeed, x.pass.h * s.maxMotorTorque, p.motor, x.a,
             x.b);
  }
  rigidRow(x.row, slide.across, slide.offset, p.perpendicular, x.pass, x.a, x.b);
}

bool turnsWithLimits(const JointSettings& settings) {
  return std::holds_alternative<RevoluteJointSettings>(settings);
}
bool slides(const JointSettings& settings) {
  return std::holds_alternative<PrismaticJointSettings>(settings) ||
         std::holds_alternative<WheelJointSettings>(settings);
}

// The row that carries the axial, limit and motor impulses of each kind.
Jacobian limitJacobian(const JointRow& row, const Frame& f, const SolverState& a) {
  if (turnsWithLimits(row.joint->settings)) return angularJacobian();
  if (slides(row.joint->settings)) return slideJacobian(f, a.deltaRotation.apply(row.axis));
  return lineJacobian(f, unitOr(f.d, row.lastAxis));
}

// ---- rigid rows, for the tree pass (joint_tree_pass.h) ----

struct RigidRowsOut {
  RigidRows& rows;
  int count = 0;
  void add(const Jacobian& j, Real position, Real& impulse) {
    rows[count++] = {j, position, &impulse};
  }
  void addPoint(const Frame& f, Vec2& impulse) {
    pointRows({f.rA, f.rB, f.d}, impulse, rows.data() + count);
    count += 2;
  }
};

/// What the rigid rows are read from: the joint now.
struct RigidContext {
  JointRow& row;
  const SolverState& a;
  Frame f;
};

void addRigid(RigidRowsOut& out, RigidContext& x, const DistanceJointSettings& s) {
  if (s.stiffness > 0) return;
  // The axis its reaction is reported along, as the soft row keeps it.
  x.row.lastAxis = unitOr(x.f.d, x.row.lastAxis);
  out.add(lineJacobian(x.f, x.row.lastAxis), x.f.d.norm() - x.row.joint->length, x.row.impulses.axial);
}
void addRigid(RigidRowsOut&, RigidContext&, const RopeJointSettings&) {}
void addRigid(RigidRowsOut&, RigidContext&, const MouseJointSettings&) {}
void addRigid(RigidRowsOut& out, RigidContext& x, const RevoluteJointSettings&) {
  out.addPoint(x.f, x.row.impulses.point);
}
void addRigid(RigidRowsOut& out, RigidContext& x, const WeldJointSettings& s) {
  if (s.linearStiffness == 0) out.addPoint(x.f, x.row.impulses.point);
  if (s.angularStiffness == 0) out.add(angularJacobian(), x.f.angle(), x.row.impulses.angular);
}
void addRigid(RigidRowsOut& out, RigidContext& x, const PrismaticJointSettings&) {
  Slide slide = slideOf(x.row, x.f, x.a);
  out.add(angularJacobian(), x.f.angle(), x.row.impulses.angular);
  out.add(slide.across, slide.offset, x.row.impulses.perpendicular);
}
void addRigid(RigidRowsOut& out, RigidContext& x, const WheelJointSettings& s) {
  Slide slide = slideOf(x.row, x.f, x.a);
  out.add(slide.across, slide.offset, x.row.impulses.perpendicular);
  if (s.stiffness == 0) out.add(slide.along, slide.translation, x.row.impulses.axial);
}

}  // namespace

Softness rowSoftness(const JointPass& pass) { return pass.useBias ? pass.rigid : Softness{0, 1, 0}; }

Softness loopPinSoftness(const JointPass& pass) {
  return pass.useBias ? pass.loop : rowSoftness(pass);
}

Softness pointSoftness(const JointRow& row, const JointPass& pass) {
  return row.pinInLoop ? loopPinSoftness(pass) : rowSoftness(pass);
}

Real jointAngle(const Joint& joint, const Rot& qA, const Rot& qB) {
  constexpr Real pi = std::numbers::pi_v<Real>;
  Real angle = relativeRotation(qA, qB).angle() - joint.referenceAngle;
  if (angle > pi) angle -= 2 * pi;
  if (angle < -pi) angle += 2 * pi;
  return angle;
}

void warmStartJoint(JointRow& row, SolverState& a, SolverState& b) {
  const JointImpulses& p = row.impulses;
  Frame f = frameOf(row, a, b);
  applyPoint(row, f, p.point, a, b);
  if (row.plainPin) return;  // its other impulses are all zero
  apply(row, angularJacobian(), p.angular, a, b);
  Jacobian limits = limitJacobian(row, f, a);
  apply(row, limits, p.axial + p.lower - p.upper, a, b);
  // Only a prismatic motor pushes along its axis; the others turn.
  bool prismatic = std::holds_alternative<PrismaticJointSettings>(row.joint->settings);
  apply(row, prismatic ? limits : angularJacobian(), p.motor, a, b);
  if (slides(row.joint->settings)) {
    apply(row, slideJacobian(f, leftPerp(a.deltaRotation.apply(row.axis))), p.perpendicular, a, b);
  }
}

void solveJoint(JointRow& row, SolverState& a, SolverState& b, const JointPass& pass) {
  if (row.inTree && !row.softRows && (pass.useBias || row.relaxedExactly)) return;
  if (row.plainPin) {
    const Frame f = frameOf(row, a, b);
    rigidPoint(row, f, f.d, row.impulses.point, pass, a, b);
    return;
  }
  Context x{row, a, b, pass, frameOf(row, a, b)};
  std::visit([&](const auto& settings) { solveKind(x, settings); }, row.joint->settings);
}

bool isTurningRevolute(const JointRow& row) {
  return !row.plainPin && std::holds_alternative<RevoluteJointSettings>(row.joint->settings);
}

void placeRevolute(RevoluteBlock& block, int lane, const JointRow& row, std::int32_t rowIndex,
                   Real h) {
  const auto& s = std::get<RevoluteJointSettings>(row.joint->settings);
  const auto mask = [](bool on) { return on ? std::bit_cast<Real>(~std::uint32_t(0)) : Real(0); };
  placeGeometry(block.pin, lane, row, rowIndex);
  block.startAngle[lane] = row.deltaAngle;
  const Real mass = effectiveMass(row, angularJacobian());
  block.turnMass[lane] = mass;
  block.reverseMass[lane] = effectiveMass(row, -angularJacobian());
  block.springStep[lane] = h * s.stiffness;
  const Real weight = mass > 0 ? springVelocityWeight(s.stiffness, s.damping, mass, h) : Real(0);
  block.springWeight[lane] = weight;
  block.springDivisor[lane] = mass + weight;
  block.motorSpeed[lane] = s.motorSpeed;
  block.maxMotorImpulse[lane] = h * s.maxMotorTorque;
  block.lowerAngle[lane] = s.lowerAngle;
  block.upperAngle[lane] = s.upperAngle;
  const JointImpulses& impulses = row.impulses;
  block.angularImpulse[lane] = impulses.angular;
  block.axialImpulse[lane] = impulses.axial;
  block.springImpulse[lane] = impulses.spring;
  block.motorImpulse[lane] = impulses.motor;
  block.lowerImpulse[lane] = impulses.lower;
  block.upperImpulse[lane] = impulses.upper;
  // springRow skips a spring without mass.
  block.springOn[lane] = mask(s.stiffness > 0 && mass != 0);
  block.motorOn[lane] = mask(s.enableMotor);
  block.limitOn[lane] = mask(s.enableLimit);
  block.biasedPinOn[lane] = mask(!row.inTree);
  block.needsAngle[lane] = s.stiffness > 0 || s.enableLimit;
}

void storeRevoluteImpulses(const RevoluteBlock& block, std::span<JointRow> rows) {
  for (int lane = 0; lane < RevoluteBlock::kLanes && block.pin.row[lane] >= 0; ++lane) {
    JointImpulses& impulses = rows[std::size_t(block.pin.row[lane])].impulses;
    impulses.spring = block.springImpulse[lane];
    impulses.motor = block.motorImpulse[lane];
    impulses.lower = block.lowerImpulse[lane];
    impulses.upper = block.upperImpulse[lane];
  }
}

bool hasSoftRows(const JointSettings& settings) {
  return std::visit(
      [](const auto& s) -> bool {
        using Kind = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<Kind, DistanceJointSettings>) return s.stiffness > 0;
        if constexpr (std::is_same_v<Kind, RevoluteJointSettings> ||
                      std::is_same_v<Kind, PrismaticJointSettings>)
          return s.enableLimit || s.enableMotor || s.stiffness > 0;
        if constexpr (std::is_same_v<Kind, WeldJointSettings>)
          return s.linearStiffness > 0 || s.angularStiffness > 0;
        if constexpr (std::is_same_v<Kind, WheelJointSettings>) return s.stiffness > 0 || s.enableMotor;
        return true;  // ropes and mouse joints
      },
      settings);
}

int rigidRows(JointRow& row, const SolverState& a, const SolverState& b, RigidRows& out) {
  if (row.plainPin) return plainPinRows(row, a, b, out);
  RigidRowsOut rows{out};
  RigidContext x{row, a, frameOf(row, a, b)};
  std::visit([&](const auto& settings) { addRigid(rows, x, settings); }, row.joint->settings);
  return rows.count;
}

void jointReaction(const JointRow& row, Real invH, Vec2& force, Real& torque) {
  const JointImpulses& p = row.impulses;
  const JointSettings& settings = row.joint->settings;
  Vec2 axis = row.lastAxis;
  Real along = p.axial + p.lower - p.upper;
  Real turn = p.angular;
  if (turnsWithLimits(settings)) {
    turn += along + p.spring + p.motor;
    along = 0;
  } else if (std::holds_alternative<WeldJointSettings>(settings) ||
             std::holds_alternative<WheelJointSettings>(settings)) {
    turn += std::holds_alternative<WeldJointSettings>(settings) ? p.spring : p.motor;
    along += std::holds_alternative<WheelJointSettings>(settings) ? p.spring : Real(0);
  } else {
    along += p.spring + p.motor;
  }
  force = invH * (p.point + p.pointSpring + along * axis + p.perpendicular * leftPerp(axis));
  torque = invH * turn;
}

}  // namespace impulse
