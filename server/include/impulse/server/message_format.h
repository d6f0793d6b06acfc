#pragma once
/// Numbers in refusal messages, printed as %g prints them.

#include <cstdio>
#include <string>

namespace impulse::server {

/// printf's `format` with `numbers` (the messages are short: 200 bytes at most).
template <class... Numbers>
std::string formatted(const char* format, Numbers... numbers) {
  char text[200];
  std::snprintf(text, sizeof text, format, numbers...);
  return text;
}

}  // namespace impulse::server
