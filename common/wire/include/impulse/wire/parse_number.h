#pragma once
/// Whole-text number parsing for every place that reads numbers people type
/// (server flags, HOST:PORT, script words): one rule, no locale, no
/// exceptions, no partial reads.

#include <charconv>
#include <optional>
#include <string_view>

namespace impulse::wire {

/// `text` as a T when all of it is one number of that type (no sign for
/// unsigned types, no leading '+' or blanks); nothing otherwise, also when
/// it overflows T.
template <class T>
std::optional<T> parseNumber(std::string_view text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

}  // namespace impulse::wire
