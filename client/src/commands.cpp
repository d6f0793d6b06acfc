#include "impulse/client/commands.h"

#include "impulse/wire/convert.h"

namespace impulse::client {

namespace {

void setPoint(Point p, v1::Vec2* out) {
  out->set_x(p.x);
  out->set_y(p.y);
}

void setOptions(const SpawnOptions& options, v1::BodyOptions* out) {
  out->set_material(wire::toWire(options.material));
  out->set_is_static(options.isStatic);
  out->set_ignore_gravity(options.ignoreGravity);
  setPoint({options.velocityX, options.velocityY}, out->mutable_velocity());
  out->set_angular_velocity(options.angularVelocity);
}

}  // namespace

v1::ClientMessage spawnCircle(Point center, double radius, const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_circle();
  setPoint(center, command->mutable_center());
  command->set_radius(radius);
  setOptions(options, command->mutable_options());
  return message;
}

v1::ClientMessage spawnPolygon(std::span<const Point> vertices, const SpawnOptions& options) {
  v1::ClientMessage message;
  auto* command = message.mutable_spawn_polygon();
  for (const Point& p : vertices) setPoint(p, command->add_vertices());
  setOptions(options, command->mutable_options());
  return message;
}

v1::ClientMessage loadPreset(int preset, Material material) {
  v1::ClientMessage message;
  message.mutable_load_preset()->set_preset(preset);
  message.mutable_load_preset()->set_material(wire::toWire(material));
  return message;
}

v1::ClientMessage setGravity(Point gravity) {
  v1::ClientMessage message;
  setPoint(gravity, message.mutable_set_gravity()->mutable_gravity());
  return message;
}

v1::ClientMessage nudgeGravity(Point delta) {
  v1::ClientMessage message;
  setPoint(delta, message.mutable_nudge_gravity()->mutable_delta());
  return message;
}

v1::ClientMessage resetGravity() {
  v1::ClientMessage message;
  message.mutable_reset_gravity();
  return message;
}

v1::ClientMessage clearWorld() {
  v1::ClientMessage message;
  message.mutable_clear();
  return message;
}

v1::ClientMessage removeBody(std::uint32_t id) {
  v1::ClientMessage message;
  message.mutable_remove_body()->set_body_id(id);
  return message;
}

v1::ClientMessage applyImpulse(std::uint32_t id, Point impulse, std::optional<Point> point) {
  v1::ClientMessage message;
  auto* command = message.mutable_apply_impulse();
  command->set_body_id(id);
  setPoint(impulse, command->mutable_impulse());
  if (point) setPoint(*point, command->mutable_point());
  return message;
}

v1::ClientMessage setPaused(bool paused) {
  v1::ClientMessage message;
  message.mutable_set_paused()->set_paused(paused);
  return message;
}

v1::ClientMessage step(std::uint32_t ticks) {
  v1::ClientMessage message;
  message.mutable_step()->set_ticks(ticks);
  return message;
}

v1::ClientMessage queryBody(std::uint32_t id) {
  v1::ClientMessage message;
  message.mutable_query_body()->set_body_id(id);
  return message;
}

v1::ClientMessage ping(std::uint64_t clientTimeUs, bool wantStateHash) {
  v1::ClientMessage message;
  message.mutable_ping()->set_client_time_us(clientTimeUs);
  message.mutable_ping()->set_want_state_hash(wantStateHash);
  return message;
}

}  // namespace impulse::client
