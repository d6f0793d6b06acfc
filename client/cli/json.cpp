#include "json.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace impulse::cli {

Json::Json(char open, char close) : text_(1, open), close_(close) {}

Json Json::object() { return Json('{', '}'); }
Json Json::array() { return Json('[', ']'); }

void Json::separate() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (!first_) text_ += ',';
  first_ = false;
}

Json& Json::key(std::string_view name) {
  value(name);
  text_ += ':';
  afterKey_ = true;
  return *this;
}

Json& Json::value(std::string_view text) {
  separate();
  text_ += '"';
  for (const char c : text) {
    switch (c) {
      case '"':
        text_ += "\\\"";
        break;
      case '\\':
        text_ += "\\\\";
        break;
      case '\n':
        text_ += "\\n";
        break;
      case '\r':
        text_ += "\\r";
        break;
      case '\t':
        text_ += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
          text_ += escaped;
        } else {
          text_ += c;
        }
    }
  }
  text_ += '"';
  return *this;
}

Json& Json::value(double number) {
  separate();
  if (!std::isfinite(number)) {
    text_ += "null";
    return *this;
  }
  // Shortest text that reads back as the same double: states compare exactly.
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, number);
  text_.append(buffer, ec == std::errc() ? end : buffer);
  return *this;
}

Json& Json::value(std::uint64_t number) {
  separate();
  text_ += std::to_string(number);
  return *this;
}

Json& Json::value(std::int64_t number) {
  separate();
  text_ += std::to_string(number);
  return *this;
}

Json& Json::value(bool flag) {
  separate();
  text_ += flag ? "true" : "false";
  return *this;
}

Json& Json::raw(const Json& nested) {
  separate();
  text_ += nested.str();
  return *this;
}

Json& Json::pair(double x, double y) {
  Json p = array();
  p.value(x).value(y).close();
  return raw(p);
}

Json& Json::close() {
  text_ += close_;
  return *this;
}

}  // namespace impulse::cli
