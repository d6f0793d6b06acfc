#include "impulse/server/interest_area.h"

#include <algorithm>
#include <cmath>

#include "impulse/shape.h"
#include "impulse/server/message_format.h"

namespace impulse::server {

namespace {

bool finite(const v1::Vec2& point) { return std::isfinite(point.x()) && std::isfinite(point.y()); }

}  // namespace

InterestAreaRequest interestAreaFromWire(const v1::SetInterestArea& command) {
  if (!command.has_min() && !command.has_max()) return {};
  if (!command.has_min()) return {{}, "set_interest_area.min is missing (leave out both corners for the whole room)"};
  if (!command.has_max()) return {{}, "set_interest_area.max is missing (leave out both corners for the whole room)"};
  if (!finite(command.min())) return {{}, "set_interest_area.min is not a finite point"};
  if (!finite(command.max())) return {{}, "set_interest_area.max is not a finite point"};
  const double width = command.max().x() - command.min().x();
  const double height = command.max().y() - command.min().y();
  if (width <= 0 || height <= 0) {
    return {{}, formatted("set_interest_area is empty or inverted: max must exceed min in x and y "
                          "(width %g m, height %g m)", width, height)};
  }
  if (width > kMaxInterestAreaSide || height > kMaxInterestAreaSide) {
    return {{}, formatted("set_interest_area is %g m wide and %g m high: each side may be at most %g m", width,
                          height, kMaxInterestAreaSide)};
  }
  return {AABB{Vec2(Real(command.min().x()), Real(command.min().y())),
               Vec2(Real(command.max().x()), Real(command.max().y()))},
          {}};
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
