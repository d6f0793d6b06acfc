#pragma once
/// Scalar, vector, rotation and transform types of the engine, on Eigen.

#include <Eigen/Core>
#include <cmath>

namespace impulse {

/// The engine computes in single precision, as Box2D does. Scenes are tens of
/// metres wide, where float resolves a few micrometres, far below the 5 mm
/// linear slop; float halves the memory the solver streams through per
/// sub-step (the step is bandwidth-bound on large scenes) and Vector2f needs no
/// special alignment. Determinism comes from fixed operation order and no
/// fast-math, not from the width. The wire carries doubles; conversion happens
/// at the protocol boundary. A world far from (0, 0) keeps its floats small
/// by moving its origin (World::shiftOrigin): positions are relative to it.
using Real = float;
using Vec2 = Eigen::Matrix<Real, 2, 1>;
/// Double precision, where float would lose what matters: a world's origin
/// and positions given relative to no origin, sums of long series.
using Vec2d = Eigen::Vector2d;

inline Real cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
/// cross(w, v) for a scalar angular velocity w: the velocity w x v of a point.
inline Vec2 cross(Real w, const Vec2& v) { return Vec2(-w * v.y(), w * v.x()); }
inline Vec2 cross(const Vec2& v, Real w) { return Vec2(w * v.y(), -w * v.x()); }
/// Left perpendicular (rotated +90 degrees).
inline Vec2 leftPerp(const Vec2& v) { return Vec2(-v.y(), v.x()); }
/// Right perpendicular (rotated -90 degrees).
inline Vec2 rightPerp(const Vec2& v) { return Vec2(v.y(), -v.x()); }
inline bool isFinite(Real x) { return std::isfinite(x); }
inline bool isFinite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

/// A rotation stored as cosine and sine, so rotating a vector needs no trig.
struct Rot {
  Real c = 1;
  Real s = 0;

  static Rot fromAngle(Real angle) { return {std::cos(angle), std::sin(angle)}; }
  Real angle() const { return std::atan2(s, c); }
  Vec2 apply(const Vec2& v) const { return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); }
  Vec2 applyInverse(const Vec2& v) const { return Vec2(c * v.x() + s * v.y(), -s * v.x() + c * v.y()); }
};

/// Rotation q advanced by angle delta (small angles: first order, then
/// renormalised, as Box2D v3 does, so repeated integration stays on the circle).
inline Rot integrateRotation(const Rot& q, Real deltaAngle) {
  Real c = q.c - deltaAngle * q.s;
  Real s = q.s + deltaAngle * q.c;
  Real length = std::sqrt(c * c + s * s);
  Real inv = length > 0 ? Real(1) / length : Real(0);
  return {c * inv, s * inv};
}

/// Rotation b relative to a: a^-1 * b.
inline Rot relativeRotation(const Rot& a, const Rot& b) {
  return {a.c * b.c + a.s * b.s, a.c * b.s - a.s * b.c};
}

/// Rigid transform: rotate, then translate.
struct Transform {
  Vec2 p = Vec2::Zero();
  Rot q;

  Vec2 apply(const Vec2& v) const { return q.apply(v) + p; }
  Vec2 applyInverse(const Vec2& v) const { return q.applyInverse(v - p); }
};

/// Axis-aligned bounding box.
struct AABB {
  Vec2 lower = Vec2::Zero();
  Vec2 upper = Vec2::Zero();

  bool overlaps(const AABB& o) const {
    return !(o.lower.x() > upper.x() || o.lower.y() > upper.y() || lower.x() > o.upper.x() ||
             lower.y() > o.upper.y());
  }
  bool contains(const AABB& o) const {
    return lower.x() <= o.lower.x() && lower.y() <= o.lower.y() && o.upper.x() <= upper.x() &&
           o.upper.y() <= upper.y();
  }
  Real perimeter() const { return 2 * ((upper.x() - lower.x()) + (upper.y() - lower.y())); }
  AABB unite(const AABB& o) const {
    return {lower.cwiseMin(o.lower), upper.cwiseMax(o.upper)};
  }
  AABB expanded(Real margin) const {
    return {lower - Vec2(margin, margin), upper + Vec2(margin, margin)};
  }
};

}  // namespace impulse
