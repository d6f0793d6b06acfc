#include "field_parsers.h"

#include <string>

namespace impulse::cli {

namespace {

void setVec(v1::Vec2* out, double x, double y) {
  out->set_x(x);
  out->set_y(y);
}

}  // namespace

std::optional<std::tuple<double>> parseGravitation(Arguments& line) {
  const auto constant = line.numberAt(1);
  if (!constant || !line.maxWords(2)) return std::nullopt;
  return std::tuple{*constant};
}

std::optional<std::tuple<v1::FluidRegion>> parseFluid(Arguments& line) {
  v1::FluidRegion fluid;
  const auto density = line.numberAt(1), drag = line.numberAt(2), angularDrag = line.numberAt(3);
  const auto cx = line.numberAt(4), cy = line.numberAt(5);
  if (!density || !drag || !angularDrag || !cx || !cy) return std::nullopt;
  fluid.set_density(*density);
  fluid.set_linear_drag(*drag);
  fluid.set_angular_drag(*angularDrag);
  setVec(fluid.mutable_current(), *cx, *cy);
  for (std::size_t i = 6; i < line.size(); i += 2) {
    const auto x = line.numberAt(i), y = line.numberAt(i + 1);
    if (!x) return std::nullopt;
    if (!y) {
      line.refuse("polygon point " + std::to_string(fluid.polygon_size() + 1) + " has no y");
      return std::nullopt;
    }
    setVec(fluid.add_polygon(), *x, *y);
  }
  // Too few points or a concave polygon are for the server to judge.
  return std::tuple{std::move(fluid)};
}

std::optional<std::tuple<v1::Fan>> parseFan(Arguments& line) {
  double numbers[7];
  for (std::size_t i = 0; i < 7; ++i) {
    const auto value = line.numberAt(i + 1);
    if (!value) return std::nullopt;
    numbers[i] = *value;
  }
  if (!line.maxWords(8)) return std::nullopt;
  v1::Fan fan;
  setVec(fan.mutable_position(), numbers[0], numbers[1]);
  setVec(fan.mutable_direction(), numbers[2], numbers[3]);
  fan.set_speed(numbers[4]);
  fan.set_range(numbers[5]);
  fan.set_spread(numbers[6]);
  return std::tuple{std::move(fan)};
}

}  // namespace impulse::cli
