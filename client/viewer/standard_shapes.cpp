#include "standard_shapes.h"

#include <array>
#include <cmath>
#include <numbers>

namespace impulse::viewer {

std::vector<Vec2> regularPolygon(int sides, const Vec2& centre, Real circumradius) {
  // Starting half a side past straight down puts the first side, from
  // vertex 0 to vertex n-1, level at the bottom.
  const double step = 2 * std::numbers::pi / sides;
  const double start = -std::numbers::pi / 2 + step / 2;
  std::vector<Vec2> vertices;
  vertices.reserve(std::size_t(sides));
  for (int k = 0; k < sides; ++k) {
    const double angle = start + step * k;
    vertices.push_back(centre + circumradius * Vec2(Real(std::cos(angle)), Real(std::sin(angle))));
  }
  return vertices;
}

std::string_view standardShapeName(int sides) {
  constexpr std::array<std::string_view, 4> kNames = {"triangle", "square", "pentagon", "hexagon"};
  if (sides < kFewestStandardSides || sides > kMostStandardSides) return "polygon";
  return kNames[std::size_t(sides - kFewestStandardSides)];
}

}  // namespace impulse::viewer
