#pragma once
/// The world bounds a room is made with (Hello.room_min, room_max;
/// docs/networked-play.md): checked against the stated limits, and the
/// origin the room's world computes around.

#include <optional>
#include <string>

#include "impulse.pb.h"
#include "impulse/math.h"

namespace impulse::server {

/// No bound of a room lies farther from (0, 0) than this (metres): the wire
/// carries positions from (0, 0) in double, which resolves 0.1 nm here.
inline constexpr double kMaxRoomCoordinate = 1'000'000;
/// Narrowest and lowest room, metres.
inline constexpr double kMinRoomSide = 1;
/// Widest and tallest room, metres: with the origin at most half the
/// origin grid from the bounds' centre, no point of the room lies more than
/// 15 km from the origin on either axis, where the engine's float positions
/// resolve a millimetre (2^-10 m up to 16 384 m).
inline constexpr double kMaxRoomSide = 20'000;
/// A room's origin is its bounds' centre rounded to a multiple of this
/// (metres): every room whose centre lies within 5 km of (0, 0) on each
/// axis keeps (0, 0), so its world computes as a world at (0, 0) does.
inline constexpr double kOriginGrid = 10'000;

/// A room's bounds as Hello gave them: metres from (0, 0), in double.
struct RoomBounds {
  Vec2d lower = Vec2d::Zero();
  Vec2d upper = Vec2d::Zero();

  /// The server's default bounds (WorldSettings).
  static RoomBounds defaults();
  /// The point the room's world computes positions around: the centre
  /// rounded to kOriginGrid.
  Vec2d origin() const;
  /// The bounds relative to origin(), as the world keeps them.
  AABB relativeToOrigin() const;
  bool operator==(const RoomBounds&) const = default;
};

/// Hello's room bounds: the box, none when both corners are unset, or the
/// error naming the field that is missing, not finite, out of range, or
/// leaves the room thinner than kMinRoomSide or wider than kMaxRoomSide.
struct RoomBoundsRequest {
  std::optional<RoomBounds> bounds;
  std::string error;
};
RoomBoundsRequest roomBoundsFromHello(const v1::Hello& hello);

/// "(-25, -25) to (50, 45) m", for messages.
std::string describeBounds(const RoomBounds& bounds);

}  // namespace impulse::server
