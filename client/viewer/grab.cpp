#include "grab.h"

namespace impulse::viewer {

Vec2 grabImpulse(const GrabbedMotion& body, const Vec2& offset, const Vec2& cursor,
                 const Vec2& gravity, double interval, const GrabSettings& settings) {
  const Vec2 toCursor = cursor - (body.position + offset);
  Vec2 wanted = toCursor * Real(settings.gain);
  const Real speed = wanted.norm();
  if (speed > Real(settings.maxSpeed)) wanted *= Real(settings.maxSpeed) / speed;
  const Vec2 velocityChange = wanted - body.velocity - gravity * Real(interval);
  return velocityChange * Real(body.mass);
}

}  // namespace impulse::viewer
