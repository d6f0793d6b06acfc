#pragma once
/// The world bounds a room is made with (Hello.room_min, room_max;
/// docs/networked-play.md): checked against the stated limits.

#include <optional>
#include <string>

#include "impulse.pb.h"
#include "impulse/math.h"

namespace impulse::server {

/// No bound of a room lies farther from the origin than this (metres): at
/// 10 km the engine's float positions still resolve a millimetre.
inline constexpr double kMaxRoomCoordinate = 10000;
/// Narrowest and lowest room, metres.
inline constexpr double kMinRoomSide = 1;

/// Hello's room bounds: the box, none when both corners are unset, or the
/// error naming the field that is missing, not finite, out of range, or
/// leaves the room thinner than kMinRoomSide.
struct RoomBoundsRequest {
  std::optional<AABB> bounds;
  std::string error;
};
RoomBoundsRequest roomBoundsFromHello(const v1::Hello& hello);

/// "(-25, -25) to (50, 45) m", for messages.
std::string describeBounds(const AABB& bounds);

}  // namespace impulse::server
