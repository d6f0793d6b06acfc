// Fields drawn under the bodies (WorldRenderer::drawFields): a liquid as its
// tinted polygon with the surface edge brighter, a fan as its cone out to
// its range, gravitation as a small marker in the frame's corner (it acts
// everywhere, so there is nothing to outline).

#include <cmath>
#include <variant>

#include "renderer.h"

namespace impulse::viewer {

namespace {

ImVec2 pixelOf(const ViewTransform& view, const Vec2& world) {
  const PixelPoint p = view.toPixels(world);
  return {p.x, p.y};
}

constexpr int kConeSegments = 16;

}  // namespace

void WorldRenderer::drawFluid(ImDrawList& list, const ViewTransform& view, const FluidDef& fluid) {
  points_.clear();
  for (const Vec2& p : fluid.polygon) points_.push_back(pixelOf(view, p));
  list.AddConvexPolyFilled(points_.data(), int(points_.size()), packed(palette::kLiquid));
  list.AddPolyline(points_.data(), int(points_.size()), packed(palette::kLiquidEdge), ImDrawFlags_Closed, 1.5f);
}

void WorldRenderer::drawFan(ImDrawList& list, const ViewTransform& view, const FanDef& fan) {
  const Real heading = std::atan2(fan.direction.y(), fan.direction.x());
  points_.clear();
  points_.push_back(pixelOf(view, fan.position));
  for (int k = 0; k <= kConeSegments; ++k) {
    const Real angle = heading - fan.spread + 2 * fan.spread * Real(k) / kConeSegments;
    points_.push_back(pixelOf(view, fan.position + fan.range * Vec2(std::cos(angle), std::sin(angle))));
  }
  list.AddConvexPolyFilled(points_.data(), int(points_.size()), packed(palette::kAir));
  list.AddPolyline(points_.data(), int(points_.size()), packed(palette::kAirEdge), ImDrawFlags_Closed, 1.0f);
  list.AddCircleFilled(points_.front(), 5, packed(palette::kAirEdge));
}

void WorldRenderer::drawGravitationMarker(ImDrawList& list, const ViewTransform& view) {
  // An orbit glyph inside the frame's top-left corner: a dot and its ring.
  const AABB& frame = view.frame();
  const ImVec2 at = pixelOf(view, Vec2(frame.lower.x() + Real(0.6), frame.upper.y() - Real(0.6)));
  list.AddCircleFilled(at, 4, packed(palette::kGravitation));
  list.AddCircle(at, 10, packed(palette::kGravitation), 0, 1.5f);
}

void WorldRenderer::drawFields(ImDrawList& list, const ViewTransform& view,
                               const std::map<std::uint32_t, FieldDef>& fields) {
  for (const auto& [id, field] : fields) {
    if (const auto* fluid = std::get_if<FluidDef>(&field)) drawFluid(list, view, *fluid);
    if (const auto* fan = std::get_if<FanDef>(&field)) drawFan(list, view, *fan);
    if (std::holds_alternative<GravitationDef>(field)) drawGravitationMarker(list, view);
  }
}

}  // namespace impulse::viewer
