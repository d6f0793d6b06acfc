#include "impulse/server/room_name.h"

#include <algorithm>

namespace impulse::server {

namespace {

bool allowedInName(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

}  // namespace

std::string roomNameOf(std::string_view requested) {
  return std::string(requested.empty() ? kDefaultRoom : requested);
}

std::string roomNameRefusal(std::string_view name) {
  const std::string rule = "room names are 1-" + std::to_string(kMaxRoomNameLength) +
                           " characters of A-Z a-z 0-9 _ - .";
  if (name.size() > kMaxRoomNameLength) {
    return "Hello.room is " + std::to_string(name.size()) + " characters long: " + rule;
  }
  if (!std::all_of(name.begin(), name.end(), allowedInName)) {
    // The name itself is not echoed: it may hold control characters.
    return "Hello.room holds a character outside the allowed set: " + rule;
  }
  return {};
}

}  // namespace impulse::server
