// Contact events: which contacts report, the events they make, and their
// publication in a fixed order at the end of the step.

#include "contact_events.h"

#include <algorithm>
#include <tuple>

namespace impulse {

namespace {

// The pair's ids with the lower one first, as the events list them.
struct OrderedPair {
  ShapeId shapeA, shapeB;
  BodyId bodyA, bodyB;
  bool swapped = false;
};

OrderedPair orderedPair(const WorldData& world, const Contact& contact) {
  OrderedPair pair{world.shapeIdOf(contact.shapeA), world.shapeIdOf(contact.shapeB),
                   world.idOf(contact.edges.bodyA), world.idOf(contact.edges.bodyB)};
  if (pair.shapeB.value < pair.shapeA.value) {
    std::swap(pair.shapeA, pair.shapeB);
    std::swap(pair.bodyA, pair.bodyB);
    pair.swapped = true;
  }
  return pair;
}

// Closing speed of the point along the normal (A to B): positive when B
// moves towards A.
Real approachSpeed(const Body& a, const Body& b, const ManifoldPoint& point, const Vec2& normal) {
  auto velocityAt = [](const Body& body, const Vec2& arm) -> Vec2 {
    return body.linearVelocity + body.angularVelocity * Vec2(-arm.y(), arm.x());
  };
  return -(velocityAt(b, point.anchorB) - velocityAt(a, point.anchorA)).dot(normal);
}

template <typename Event>
void sortByShapes(std::vector<Event>& events) {
  std::stable_sort(events.begin(), events.end(), [](const Event& x, const Event& y) {
    return std::tie(x.shapeA.value, x.shapeB.value) < std::tie(y.shapeA.value, y.shapeB.value);
  });
}

void sortSensorEvents(std::vector<SensorEvent>& events) {
  std::stable_sort(events.begin(), events.end(), [](const SensorEvent& x, const SensorEvent& y) {
    return std::tie(x.sensor.value, x.visitor.value) < std::tie(y.sensor.value, y.visitor.value);
  });
}

}  // namespace

void setContactEventFlags(const WorldData& world, Contact& contact) {
  const ShapeInteraction& a = world.shapes[contact.shapeA].interaction;
  const ShapeInteraction& b = world.shapes[contact.shapeB].interaction;
  contact.reportsTouch = a.enableContactEvents || b.enableContactEvents;
  contact.reportsHits = a.enableHitEvents || b.enableHitEvents;
}

void reportTouchChange(WorldData& world, const Contact& contact) {
  if (!contact.reportsTouch) return;
  const OrderedPair pair = orderedPair(world, contact);
  if (contact.touching) {
    world.pendingEvents.contactBegins.push_back({pair.shapeA, pair.shapeB, pair.bodyA, pair.bodyB});
  } else {
    world.pendingEvents.contactEnds.push_back({pair.shapeA, pair.shapeB, pair.bodyA, pair.bodyB});
  }
}

void reportHit(WorldData& world, const Contact& contact, Real dt) {
  const Manifold& manifold = contact.manifold;
  const Body& a = world.bodies[contact.edges.bodyA];
  const Body& b = world.bodies[contact.edges.bodyB];
  int fastest = -1;
  Real fastestSpeed = world.settings.hitEventThreshold;
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ManifoldPoint& point = manifold.points[i];
    const Real speed = approachSpeed(a, b, point, manifold.normal);
    if (speed > fastestSpeed && point.separation < speed * dt + kLinearSlop) {
      fastest = i;
      fastestSpeed = speed;
    }
  }
  if (fastest < 0) return;
  const OrderedPair pair = orderedPair(world, contact);
  const Vec2 normal = pair.swapped ? Vec2(-manifold.normal) : manifold.normal;
  world.pendingEvents.contactHits.push_back(
      {pair.shapeA, pair.shapeB, pair.bodyA, pair.bodyB, manifold.points[fastest].point, normal, fastestSpeed});
}

void publishEvents(WorldData& world) {
  StepEvents& events = world.pendingEvents;
  sortByShapes(events.contactBegins);
  sortByShapes(events.contactEnds);
  sortByShapes(events.contactHits);
  sortSensorEvents(events.sensorBegins);
  sortSensorEvents(events.sensorEnds);
  std::swap(world.events, world.pendingEvents);
  world.pendingEvents.clear();
}

}  // namespace impulse
