// Input limits: every physical number a caller hands the engine is checked
// here before it touches the world. Products are formed in double, so a
// request of 3e38 is measured and refused instead of overflowing float.

#include "input_limits.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace impulse {

namespace {

// A pair of numbers as "(x, y)", each written by `describe`.
template <class Describe>
std::string pair(double x, double y, Describe describe) {
  // Appended piece by piece: GCC 12 warns (falsely, -Wrestrict) on "(" + string.
  std::string text = "(";
  text += describe(x);
  text += ", ";
  text += describe(y);
  text += ')';
  return text;
}

std::string vector(const Vec2& v) { return pair(v.x(), v.y(), describeNumber); }

// A float as its shortest decimal says it: 37.3f holds 37.2999992, and 37.3
// is what its caller wrote.
double asWritten(Real value) {
  char text[32];
  const char* end = std::to_chars(text, text + sizeof text, value).ptr;
  double written = 0;
  std::from_chars(text, end, written);
  return written;
}

// A position as the caller's level has it: from (0, 0), the world's origin
// added in double, so a world moved far out quotes the numbers its user
// gives and sees, not the float frame's.
std::string globalPosition(const Vec2d& origin, const Vec2& p) {
  return pair(origin.x() + asWritten(p.x()), origin.y() + asWritten(p.y()), describeCoordinate);
}

double length(double x, double y) { return std::hypot(x, y); }

// The dynamic body a push may act on, or the reason there is none.
std::string pushTarget(const WorldData& world, BodyId id, const Body*& body) {
  body = world.find(id);
  if (body == nullptr) return "unknown body id " + std::to_string(id.value);
  if (body->isStatic) return "body " + std::to_string(id.value) + " is static";
  return {};
}

// A push (impulse or force) moves dynamic bodies only.
std::string pushableTarget(const WorldData& world, BodyId id, const Body*& body) {
  if (std::string error = pushTarget(world, id, body); !error.empty()) return error;
  if (body->isKinematic) {
    return "body " + std::to_string(id.value) +
           " is kinematic: it moves by its velocity only (set its velocity or its target instead)";
  }
  return {};
}

std::string checkFinite(const Vec2& value, const char* field) {
  if (isFinite(value)) return {};
  return std::string(field) + " is not a finite number (NaN or infinity)";
}

// r x F of a push at `point` on `body`, in double.
double leverMoment(const Body& body, const std::optional<Vec2>& point, const Vec2& push) {
  if (!point) return 0;
  const double rx = double(point->x()) - double(body.transform.p.x());
  const double ry = double(point->y()) - double(body.transform.p.y());
  return rx * double(push.y()) - ry * double(push.x());
}

// Finite numbers and a point where a push can act.
std::string checkPush(const WorldData& world, const Vec2& push, const std::optional<Vec2>& point,
                      const char* field, const char* pointField) {
  if (std::string error = checkFinite(push, field); !error.empty()) return error;
  return checkApplicationPoint(world.settings.inputLimits, world.settings.bounds, world.origin,
                               point, pointField);
}

}  // namespace

std::string checkRange(const std::string& field, double value, double lo, double hi) {
  if (std::isfinite(value) && value >= lo && value <= hi) return {};
  return field + " must be a finite number in [" + describeNumber(lo) + ", " + describeNumber(hi) +
         "]";
}

std::string describeNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string describeCoordinate(double value) {
  // Past any origin a world may have, six significant digits say enough.
  if (!(std::abs(value) < 2 * kMaxOriginCoordinate)) return describeNumber(value);
  char text[48];
  std::snprintf(text, sizeof text, "%.6f", value);
  std::string_view digits(text);
  while (digits.back() == '0') digits.remove_suffix(1);
  if (digits.back() == '.') digits.remove_suffix(1);
  return digits == "-0" ? "0" : std::string(digits);
}

std::string checkBodyMotion(const InputLimits& limits, const Vec2& linearVelocity,
                            Real angularVelocity) {
  if (std::string error = checkFinite(linearVelocity, "velocity"); !error.empty()) return error;
  if (!isFinite(angularVelocity)) return "angular velocity is not a finite number (NaN or infinity)";
  const MotionCheck linear{length(linearVelocity.x(), linearVelocity.y()), 0};
  if (std::string error = checkResultingMotion(limits, linear, "velocity"); !error.empty()) {
    return error;
  }
  const MotionCheck angular{0, std::abs(double(angularVelocity))};
  return checkResultingMotion(limits, angular, "angular velocity");
}

std::string checkGravity(const InputLimits& limits, const Vec2& gravity) {
  if (std::string error = checkFinite(gravity, "gravity"); !error.empty()) return error;
  if (std::abs(gravity.x()) > limits.maxGravity || std::abs(gravity.y()) > limits.maxGravity) {
    return "gravity " + vector(gravity) + ": components must lie within +-" +
           describeNumber(limits.maxGravity) + " m/s^2";
  }
  return {};
}

