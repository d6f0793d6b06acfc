#include "chain_drawing.h"

#include <algorithm>

namespace impulse::viewer {

namespace {

// Twice the signed area of the polygon through `points`: positive when they
// run anticlockwise.
Real doubleArea(std::span<const Vec2> points) {
  Real area = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    area += cross(points[i], points[(i + 1) % points.size()]);
  }
  return area;
}

// A point `kChainGuideLength` beyond `end`, straight on from `before`.
Vec2 guideBeyond(const Vec2& before, const Vec2& end) {
  const Vec2 along = end - before;
  const Real length = along.norm();
  return length > 0 ? Vec2(end + along * (kChainGuideLength / length)) : end;
}

}  // namespace

std::vector<Vec2> openChainPoints(std::span<const Vec2> clicked) {
  std::vector<Vec2> points(clicked.begin(), clicked.end());
  if (points.size() < 2) return points;
  if (points.back().x() > points.front().x()) std::reverse(points.begin(), points.end());
  points.insert(points.begin(), guideBeyond(points[1], points[0]));
  points.push_back(guideBeyond(points[points.size() - 2], points.back()));
  return points;
}

std::vector<Vec2> closedChainPoints(std::span<const Vec2> clicked) {
  std::vector<Vec2> points(clicked.begin(), clicked.end());
  if (doubleArea(points) < 0) std::reverse(points.begin(), points.end());
  return points;
}

ShapeError checkChainInProgress(std::span<const Vec2> clicked) {
  if (clicked.size() < 2) {
    const bool finite =
        std::all_of(clicked.begin(), clicked.end(), [](const Vec2& p) { return isFinite(p); });
    return finite ? ShapeError::None : ShapeError::NonFinite;
  }
  return buildChain(openChainPoints(clicked), false).error;
}

}  // namespace impulse::viewer
