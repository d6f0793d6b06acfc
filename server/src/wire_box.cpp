#include "impulse/server/wire_box.h"

#include <cmath>
#include <string>

#include "impulse/server/message_format.h"

namespace impulse::server {

namespace {

std::string fieldName(const WireBoxRules& rules, std::string_view field) {
  return std::string(rules.message) + "." + std::string(field);
}

std::string cornerRefusal(const v1::Vec2& corner, std::string_view field,
                          const WireBoxRules& rules) {
  if (!std::isfinite(corner.x()) || !std::isfinite(corner.y())) {
    return fieldName(rules, field) + " is not a finite point";
  }
  if (std::abs(corner.x()) > rules.maxCoordinate || std::abs(corner.y()) > rules.maxCoordinate) {
    return fieldName(rules, field) +
           formatted(" (%.10g, %.10g) lies outside the largest ", corner.x(), corner.y()) +
           std::string(rules.what) +
           formatted(": each coordinate must be within +-%.0f m", rules.maxCoordinate);
  }
  return {};
}

std::string sideRefusal(double width, double height, const WireBoxRules& rules) {
  const std::string size =
      std::string(rules.message) + formatted(" is %g m wide and %g m high: ", width, height);
  if (width <= 0 || height <= 0 || width < rules.minSide || height < rules.minSide) {
    return size + fieldName(rules, rules.maxField) + " must exceed " +
           fieldName(rules, rules.minField) +
           (rules.minSide > 0 ? formatted(" by at least %g m in x and y", rules.minSide)
                              : " in x and y");
  }
  if (width > rules.maxSide || height > rules.maxSide) {
    return size + formatted("each side may be at most %g m", rules.maxSide);
  }
  return {};
}

}  // namespace

WireBox boxFromWire(const v1::Vec2* min, const v1::Vec2* max, const WireBoxRules& rules) {
  if (min == nullptr && max == nullptr) return {};
  for (const auto& [corner, field] :
       {std::pair{min, rules.minField}, std::pair{max, rules.maxField}}) {
    if (corner == nullptr) {
      return {{},
              fieldName(rules, field) + " is missing (" + std::string(rules.bothOrNeither) + ")"};
    }
  }
  for (const auto& [corner, field] :
       {std::pair{min, rules.minField}, std::pair{max, rules.maxField}}) {
    if (std::string refusal = cornerRefusal(*corner, field, rules); !refusal.empty())
      return {{}, std::move(refusal)};
  }
  if (std::string refusal = sideRefusal(max->x() - min->x(), max->y() - min->y(), rules);
      !refusal.empty()) {
    return {{}, std::move(refusal)};
  }
  return {AABB{Vec2(Real(min->x()), Real(min->y())), Vec2(Real(max->x()), Real(max->y()))}, {}};
}

}  // namespace impulse::server
