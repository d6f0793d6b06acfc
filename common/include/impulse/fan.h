#pragma once
/// A fan: a jet of air blowing from a point along a direction, within a
/// cone. The air moves along the axis; its speed falls linearly from
/// `speed` at the fan to nothing at `range` (measured along the axis) and
/// across the cone from full on the axis to nothing at its edge (1 - f^2,
/// f the angle off the axis over `spread`). The jet also draws air in from
/// its sides (entrainment): a crosswind towards the axis of kEntrainment
/// times f times the jet's speed there, so a body on the flank is carried
/// back towards the axis rather than out of the cone.
/// Bodies in the flow feel quadratic drag, 1/2 rho Cd w |u - v| (u - v),
/// with air of areal density 1.2 kg/m^2 (the materials' densities are
/// areal: a 1 m deep slice), Cd = 1 and w the body's width across the flow.
/// A body whose centre is hidden from the fan by a nearer moving body (its
/// circle of reach) is in that body's shadow and feels no air. Static
/// bodies cast no shadow: a wall's or the ground's circle of reach would
/// shade far more than the wall does.

#include <vector>

#include "impulse/field.h"

namespace impulse {

struct FanDef {
  Vec2 position = Vec2::Zero();      ///< each coordinate within +-10000 m
  Vec2 direction = Vec2(1, 0);       ///< any length in [1e-6, 1e6]
  Real speed = 10;                   ///< m/s at the fan, in (0, 200]
  Real range = 10;                   ///< m, in (0, 1000]
  Real spread = Real(0.3);           ///< half-angle of the cone, rad, in (0, pi/2]
};

class Fan : public ForceField {
 public:
  static constexpr Real kAirDensity = Real(1.2);
  static constexpr Real kDragCoefficient = 1;
  static constexpr Real kEntrainment = Real(0.5);

  /// `def` must have passed makeFan's checks.
  explicit Fan(const FanDef& def);
  const FanDef& def() const { return def_; }
  /// The air's velocity at a point, ignoring shadows: zero outside the cone or range.
  Vec2 airVelocity(const Vec2& point) const;
  void apply(const FieldStep& step, std::span<FieldLoad> loads) const override;

 private:
  /// Angle of a point off the fan's axis, and its distance.
  struct Bearing {
    Real angle = 0;
    Real distance = 0;
  };
  Bearing bearingOf(const Vec2& point) const;
  bool inFlow(const Bearing& bearing) const;
  Vec2 dragOn(const FieldBody& body, Real dt) const;
  /// Marks which moving bodies sit in a nearer body's shadow.
  void findShadows(const FieldStep& step) const;

  FanDef def_;
  Vec2 axis_;
  // Scratch reused every step (a field serves one world at a time).
  struct Blocker {
    Real distance;
    Real angle;
    Real halfWidth;  ///< angle the body's reach covers either side
    int moving;      ///< index into FieldStep::bodies
  };
  mutable std::vector<Blocker> blockers_;
  mutable std::vector<std::pair<Real, Real>> shadows_;
  mutable std::vector<char> shadowed_;
};

/// The field, or the error naming the refused number and its range.
FieldBuild makeFan(const FanDef& def);

}  // namespace impulse
