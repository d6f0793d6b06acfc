#include "impulse/server/interest_area.h"

#include <algorithm>
#include <cmath>

#include "impulse/field_kinds.h"
#include "impulse/shape.h"
#include "impulse/server/message_format.h"
#include "impulse/server/wire_box.h"

namespace impulse::server {

InterestAreaRequest interestAreaFromWire(const v1::SetInterestArea& command) {
  static constexpr WireBoxRules kRules{.message = "set_interest_area",
                                       .minField = "min",
                                       .maxField = "max",
                                       .what = "area",
                                       .bothOrNeither = "leave out both corners for the whole room",
                                       .maxSide = kMaxInterestAreaSide};
  WireBox area = boxFromWire(command.has_min() ? &command.min() : nullptr,
                             command.has_max() ? &command.max() : nullptr, kRules);
  return {area.box, std::move(area.error)};
}

BudgetRequest budgetFromWire(const v1::SetBandwidthBudget& command) {
  if (!command.has_bytes_per_second()) return {};
  const double rate = command.bytes_per_second();
  if (!(rate >= kMinBudgetBytesPerSecond && rate <= kMaxBudgetBytesPerSecond)) {
    return {{}, formatted("set_bandwidth_budget.bytes_per_second %g must be in [%.0f, %.0f] (leave it out for no "
                          "budget)", rate, kMinBudgetBytesPerSecond, kMaxBudgetBytesPerSecond)};
  }
  return {rate, {}};
}

// ------------------------------------------------------------------ places

Real BodyPlaces::reachOf(const World& world, std::uint32_t id) {
  const auto known = reaches_.find(id);
  if (known != reaches_.end()) return known->second;
  Real reach = 0;
  if (const auto description = world.bodyDescription(BodyId{id})) {
    for (const ShapeDescription& shape : description->shapes) reach = std::max(reach, computeExtent(shape.shape));
  }
  reaches_.emplace(id, reach);
  return reach;
}

void BodyPlaces::update(const World& world, const WorldChanges& changes) {
  if (changes.wasReplaced()) return rebuild(world);
  // A body described again may have new shapes; a removed one's id is
  // never reused within the world's life.
  for (const BodyId id : changes.addedIds()) reaches_.erase(id.value);
  for (const BodyId id : changes.removedIds()) reaches_.erase(id.value);
  places_.clear();
  for (const BodyId id : world.bodyIds()) {
    if (const auto state = world.bodyState(id)) {
      places_.push_back({id.value, state->position, reachOf(world, id.value), state->linearVelocity});
    }
  }
  std::ranges::sort(places_, {}, &BodyPlace::id);
  takeJointsAndFields(world);
}

namespace {

/// Where a field acts: a fluid's polygon, a fan's range about it; a field
/// of the bodies themselves acts everywhere.
std::optional<AABB> fieldReach(const FieldDef& def) {
  if (const auto* fluid = std::get_if<FluidDef>(&def)) {
    AABB box{fluid->polygon.front(), fluid->polygon.front()};
    for (const Vec2& point : fluid->polygon) box = AABB{box.lower.cwiseMin(point), box.upper.cwiseMax(point)};
    return box;
  }
  if (const auto* fan = std::get_if<FanDef>(&def)) {
    const Vec2 range(fan->range, fan->range);
    return AABB{fan->position - range, fan->position + range};
  }
  return std::nullopt;
}

}  // namespace

void BodyPlaces::takeJointsAndFields(const World& world) {
  joints_.clear();
  for (const JointId id : world.jointIds()) {
    if (const auto joint = world.jointDescription(id)) joints_.push_back({id.value, joint->bodyA.value, joint->bodyB.value});
  }
  std::ranges::sort(joints_, {}, &JointPlace::id);
  fields_.clear();
  for (const FieldId id : world.fieldIds()) {
    const ForceField* field = world.field(id);
    const auto def = field ? describeField(*field) : std::nullopt;
    if (def) fields_.push_back({id.value, fieldReach(*def)});
  }
  std::ranges::sort(fields_, {}, &FieldPlace::id);
}

void BodyPlaces::jointsOf(const std::vector<std::uint32_t>& bodies, std::vector<std::uint32_t>& ids) const {
  ids.clear();
  const auto held = [&](std::uint32_t body) { return body != 0 && std::ranges::binary_search(bodies, body); };
  for (const JointPlace& joint : joints_) {
    if (held(joint.bodyA) || held(joint.bodyB)) ids.push_back(joint.id);
  }
}

void BodyPlaces::fieldsIn(const std::optional<AABB>& area, std::vector<std::uint32_t>& ids) const {
  ids.clear();
  for (const FieldPlace& field : fields_) {
    if (!area || !field.reach || area->overlaps(*field.reach)) ids.push_back(field.id);
  }
}

void BodyPlaces::rebuild(const World& world) {
  reaches_.clear();
  update(world, WorldChanges{});
}

const BodyPlace* BodyPlaces::find(std::uint32_t id) const {
  const auto place = std::ranges::lower_bound(places_, id, {}, &BodyPlace::id);
  return place != places_.end() && place->id == id ? &*place : nullptr;
}

void BodyPlaces::inside(const AABB& area, std::vector<std::uint32_t>& ids) const {
  ids.clear();
  for (const BodyPlace& place : places_) {
    const Vec2 nearest = place.centre.cwiseMax(area.lower).cwiseMin(area.upper);
    if ((place.centre - nearest).squaredNorm() <= place.reach * place.reach) ids.push_back(place.id);
  }
}

}  // namespace impulse::server
