#pragma once
/// What happened between shapes in a step: contacts that began or ended
/// touching, hard hits, and shapes entering or leaving sensors.
///
/// Only shapes that ask for them (ShapeInteraction) produce events. Each list
/// is sorted by its pair of shape ids, so a world replayed, or saved and
/// loaded, reports the same events in the same order.

#include <vector>

#include "impulse/body.h"
#include "impulse/math.h"

namespace impulse {

/// Two shapes began touching (their contact has points, within the
/// speculative distance), or stopped: they moved apart, or one of them (or
/// its body) was removed, and the ids may then be stale. shapeA's id is
/// below shapeB's.
struct ContactTouchEvent {
  ShapeId shapeA;
  ShapeId shapeB;
  BodyId bodyA;
  BodyId bodyB;
  friend bool operator==(const ContactTouchEvent&, const ContactTouchEvent&) = default;
};

/// A touching pair closing faster than WorldSettings::hitEventThreshold
/// that meets within the step: where, along which normal (from A to B) and
/// how fast (m/s, the fastest of the manifold's points).
struct ContactHitEvent {
  ShapeId shapeA;
  ShapeId shapeB;
  BodyId bodyA;
  BodyId bodyB;
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();
  Real approachSpeed = 0;
  friend bool operator==(const ContactHitEvent&, const ContactHitEvent&) = default;
};

/// A shape began or stopped overlapping a sensor (the visitor's id may be
/// stale when it was removed).
struct SensorEvent {
  ShapeId sensor;
  ShapeId visitor;
  BodyId sensorBody;
  BodyId visitorBody;
  friend bool operator==(const SensorEvent&, const SensorEvent&) = default;
};

/// The events of one step, each list sorted by its pair of shape ids.
struct StepEvents {
  std::vector<ContactTouchEvent> contactBegins;
  std::vector<ContactTouchEvent> contactEnds;
  std::vector<ContactHitEvent> contactHits;
  std::vector<SensorEvent> sensorBegins;
  std::vector<SensorEvent> sensorEnds;

  bool empty() const {
    return contactBegins.empty() && contactEnds.empty() && contactHits.empty() && sensorBegins.empty() &&
           sensorEnds.empty();
  }
  void clear() {
    contactBegins.clear();
    contactEnds.clear();
    contactHits.clear();
    sensorBegins.clear();
    sensorEnds.clear();
  }
};

}  // namespace impulse
