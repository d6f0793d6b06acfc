#include "impulse/server/interest_area.h"

#include <algorithm>
#include <cmath>

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
