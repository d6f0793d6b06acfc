// Sensors: shapes that report what overlaps them and never collide. After
// each step every sensor finds the shapes overlapping it (through the broad
// phase, then exactly), and the difference from the step before becomes
// begin and end events.

#include <algorithm>

#include "world_data.h"

namespace impulse {

namespace {

bool visitorBefore(const SensorVisitor& a, const SensorVisitor& b) { return a.shape.value < b.shape.value; }

bool sameVisitor(const SensorVisitor& a, const SensorVisitor& b) { return a.shape == b.shape; }

// Whether the sensor may see the shape at all (before any geometry).
bool mayVisit(const ShapeSlot& sensor, const ShapeSlot& visitor) {
  if (visitor.body == sensor.body || visitor.interaction.isSensor) return false;
  if (!visitor.interaction.enableSensorEvents) return false;
  return shouldCollide(sensor.interaction.filter, visitor.interaction.filter);
}

// The shapes overlapping the sensor now, sorted by id, into `visitors`.
void findVisitors(const WorldData& world, std::int32_t sensorShape, std::vector<SensorVisitor>& visitors) {
  visitors.clear();
  const ShapeSlot& sensor = world.shapes[sensorShape];
  const Transform& sensorPose = world.bodies[sensor.body].transform;
  const AABB box = shapeAABB(world, sensorShape);
  world.broadPhase.query(box, [&](std::int32_t other) {
    const ShapeSlot& visitor = world.shapes[other];
    if (!mayVisit(sensor, visitor) || !shapeAABB(world, other).overlaps(box)) return true;
    const Transform& visitorPose = world.bodies[visitor.body].transform;
    if (computeSeparation(sensor.ref(), sensorPose, visitor.ref(), visitorPose) < 0) {
      visitors.push_back({world.shapeIdOf(other), world.idOf(visitor.body)});
    }
    return true;
  });
  std::sort(visitors.begin(), visitors.end(), visitorBefore);
}

// Events for the visitors in one sorted list and not the other.
void reportDifference(const std::vector<SensorVisitor>& from, const std::vector<SensorVisitor>& to,
                      ShapeId sensor, BodyId sensorBody, std::vector<SensorEvent>& events,
                      std::vector<SensorVisitor>& scratch) {
  scratch.clear();
  std::set_difference(from.begin(), from.end(), to.begin(), to.end(), std::back_inserter(scratch), visitorBefore);
  for (const SensorVisitor& visitor : scratch) events.push_back({sensor, visitor.shape, sensorBody, visitor.body});
}

}  // namespace

void addSensor(WorldData& world, std::int32_t shape) {
  auto place = std::lower_bound(world.sensors.begin(), world.sensors.end(), shape,
                                [](const Sensor& sensor, std::int32_t slot) { return sensor.shape < slot; });
  world.sensors.insert(place, Sensor{shape, {}});
}

void removeSensor(WorldData& world, std::int32_t shape) {
  std::erase_if(world.sensors, [&](const Sensor& sensor) { return sensor.shape == shape; });
}

void updateSensors(WorldData& world, Real /*dt*/) {
  std::vector<SensorVisitor>& now = world.sensorScratch;
  for (Sensor& sensor : world.sensors) {
    findVisitors(world, sensor.shape, now);
    if (std::equal(now.begin(), now.end(), sensor.visitors.begin(), sensor.visitors.end(), sameVisitor)) continue;
    const ShapeId sensorId = world.shapeIdOf(sensor.shape);
    const BodyId sensorBody = world.idOf(world.shapes[sensor.shape].body);
    StepEvents& events = world.pendingEvents;
    reportDifference(now, sensor.visitors, sensorId, sensorBody, events.sensorBegins, world.sensorChanges);
    reportDifference(sensor.visitors, now, sensorId, sensorBody, events.sensorEnds, world.sensorChanges);
    sensor.visitors.swap(now);
  }
}

void rebuildSensors(WorldData& world) {
  world.sensors.clear();
  for (std::size_t s = 0; s < world.shapes.size(); ++s) {
    const ShapeSlot& slot = world.shapes[s];
    if (slot.alive && slot.interaction.isSensor) world.sensors.push_back({std::int32_t(s), {}});
  }
  for (Sensor& sensor : world.sensors) findVisitors(world, sensor.shape, sensor.visitors);
}

}  // namespace impulse
