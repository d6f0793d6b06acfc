#pragma once
/// Dragging a body by hand through a mouse joint on the server: the press
/// point of the body is pulled towards the cursor by a critically damped
/// spring whose force is capped, so a heavy body lags and a light one
/// follows. On release the joint is removed and the body flies on with the
/// speed it had: a throw.

#include "impulse.pb.h"

namespace impulse::viewer {

struct GrabSettings {
  /// The spring's natural frequency (Hz): how briskly the body follows.
  double frequency = 5;
  /// 1 is critical damping: no overshoot at the cursor.
  double dampingRatio = 0.9;
  /// The largest acceleration the hand gives the body (m/s^2), about 50 g:
  /// enough to lift anything, not enough to fling it through walls.
  double maxAcceleration = 500;
};

/// A body of `mass` kg: stiffness m*w^2 and damping 2*zeta*m*w give the same
/// motion whatever the mass; the force cap scales with it too.
v1::MouseJoint mouseSpring(double mass, const GrabSettings& settings = {});

}  // namespace impulse::viewer
