#pragma once
/// Room names (docs/protocol.md, Rooms): what Hello.room may hold.

#include <cstddef>
#include <string>
#include <string_view>

namespace impulse::server {

/// The room Hello.room "" names.
inline constexpr std::string_view kDefaultRoom = "default";
inline constexpr std::size_t kMaxRoomNameLength = 64;

/// The room a Hello names: "" is the default room.
std::string roomNameOf(std::string_view requested);

/// Why `name` may not name a room ("" when it may): 1-64 characters of
/// A-Z a-z 0-9 _ - . (printable in logs, usable in file names and URLs).
std::string roomNameRefusal(std::string_view name);

}  // namespace impulse::server
