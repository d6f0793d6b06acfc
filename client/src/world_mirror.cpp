#include "impulse/client/world_mirror.h"

#include "impulse/wire/convert.h"
#include "impulse/wire/field_convert.h"
#include "impulse/wire/wire_positions.h"

namespace impulse::client {

void WorldMirror::setOrigin(const Vec2d& origin) {
  origin_ = origin;
  decoder_.setOrigin(origin);
}

bool WorldMirror::apply(const v1::Snapshot& snapshot, std::string* error) {
  if (origin_ == Vec2d::Zero()) return applyRelative(snapshot, error);
  // Taken from every position in double, before it becomes a float.
  v1::Snapshot relative = snapshot;
  wire::shiftPositions(relative, -origin_);
  return applyRelative(relative, error);
}

bool WorldMirror::applyRelative(const v1::Snapshot& snapshot, std::string* error) {
  auto failed = [error](std::string message) {
    if (error != nullptr) *error = std::move(message);
    return false;
  };
  tick_ = snapshot.tick();
  simTime_ = snapshot.sim_time();
  gravity_ = wire::vecFromWireUnchecked(snapshot.gravity());
  paused_ = snapshot.paused();
  timeScale_ = snapshot.time_scale() > 0 ? snapshot.time_scale() : 1;
  if (snapshot.has_preset()) preset_ = wire::presetFromWire(snapshot.preset());
  if (snapshot.full()) {
    bodies_.clear();
    joints_.clear();
    fields_.clear();
  }
  ++snapshotsApplied_;

  for (const std::uint32_t id : snapshot.removed()) bodies_.erase(id);
  // Out of this client's area of interest: forgotten until it comes back.
  for (const std::uint32_t id : snapshot.left_area()) bodies_.erase(id);
  for (const std::uint32_t id : snapshot.joints_removed()) joints_.erase(id);
  for (const std::uint32_t id : snapshot.fields_removed()) fields_.erase(id);
  for (const auto& descriptor : snapshot.added()) {
    auto shape = wire::shapeFromWire(descriptor.shape());
    if (!shape.ok()) {
      return failed("body " + std::to_string(descriptor.id()) + ": " + shape.error);
    }
    auto material = wire::materialFromWire(descriptor.material());
    MirrorBody body;
    body.id = BodyId{descriptor.id()};
    body.shape = *shape.value;
    for (const auto& extra : descriptor.extra_shapes()) {
      auto decoded = wire::shapeFromWire(extra);
      if (!decoded.ok()) return failed("body " + std::to_string(descriptor.id()) + ": " + decoded.error);
      body.extraShapes.push_back(*decoded.value);
    }
    body.isKinematic = descriptor.is_kinematic();
    body.material = material.value_or(Material::Solid);
    body.isStatic = descriptor.is_static();
    body.ignoreGravity = descriptor.ignore_gravity();
    body.flags = wire::shapeFlagsFromWire(descriptor.shape_flags());
    body.shapeIds.assign(descriptor.shape_ids().begin(), descriptor.shape_ids().end());
    body.state.id = body.id;
    bodies_[descriptor.id()] = body;
  }
  if (!snapshot.quantized_bodies().empty()) {
    if (auto problem = applyQuantized(snapshot)) return failed(std::move(*problem));
  } else if (snapshot.full()) {
    decoder_.forget();
  }
  for (const auto& state : snapshot.bodies()) {
    const auto it = bodies_.find(state.id());
    if (it == bodies_.end()) {
      return failed("state for unknown body " + std::to_string(state.id()));
    }
    it->second.state = wire::stateFromWire(state);
  }
  // joints_added both adds and replaces (a changed motor speed or target).
  for (const auto& descriptor : snapshot.joints_added()) {
    auto joint = wire::jointFromWire(descriptor);
    if (!joint) return failed("joint " + std::to_string(descriptor.id()) + " has no kind");
    joints_[descriptor.id()] = *joint;
  }
  for (const auto& descriptor : snapshot.fields_added()) {
    auto field = wire::fieldFromWire(descriptor);
    if (!field) return failed("field " + std::to_string(descriptor.id()) + " has no kind");
    fields_.insert_or_assign(descriptor.id(), std::move(*field));
  }
  return true;
}

std::optional<std::string> WorldMirror::applyQuantized(const v1::Snapshot& snapshot) {
  addedIds_.clear();
  for (const auto& descriptor : snapshot.added()) addedIds_.push_back(descriptor.id());
  const std::span<const std::uint32_t> removed(snapshot.removed().data(),
                                               std::size_t(snapshot.removed_size()));
  if (auto problem = decoder_.decode(snapshot.quantized_bodies(), snapshot.full(), removed,
                                     addedIds_, decoded_)) {
    return problem;
  }
  for (const BodyState& state : decoded_) {
    const auto it = bodies_.find(state.id.value);
    if (it == bodies_.end()) return "state for unknown body " + std::to_string(state.id.value);
    it->second.state = state;
  }
  return std::nullopt;
}

const MirrorBody* WorldMirror::find(BodyId id) const {
  const auto it = bodies_.find(id.value);
  return it == bodies_.end() ? nullptr : &it->second;
}

}  // namespace impulse::client
