#include "impulse/server/room_bounds.h"

#include "impulse/server/message_format.h"
#include "impulse/server/wire_box.h"

namespace impulse::server {

RoomBoundsRequest roomBoundsFromHello(const v1::Hello& hello) {
  static constexpr WireBoxRules kRules{.message = "hello",
                                       .minField = "room_min",
                                       .maxField = "room_max",
                                       .what = "room",
                                       .bothOrNeither = "give both corners, or neither",
                                       .maxCoordinate = kMaxRoomCoordinate,
                                       .minSide = kMinRoomSide};
  WireBox bounds = boxFromWire(hello.has_room_min() ? &hello.room_min() : nullptr,
                               hello.has_room_max() ? &hello.room_max() : nullptr, kRules);
  return {bounds.box, std::move(bounds.error)};
}

std::string describeBounds(const AABB& bounds) {
  return formatted("(%g, %g)", bounds.lower.x(), bounds.lower.y()) + " to " +
         formatted("(%g, %g) m", bounds.upper.x(), bounds.upper.y());
}

}  // namespace impulse::server
