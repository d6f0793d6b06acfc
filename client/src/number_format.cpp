#include "impulse/client/number_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace impulse::client {

std::string formatNumber(double value, int maxDecimals) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[64];
  std::size_t length = std::size_t(std::snprintf(text, sizeof text, "%.*f", maxDecimals, value));
  // Trailing zeros and a bare point go (trimmed in the buffer: GCC 12 warns
  // falsely, -Wrestrict, on the same done with std::string::erase).
  if (std::memchr(text, '.', length) != nullptr) {
    while (text[length - 1] == '0') --length;
    if (text[length - 1] == '.') --length;
  }
  if (length == 2 && text[0] == '-' && text[1] == '0') return "0";
  return std::string(text, length);
}

std::string formatExact(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

}  // namespace impulse::client
