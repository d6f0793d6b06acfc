#include "impulse/server/room_bounds.h"

#include <cmath>

#include "impulse/server/message_format.h"
#include "impulse/server/wire_box.h"
#include "impulse/world.h"

namespace impulse::server {

RoomBounds RoomBounds::defaults() {
  const AABB bounds = WorldSettings{}.bounds;
  return {bounds.lower.cast<double>(), bounds.upper.cast<double>()};
}

Vec2d RoomBounds::origin() const {
  const Vec2d centre = (lower + upper) / 2;
  return {std::round(centre.x() / kOriginGrid) * kOriginGrid, std::round(centre.y() / kOriginGrid) * kOriginGrid};
}

AABB RoomBounds::relativeToOrigin() const {
  // Taken away in double: the float then holds what is near the origin.
  const Vec2d at = origin();
  return {(lower - at).cast<Real>(), (upper - at).cast<Real>()};
}

RoomBoundsRequest roomBoundsFromHello(const v1::Hello& hello) {
  static constexpr WireBoxRules kRules{.message = "hello",
                                       .minField = "room_min",
                                       .maxField = "room_max",
                                       .what = "room",
                                       .bothOrNeither = "give both corners, or neither",
                                       .maxCoordinate = kMaxRoomCoordinate,
                                       .minSide = kMinRoomSide,
                                       .maxSide = kMaxRoomSide};
  WireBox checked = boxFromWire(hello.has_room_min() ? &hello.room_min() : nullptr,
                                hello.has_room_max() ? &hello.room_max() : nullptr, kRules);
  if (!checked.box) return {std::nullopt, std::move(checked.error)};
  // The corners as given, in double (the checked box holds floats).
  return {RoomBounds{{hello.room_min().x(), hello.room_min().y()}, {hello.room_max().x(), hello.room_max().y()}},
          {}};
}

std::string describeBounds(const RoomBounds& bounds) {
  return formatted("(%.10g, %.10g)", bounds.lower.x(), bounds.lower.y()) + " to " +
         formatted("(%.10g, %.10g) m", bounds.upper.x(), bounds.upper.y());
}

}  // namespace impulse::server
