// A liquid region (impulse/fluid_region.h). Buoyancy -rho * A_sub * g acts at
// the submerged centroid, so a body tilted off its stable pose feels the
// torque that rights it. Drag is implicit (backward Euler), stable for any
// rate.

#include "impulse/fluid_region.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "impulse/submerged.h"
#include "input_limits.h"

namespace impulse {

namespace {

constexpr Real kMaxCoordinate = 10000;
constexpr Real kMaxDensity = 100000;
constexpr Real kMaxDrag = 100;
constexpr Real kMaxCurrent = 100;

// Backward Euler for drag at `rate`: the force per unit mass (or torque per
// unit inertia) is rate / (1 + rate dt) times the speed the body would have
// at the end of the step. Stable for any rate, and a sinking body reaches
// exactly the terminal speed of the continuous law.
Real implicitRate(Real rate, Real dt) { return rate / (1 + rate * dt); }

std::string checkRange(Real value, Real low, Real high, const char* field, bool lowIncluded) {
  const bool below = lowIncluded ? value < low : value <= low;
  if (std::isfinite(value) && !below && value <= high) return {};
  return std::string("fluid ") + field + " " + describeNumber(value) + " is outside " + (lowIncluded ? "[" : "(") +
         describeNumber(low) + ", " + describeNumber(high) + "]";
}

std::string checkPolygon(const std::vector<Vec2>& points) {
  for (const Vec2& p : points) {
    if (!isFinite(p) || std::abs(p.x()) > kMaxCoordinate || std::abs(p.y()) > kMaxCoordinate) {
      // Said from the origin, as a fan's place is (fan.cpp).
      return "fluid polygon point is not finite or lies more than " +
             describeNumber(kMaxCoordinate) + " m from the world's origin on an axis";
    }
  }
  ShapeLimits limits;
  limits.minArea = Real(0.01);
  limits.maxArea = Real(1e6);
  const PolygonBuild build = buildPolygon(points, limits);
  if (build.error != ShapeError::None) return "fluid polygon: " + std::string(describe(build.error));
  return {};
}

std::string checkFluid(const FluidDef& def) {
  for (const std::string& error :
       {checkPolygon(def.polygon), checkRange(def.density, 0, kMaxDensity, "density", false),
        checkRange(def.linearDrag, 0, kMaxDrag, "linear_drag", true),
        checkRange(def.angularDrag, 0, kMaxDrag, "angular_drag", true),
        checkRange(def.current.x(), -kMaxCurrent, kMaxCurrent, "current.x", true),
        checkRange(def.current.y(), -kMaxCurrent, kMaxCurrent, "current.y", true)}) {
    if (!error.empty()) return error;
  }
  return {};
}

Real signedArea(const std::vector<Vec2>& points) {
  Real sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) sum += cross(points[i], points[(i + 1) % points.size()]);
  return sum / 2;
}

}  // namespace

FluidRegion::FluidRegion(const FluidDef& def) : def_(def) {
  if (signedArea(def_.polygon) < 0) std::ranges::reverse(def_.polygon);
  box_ = {def_.polygon[0], def_.polygon[0]};
  for (const Vec2& p : def_.polygon) {
    box_.lower = box_.lower.cwiseMin(p);
    box_.upper = box_.upper.cwiseMax(p);
  }
}

// Outward distance of `p` past the region's nearest edge line (negative inside).
Real FluidRegion::outsideBy(const Vec2& p) const {
  Real farthest = -std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < def_.polygon.size(); ++i) {
    const Vec2& a = def_.polygon[i];
    const Vec2 edge = def_.polygon[(i + 1) % def_.polygon.size()] - a;
    farthest = std::max(farthest, cross(edge, a - p) / edge.norm());
  }
  return farthest;
}

// Buoyancy changes with position only where the body meets the region's
// edge (the surface): by rho g w / m per metre, w the width there, at most
// twice the body's extent. Within the step's reach of the edge, that.
Real FluidRegion::gradientOn(const FieldBody& body, const FieldStep& step) const {
  if (body.mass <= 0) return 0;
  const Real reach = body.extent + body.linearVelocity.norm() * step.dt;
  if (std::abs(outsideBy(body.transform.p)) >= reach) return 0;
  return def_.density * step.gravity.norm() * 2 * body.extent / body.mass;
}

FieldLoad FluidRegion::loadOn(const FieldBody& body, const FieldStep& step) const {
  const SubmergedPart part = submergedPart(body.shapes, body.transform, def_.polygon);
  if (part.area <= 0 || body.area <= 0 || body.mass <= 0) return {};
  // The liquid drags in proportion to what the body displaces, not to its
  // own mass: per unit of the body's mass the rates scale by the displaced
  // mass over the body's, so a floating body, whatever its density, is
  // damped at the liquid's rates (a light one bobs no longer than a heavy).
  const Real wet = def_.density * Real(part.area) / body.mass;
  const Vec2 arm = part.centroid - body.transform.p;
  FieldLoad load;
  const Vec2 buoyancy = -def_.density * Real(part.area) * step.gravity;
  // Drag on the centre's motion through the current, on the velocity weight
  // and buoyancy would give it by the step's end, acting where the liquid
  // holds the body (the submerged centroid): a current turns it.
  const Vec2 predicted = body.linearVelocity + step.dt * (step.gravity + buoyancy / body.mass) - def_.current;
  const Vec2 drag = -body.mass * implicitRate(def_.linearDrag * wet, step.dt) * predicted;
  load.force = buoyancy + drag;
  load.torque = cross(arm, buoyancy + drag) -
                body.inertia * implicitRate(def_.angularDrag * wet, step.dt) * body.angularVelocity;
  return load;
}

void FluidRegion::apply(const FieldStep& step, std::span<FieldLoad> loads) const {
  for (std::size_t i = 0; i < step.bodies.size(); ++i) {
    const FieldBody& body = step.bodies[i];
    loads[i].gradient += gradientOn(body, step);
    const Vec2 reach(body.extent, body.extent);
    const Vec2& p = body.transform.p;
    if (!box_.overlaps({p - reach, p + reach})) continue;
    // Buoyancy is a stiff spring for a light body: spread over the sub-steps
    // its bobbing gains energy (an ICE box leapt ever higher). So the load
    // is an impulse at the start of the step, except the body's weight,
    // which is spread as gravity is and cancels it: a body at its rest
    // depth then has no velocity at all, and the rest is symplectic Euler.
    const FieldLoad load = loadOn(body, step);
    const Vec2 weight = body.mass * step.gravity;
    loads[i].force -= weight;
    loads[i].impulse += step.dt * (load.force + weight);
    loads[i].angularImpulse += step.dt * load.torque;
  }
}

FieldBuild makeFluidRegion(const FluidDef& def) {
  if (std::string error = checkFluid(def); !error.empty()) return {nullptr, error};
  return {std::make_shared<FluidRegion>(def), {}};
}

}  // namespace impulse
