#include "impulse/wire/event_convert.h"

#include "impulse/wire/convert.h"

namespace impulse::wire {

namespace {

void fill(const ContactTouchEvent& event, v1::ContactEvent* out) {
  out->set_body_a(event.bodyA.value);
  out->set_body_b(event.bodyB.value);
  out->set_shape_a(event.shapeA.value);
  out->set_shape_b(event.shapeB.value);
}

void fill(const ContactHitEvent& event, v1::HitEvent* out) {
  out->set_body_a(event.bodyA.value);
  out->set_body_b(event.bodyB.value);
  out->set_shape_a(event.shapeA.value);
  out->set_shape_b(event.shapeB.value);
  toWire(event.point, out->mutable_point());
  toWire(event.normal, out->mutable_normal());
  out->set_approach_speed(event.approachSpeed);
}

void fill(const SensorEvent& event, v1::SensorEvent* out) {
  out->set_sensor_body(event.sensorBody.value);
  out->set_visitor_body(event.visitorBody.value);
  out->set_sensor_shape(event.sensor.value);
  out->set_visitor_shape(event.visitor.value);
}

// Copies the list while the message has room; false once it had to stop.
template <typename Event, typename Field>
bool copyWithin(const std::vector<Event>& events, Field* field, int& room) {
  for (const Event& event : events) {
    if (room == 0) return false;
    fill(event, field->Add());
    --room;
  }
  return true;
}

}  // namespace

void toWire(const StepEvents& events, std::uint64_t tick, std::uint64_t sequence, v1::Events* out) {
  out->set_tick(tick);
  out->set_sequence(sequence);
  int room = kMaxEventsPerMessage;
  const bool complete = copyWithin(events.contactBegins, out->mutable_contact_begins(), room) &&
                        copyWithin(events.contactEnds, out->mutable_contact_ends(), room) &&
                        copyWithin(events.contactHits, out->mutable_hits(), room) &&
                        copyWithin(events.sensorBegins, out->mutable_sensor_begins(), room) &&
                        copyWithin(events.sensorEnds, out->mutable_sensor_ends(), room);
  out->set_truncated(!complete);
}

}  // namespace impulse::wire
