#include "grab.h"

#include <numbers>

namespace impulse::viewer {

v1::MouseJoint mouseSpring(double mass, const GrabSettings& settings) {
  const double omega = 2 * std::numbers::pi * settings.frequency;
  v1::MouseJoint spring;
  spring.set_stiffness(mass * omega * omega);
  spring.set_damping(2 * settings.dampingRatio * mass * omega);
  spring.set_max_force(mass * settings.maxAcceleration);
  return spring;
}

}  // namespace impulse::viewer