std::string checkApplicationPoint(const InputLimits& limits, const AABB& bounds,
                                  const Vec2d& origin, const std::optional<Vec2>& point,
                                  const char* field) {
  if (!point) return {};
  if (std::string error = checkFinite(*point, field); !error.empty()) return error;
  const Vec2 margin(limits.escapeMargin, limits.escapeMargin);
  const Vec2 lower = bounds.lower - margin;
  const Vec2 upper = bounds.upper + margin;
  const Vec2& p = *point;
  if (p.x() < lower.x() || p.y() < lower.y() || p.x() > upper.x() || p.y() > upper.y()) {
    return std::string(field) + " " + globalPosition(origin, p) + " is outside " +
           globalPosition(origin, lower) + " to " + globalPosition(origin, upper) +
           " (the world bounds grown by " + describeNumber(limits.escapeMargin) + " m)";
  }
  return {};
}

std::string checkResultingMotion(const InputLimits& limits, const MotionCheck& motion,
                                 const char* field) {
  if (!(motion.linearSpeed <= limits.maxSpeed)) {
    return std::string(field) + " gives a speed of " + describeNumber(motion.linearSpeed) +
           " m/s: speeds must lie within 0.." + describeNumber(limits.maxSpeed) + " m/s";
  }
  if (!(motion.angularSpeed <= limits.maxAngularSpeed)) {
    return std::string(field) + " gives an angular speed of " + describeNumber(motion.angularSpeed) +
           " rad/s: angular speeds must lie within 0.." + describeNumber(limits.maxAngularSpeed) + " rad/s";
  }
  return {};
}

std::string checkImpulse(const WorldData& world, BodyId id, const Vec2& impulse,
                         const std::optional<Vec2>& point) {
  const Body* body = nullptr;
  if (std::string error = pushableTarget(world, id, body); !error.empty()) return error;
  if (std::string error = checkPush(world, impulse, point, "impulse", "impulse point");
      !error.empty()) {
    return error;
  }
  const double vx = double(body->linearVelocity.x()) + double(body->invMass) * impulse.x();
  const double vy = double(body->linearVelocity.y()) + double(body->invMass) * impulse.y();
  const double w = double(body->angularVelocity) +
                   double(body->invInertia) * leverMoment(*body, point, impulse);
  return checkResultingMotion(world.settings.inputLimits, {length(vx, vy), std::abs(w)},
                              ("impulse " + vector(impulse) + " N*s").c_str());
}

std::string checkForce(const WorldData& world, BodyId id, const Vec2& force,
                       const std::optional<Vec2>& point) {
  const Body* body = nullptr;
  if (std::string error = pushableTarget(world, id, body); !error.empty()) return error;
  if (std::string error = checkPush(world, force, point, "force", "force point"); !error.empty()) {
    return error;
  }
  const InputLimits& limits = world.settings.inputLimits;
  const double fx = double(body->force.x()) + force.x();
  const double fy = double(body->force.y()) + force.y();
  const double acceleration = double(body->invMass) * length(fx, fy);
  if (!(acceleration <= limits.maxForceAcceleration)) {
    return "force " + vector(force) + " N gives an acceleration of " + describeNumber(acceleration) +
           " m/s^2: force / mass must lie within 0.." + describeNumber(limits.maxForceAcceleration) +
           " m/s^2";
  }
  const double torque = double(body->torque) + leverMoment(*body, point, force);
  const double angular = double(body->invInertia) * std::abs(torque);
  if (!(angular <= limits.maxTorqueAcceleration)) {
    return "force " + vector(force) + " N gives an angular acceleration of " + describeNumber(angular) +
           " rad/s^2: torque / inertia must lie within 0.." +
           describeNumber(limits.maxTorqueAcceleration) + " rad/s^2";
  }
  return {};
}

std::string checkOrigin(const Vec2d& origin) {
  const double limit = kMaxOriginCoordinate;
  std::string error = checkRange("origin x (m)", origin.x(), -limit, limit);
  return error.empty() ? checkRange("origin y (m)", origin.y(), -limit, limit) : error;
}

std::string checkInsideBounds(const WorldData& world, const Vec2& p) {
  const AABB& bounds = world.settings.bounds;
  if (p.x() >= bounds.lower.x() && p.y() >= bounds.lower.y() && p.x() <= bounds.upper.x() &&
      p.y() <= bounds.upper.y()) {
    return {};
  }
  return "position is outside the world bounds " + globalPosition(world.origin, bounds.lower) +
         " to " + globalPosition(world.origin, bounds.upper);
}

std::string checkSetVelocity(const WorldData& world, BodyId id, const Vec2& linear, Real angular) {
  const Body* body = nullptr;
  if (std::string error = pushTarget(world, id, body); !error.empty()) return error;
  return checkBodyMotion(world.settings.inputLimits, linear, angular);
}

}  // namespace impulse
