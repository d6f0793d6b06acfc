#pragma once
// Reading numbers off the wire for a message with many of them (joints,
// fields): the first bad one is kept, named by its field's path.

#include <string>
#include <string_view>

#include "impulse/wire/convert.h"

namespace impulse::wire {

// Reads numbers off the wire, keeping the first that is not finite or does
// not fit a float; its error names the field under `prefix`.
class Reader {
 public:
  explicit Reader(std::string prefix) : prefix_(std::move(prefix)) {}

  Real real(double value, std::string_view field) {
    auto decoded = realFromWire(value, prefix_ + std::string(field));
    if (!decoded.ok()) keep(std::move(decoded.error));
    return decoded.value.value_or(0);
  }
  Vec2 vec(const v1::Vec2& value, std::string_view field) {
    auto decoded = vecFromWire(value, prefix_ + std::string(field));
    if (!decoded.ok()) keep(std::move(decoded.error));
    return decoded.value.value_or(Vec2::Zero());
  }
  /// Reads the kind's fields under "<prefix><kind>.".
  Reader kind(std::string_view name) const { return Reader(prefix_ + std::string(name) + "."); }
  void keep(std::string error) {
    if (error_.empty()) error_ = std::move(error);
  }
  const std::string& error() const { return error_; }
  std::string_view prefix() const { return prefix_; }

 private:
  std::string prefix_;
  std::string error_;
};

}  // namespace impulse::wire
