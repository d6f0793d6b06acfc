// A fan (impulse/fan.h): a jet of air along the axis within a cone, drag on
// the bodies in it, and shadows: bodies in the cone sorted by distance, each covering an
// angle as seen from the fan; a body whose centre's angle a nearer body
// already covers gets no air. O(k log k) for k bodies in the cone plus the
// merge of covered angles.

#include "impulse/fan.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>

#include "input_limits.h"

namespace impulse {

namespace {

constexpr Real kMaxCoordinate = 10000;
constexpr Real kMaxSpeed = 200;
constexpr Real kMaxRange = 1000;
constexpr Real kMaxSpread = std::numbers::pi_v<Real> / 2;

std::string outside(const char* field, Real value, const char* range) {
  return std::string("fan ") + field + " " + describeNumber(value) + " is outside " + range;
}

std::string checkFan(const FanDef& def) {
  if (!isFinite(def.position) || std::abs(def.position.x()) > kMaxCoordinate ||
      std::abs(def.position.y()) > kMaxCoordinate) {
    // Said from the origin: in a world moved far out, +-10000 m would read as
    // coordinates from (0, 0).
    return "fan position is not finite or lies more than 10000 m from the world's origin on an "
           "axis";
  }
  const Real length = isFinite(def.direction) ? def.direction.norm() : Real(0);
  if (!(length >= Real(1e-6) && length <= Real(1e6))) return "fan direction must be finite with length in [1e-6, 1e6]";
  if (!(def.speed > 0 && def.speed <= kMaxSpeed)) return outside("speed", def.speed, "(0, 200] m/s");
  if (!(def.range > 0 && def.range <= kMaxRange)) return outside("range", def.range, "(0, 1000] m");
  if (!(def.spread > 0 && def.spread <= kMaxSpread)) return outside("spread", def.spread, "(0, pi/2] rad");
  return {};
}

// Where a shape's points project on the unit `direction` (body frame): its
// core's points widened by its radius.
struct Projection {
  Real low = std::numeric_limits<Real>::max();
  Real high = -std::numeric_limits<Real>::max();
  void add(const Vec2& point, Real radius, const Vec2& direction) {
    low = std::min(low, point.dot(direction) - radius);
    high = std::max(high, point.dot(direction) + radius);
  }
};

void project(const Shape& shape, const Vec2& direction, Projection& projection) {
  switch (shape.type()) {
    case ShapeType::Circle: projection.add(shape.circle().center, shape.circle().radius, direction); return;
    case ShapeType::Capsule:
      projection.add(shape.capsule().center1, shape.capsule().radius, direction);
      projection.add(shape.capsule().center2, shape.capsule().radius, direction);
      return;
    case ShapeType::Segment:
      projection.add(shape.segment().point1, 0, direction);
      projection.add(shape.segment().point2, 0, direction);
      return;
    case ShapeType::Polygon:
      for (int i = 0; i < shape.polygon().count; ++i) {
        projection.add(shape.polygon().vertices[i], shape.polygon().radius, direction);
      }
      return;
    case ShapeType::ChainSegment:
      projection.add(shape.chainSegment().segment.point1, 0, direction);
      projection.add(shape.chainSegment().segment.point2, 0, direction);
      return;
  }
}

// Width of a body's shapes across a flow along unit `along`.
Real widthAcross(std::span<const Shape* const> shapes, const Rot& rotation, const Vec2& along) {
  const Vec2 across = rotation.applyInverse(Vec2(-along.y(), along.x()));
  Projection projection;
  for (const Shape* shape : shapes) project(*shape, across, projection);
  return projection.high - projection.low;
}

}  // namespace

Fan::Fan(const FanDef& def) : def_(def), axis_(def.direction.normalized()) {}

Fan::Bearing Fan::bearingOf(const Vec2& point) const {
  const Vec2 offset = point - def_.position;
  return {std::atan2(cross(axis_, offset), axis_.dot(offset)), offset.norm()};
}

bool Fan::inFlow(const Bearing& bearing) const {
  return bearing.distance > 0 && bearing.distance < def_.range && std::abs(bearing.angle) <= def_.spread;
}

Vec2 Fan::airVelocity(const Vec2& point) const {
  const Bearing bearing = bearingOf(point);
  if (!inFlow(bearing)) return Vec2::Zero();
  const Real along = axis_.dot(point - def_.position);
  if (along <= 0) return Vec2::Zero();
  // Off the axis as a fraction of the cone's half-angle, signed: -1 to 1.
  const Real offAxis = bearing.angle / def_.spread;
  const Real jet = def_.speed * std::max(Real(0), 1 - along / def_.range) * (1 - offAxis * offAxis);
  // The jet draws the still air beside it inwards (entrainment): a body on
  // its flank drifts back towards the axis instead of being blown out.
  const Vec2 towardsAxis = -offAxis * Vec2(-axis_.y(), axis_.x());
  return jet * (axis_ + kEntrainment * towardsAxis);
}

Vec2 Fan::dragOn(const FieldBody& body, Real dt) const {
  const Vec2 relative = airVelocity(body.transform.p) - body.linearVelocity;
  const Real speed = relative.norm();
  if (speed == 0 || body.mass <= 0) return Vec2::Zero();
  const Real width = widthAcross(body.shapes, body.transform.q, relative / speed);
  Real force = Real(0.5) * kAirDensity * kDragCoefficient * width * speed * speed;
  // The air can bring a body up to its own speed, not past it in one step.
  if (dt > 0) force = std::min(force, body.mass * speed / dt);
  return force / speed * relative;
}

void Fan::findShadows(const FieldStep& step) const {
  blockers_.clear();
  auto consider = [&](const FieldBody& body, int moving) {
    const Bearing bearing = bearingOf(body.transform.p);
    // A body reaching into the cone may shade others though its centre is outside.
    if (bearing.distance <= 0 || bearing.distance - body.extent >= def_.range) return;
    const Real halfWidth = std::asin(std::min(Real(1), body.extent / bearing.distance));
    if (std::abs(bearing.angle) - halfWidth > def_.spread) return;
    blockers_.push_back({bearing.distance, bearing.angle, halfWidth, moving});
  };
  for (std::size_t i = 0; i < step.bodies.size(); ++i) consider(step.bodies[i], static_cast<int>(i));
  std::ranges::sort(blockers_, [](const Blocker& a, const Blocker& b) { return a.distance < b.distance; });

  shadowed_.assign(step.bodies.size(), 0);
  shadows_.clear();  // covered angle intervals, sorted and disjoint
  for (const Blocker& blocker : blockers_) {
    auto after = std::ranges::upper_bound(shadows_, blocker.angle, {}, &std::pair<Real, Real>::first);
    const bool hidden = after != shadows_.begin() && std::prev(after)->second >= blocker.angle;
    shadowed_[blocker.moving] = hidden;
    // Merge this body's interval into the covered ones.
    Real low = blocker.angle - blocker.halfWidth, high = blocker.angle + blocker.halfWidth;
    auto first = std::ranges::lower_bound(shadows_, low, {}, &std::pair<Real, Real>::second);
    auto last = first;
    while (last != shadows_.end() && last->first <= high) {
      low = std::min(low, last->first);
      high = std::max(high, last->second);
      ++last;
    }
    first = shadows_.erase(first, last);
    shadows_.insert(first, {low, high});
  }
}

void Fan::apply(const FieldStep& step, std::span<FieldLoad> loads) const {
  findShadows(step);
  for (std::size_t i = 0; i < step.bodies.size(); ++i) {
    if (!shadowed_[i]) loads[i].force += dragOn(step.bodies[i], step.dt);
  }
}

FieldBuild makeFan(const FanDef& def) {
  if (std::string error = checkFan(def); !error.empty()) return {nullptr, error};
  return {std::make_shared<Fan>(def), {}};
}

}  // namespace impulse
