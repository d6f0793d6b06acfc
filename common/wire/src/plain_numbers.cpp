#include "impulse/wire/plain_numbers.h"

#include <algorithm>

namespace impulse::wire {

namespace {

constexpr std::size_t kFixedDecimals = 6;

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Digits from `at` on.
std::size_t digitsAt(std::string_view text, std::size_t at) {
  std::size_t end = at;
  while (end < text.size() && isDigit(text[end])) ++end;
  return end - at;
}

// The number `integer` '.' `decimals` without trailing zeros (nor a bare point).
std::string trimmed(std::string_view integer, std::string_view decimals) {
  while (!decimals.empty() && decimals.back() == '0') decimals.remove_suffix(1);
  std::string number(integer);
  if (!decimals.empty()) number.append(1, '.').append(decimals);
  return number == "-0" ? "0" : number;
}

}  // namespace

std::string plainNumbers(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    // A number starts at a digit (or a '-' before one) that does not
    // continue a word or another number ("v2", "1.5").
    const bool starts = i == 0 || (!isDigit(text[i - 1]) && text[i - 1] != '.');
    const std::size_t sign = starts && text[i] == '-' ? 1 : 0;
    const std::size_t integer = starts ? digitsAt(text, i + sign) : 0;
    const std::size_t point = i + sign + integer;
    const bool fixed = integer > 0 && point < text.size() && text[point] == '.' &&
                       digitsAt(text, point + 1) == kFixedDecimals;
    if (!fixed) {
      // Copy through the whole run of digits, so no number is cut in two.
      const std::size_t run = std::max<std::size_t>(1, sign + integer);
      out.append(text, i, run);
      i += run;
      continue;
    }
    out += trimmed(text.substr(i, sign + integer), text.substr(point + 1, kFixedDecimals));
    i = point + 1 + kFixedDecimals;
  }
  return out;
}

}  // namespace impulse::wire
