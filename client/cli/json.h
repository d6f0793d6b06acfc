#pragma once
// A minimal JSON writer for impulse-cli's one-line replies.

#include <cstdint>
#include <string>
#include <string_view>

namespace impulse::cli {

/// Appends members to one JSON object or array; call close() once.
class Json {
 public:
  static Json object();
  static Json array();

  Json& key(std::string_view name);
  Json& value(std::string_view text);
  Json& value(const char* text) { return value(std::string_view(text)); }
  Json& value(const std::string& text) { return value(std::string_view(text)); }
  Json& value(double number);
  Json& value(std::uint64_t number);
  Json& value(std::int64_t number);
  Json& value(std::uint32_t number) { return value(std::uint64_t(number)); }
  Json& value(int number) { return value(std::int64_t(number)); }
  Json& value(bool flag);
  /// A nested object or array, already closed.
  Json& raw(const Json& nested);
  /// [x, y]
  Json& pair(double x, double y);
  template <class T>
  Json& member(std::string_view name, const T& v) {
    key(name);
    return value(v);
  }
  Json& close();
  const std::string& str() const { return text_; }

 private:
  explicit Json(char open, char close);
  void separate();

  std::string text_;
  char close_;
  bool first_ = true;
  bool afterKey_ = false;
};

}  // namespace impulse::cli
