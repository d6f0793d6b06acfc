#pragma once
/// Dragging a body by hand without a mouse joint on the server: at a steady
/// rate the viewer sends the impulse that changes the body's velocity to one
/// that carries the grabbed point towards the cursor (and cancels the
/// gravity of the next interval). On release nothing more is sent, so the
/// body flies on with the cursor's speed: a throw.

#include <cstdint>

#include "impulse/math.h"

namespace impulse::viewer {

struct GrabSettings {
  /// The grabbed point closes this fraction of its distance to the cursor
  /// per second (a velocity gain, 1/s).
  double gain = 10;
  /// Speed limit of the dragged body, m/s.
  double maxSpeed = 25;
};

/// The newest known motion of the grabbed body.
struct GrabbedMotion {
  Vec2 position = Vec2::Zero();  ///< centre of mass
  Vec2 velocity = Vec2::Zero();
  double mass = 0;
};

/// The impulse (N*s) to apply at the centre of mass so that the point at
/// `offset` from the centre heads for `cursor`; `interval` is the time until
/// the next such impulse, over which `gravity` would otherwise pull.
Vec2 grabImpulse(const GrabbedMotion& body, const Vec2& offset, const Vec2& cursor,
                 const Vec2& gravity, double interval, const GrabSettings& settings = {});

}  // namespace impulse::viewer
