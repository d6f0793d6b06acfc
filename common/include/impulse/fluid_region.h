#pragma once
/// A liquid in a convex region: buoyancy from the exact submerged area and
/// centroid (impulse/submerged.h), linear and angular drag on the submerged
/// part, and a current that the drag carries bodies along with.

#include <vector>

#include "impulse/field.h"

namespace impulse {

struct FluidDef {
  /// Convex, either winding, 3 to kMaxPolygonVertices points, each
  /// coordinate within +-10000 m, area 0.01 to 1e6 m^2.
  std::vector<Vec2> polygon;
  Real density = 1000;  ///< kg/m^2 (areal, as the materials), in (0, 100000]
  /// Rates (1/s) in [0, 100] on the liquid a body displaces: the drag is the
  /// rate times that mass times the speed relative to the current (the spin
  /// likewise). Fully submerged, a body's speed relative to the current
  /// decays as exp(-linearDrag (density / body's density) t) and its spin
  /// as exp(-angularDrag (density / body's density) t); floating, every body
  /// displaces its own mass, so its bobbing dies at these rates whatever its
  /// density. Stepped by backward Euler, stable at any rate.
  Real linearDrag = 1;
  Real angularDrag = 1;
  Vec2 current = Vec2::Zero();  ///< m/s, each component within +-100
};

class FluidRegion : public ForceField {
 public:
  /// `def` must have passed makeFluidRegion's checks; the polygon anticlockwise.
  explicit FluidRegion(const FluidDef& def);
  const FluidDef& def() const { return def_; }
  void apply(const FieldStep& step, std::span<FieldLoad> loads) const override;

 private:
  FieldLoad loadOn(const FieldBody& body, const FieldStep& step) const;
  Real gradientOn(const FieldBody& body, const FieldStep& step) const;
  Real outsideBy(const Vec2& p) const;

  FluidDef def_;
  AABB box_;
};

/// The field, or the error naming the refused number and its range.
FieldBuild makeFluidRegion(const FluidDef& def);

}  // namespace impulse
