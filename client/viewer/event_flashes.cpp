#include "event_flashes.h"

#include <algorithm>

#include "impulse/wire/convert.h"

namespace impulse::viewer {

HitMark hitMark(double approachSpeed) {
  constexpr double kFullSpeed = 16;
  const double t = std::clamp(approachSpeed / kFullSpeed, 0.0, 1.0);
  return {Real(0.08 + 0.32 * t), float(0.35 + 0.65 * t)};
}

void EventFlashes::push(Flash flash) {
  if (flashes_.size() >= kMaxFlashes) flashes_.erase(flashes_.begin());
  flashes_.push_back(flash);
}

void EventFlashes::add(const v1::Events& events, double time, double now) {
  for (const v1::HitEvent& hit : events.hits()) {
    push({.kind = Flash::Kind::Hit,
          .point = wire::vecFromWireUnchecked(hit.point()),
          .speed = hit.approach_speed(),
          .time = time,
          .arrived = now});
  }
  for (const v1::ContactEvent& contact : events.contact_begins()) {
    for (const std::uint32_t body : {contact.body_a(), contact.body_b()}) {
      push({.kind = Flash::Kind::ContactBegin, .body = body, .time = time, .arrived = now});
    }
  }
  for (const v1::SensorEvent& visit : events.sensor_begins()) {
    push({.kind = Flash::Kind::SensorBegin,
          .body = visit.sensor_body(),
          .time = time,
          .arrived = now});
  }
}

void EventFlashes::update(double drawnTime, double now) {
  for (Flash& flash : flashes_) {
    if (flash.start < 0 && drawnTime >= flash.time) flash.start = now;
  }
  std::erase_if(flashes_, [&](const Flash& flash) {
    return flash.start < 0 ? now - flash.arrived > kMaxWaitSeconds
                           : now - flash.start >= kFadeSeconds;
  });
}

float EventFlashes::intensity(const Flash& flash, double now) {
  if (flash.start < 0) return 0;
  return float(std::clamp(1 - (now - flash.start) / kFadeSeconds, 0.0, 1.0));
}

}  // namespace impulse::viewer
