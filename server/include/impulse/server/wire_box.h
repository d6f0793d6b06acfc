#pragma once
/// A box a client gives as two corners (SetInterestArea's min and max,
/// Hello's room_min and room_max), checked by one set of rules so both read
/// and refuse alike.

#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "impulse.pb.h"
#include "impulse/math.h"

namespace impulse::server {

/// What a box must satisfy, and the names its refusals use.
struct WireBoxRules {
  /// The message and its corner fields: "hello", "room_min", "room_max".
  std::string_view message;
  std::string_view minField;
  std::string_view maxField;
  /// What the box is, for "lies outside the largest room".
  std::string_view what;
  /// Said when one corner is missing: what leaving out both means.
  std::string_view bothOrNeither;
  /// No coordinate may lie farther from the origin (metres).
  double maxCoordinate = std::numeric_limits<double>::infinity();
  /// Each side must be at least this long, and longer than zero.
  double minSide = 0;
  /// Each side may be at most this long.
  double maxSide = std::numeric_limits<double>::infinity();
};

/// The box, none when both corners are unset, or the error naming the field
/// that is missing, not finite or out of range, or the sides that break the
/// rules. A corner is null when its field is unset.
struct WireBox {
  std::optional<AABB> box;
  std::string error;
};
WireBox boxFromWire(const v1::Vec2* min, const v1::Vec2* max, const WireBoxRules& rules);

}  // namespace impulse::server
