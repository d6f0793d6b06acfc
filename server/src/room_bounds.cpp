#include "impulse/server/room_bounds.h"

#include <cmath>
#include "impulse/server/message_format.h"

namespace impulse::server {

namespace {

std::string cornerRefusal(const v1::Vec2& corner, const char* field) {
  if (!std::isfinite(corner.x()) || !std::isfinite(corner.y())) {
    return std::string("hello.") + field + " is not a finite point";
  }
  if (std::abs(corner.x()) > kMaxRoomCoordinate || std::abs(corner.y()) > kMaxRoomCoordinate) {
    return std::string("hello.") + field +
           formatted(" (%g, %g) lies outside the largest room: each coordinate must be within +-%g m",
                     corner.x(), corner.y(), kMaxRoomCoordinate);
  }
  return {};
}

}  // namespace

RoomBoundsRequest roomBoundsFromHello(const v1::Hello& hello) {
  if (!hello.has_room_min() && !hello.has_room_max()) return {};
  if (!hello.has_room_min()) return {{}, "hello.room_min is missing (give both corners, or neither)"};
  if (!hello.has_room_max()) return {{}, "hello.room_max is missing (give both corners, or neither)"};
  for (const auto& [corner, field] : {std::pair{&hello.room_min(), "room_min"}, std::pair{&hello.room_max(), "room_max"}}) {
    if (std::string refusal = cornerRefusal(*corner, field); !refusal.empty()) return {{}, std::move(refusal)};
  }
  const double width = hello.room_max().x() - hello.room_min().x();
  const double height = hello.room_max().y() - hello.room_min().y();
  if (width < kMinRoomSide || height < kMinRoomSide) {
    return {{}, formatted("hello.room_max must exceed room_min by at least %g m in x and y (the room would be "
                          "%g m wide, %g m high)", kMinRoomSide, width, height)};
  }
  return {AABB{Vec2(Real(hello.room_min().x()), Real(hello.room_min().y())),
               Vec2(Real(hello.room_max().x()), Real(hello.room_max().y()))},
          {}};
}

std::string describeBounds(const AABB& bounds) {
  return formatted("(%g, %g)", bounds.lower.x(), bounds.lower.y()) + " to " +
         formatted("(%g, %g) m", bounds.upper.x(), bounds.upper.y());
}

}  // namespace impulse::server
