#include "overlays.h"

#include <cmath>

#include "renderer.h"

namespace impulse::viewer {

namespace {

ImVec2 pixel(const ViewTransform& view, const Vec2& world) {
  const PixelPoint p = view.toPixels(world);
  return {p.x, p.y};
}

// A velocity arrow is as long as the distance covered in this time.
constexpr Real kVelocitySeconds = Real(0.25);
// Overlay lines are this thick (pixels): a hairline would vanish in the AA.
constexpr float kLine = 1.5f;
// A contact normal is drawn this long, metres.
constexpr Real kNormalLength = Real(0.5);

void arrow(ImDrawList& list, ImVec2 from, ImVec2 to, ImU32 colour) {
  list.AddLine(from, to, colour, kLine);
  const float dx = to.x - from.x;
  const float dy = to.y - from.y;
  const float length = std::sqrt(dx * dx + dy * dy);
  if (length < 4) return;
  const float ux = dx / length;
  const float uy = dy / length;
  const float head = std::min(8.0f, length / 2);
  list.AddTriangleFilled(to, {to.x - head * (ux + 0.5f * uy), to.y - head * (uy - 0.5f * ux)},
                         {to.x - head * (ux - 0.5f * uy), to.y - head * (uy + 0.5f * ux)}, colour);
}

}  // namespace

void OverlayRenderer::draw(ImDrawList& list, const ViewTransform& view,
                           std::span<const DrawnBody> bodies, const Overlays& overlays) {
  if (overlays.bounds) drawBounds(list, view, bodies);
  if (overlays.velocities) drawVelocities(list, view, bodies);
  if (overlays.contacts) drawContacts(list, view, bodies);
}

void OverlayRenderer::drawBounds(ImDrawList& list, const ViewTransform& view,
                                 std::span<const DrawnBody> bodies) {
  const ImU32 colour = packed(palette::kBounds);
  for (const DrawnBody& body : bodies) {
    const AABB box = computeAABB(body.look->shape,
                                 {body.state.position, Rot::fromAngle(body.state.angle)});
    // Pixel y grows downwards: the box's upper-left corner is (lower.x, upper.y).
    list.AddRect(pixel(view, Vec2(box.lower.x(), box.upper.y())),
                 pixel(view, Vec2(box.upper.x(), box.lower.y())), colour, 0, 0, kLine);
  }
}

void OverlayRenderer::drawVelocities(ImDrawList& list, const ViewTransform& view,
                                     std::span<const DrawnBody> bodies) {
  const ImU32 colour = packed(palette::kVelocity);
  for (const DrawnBody& body : bodies) {
    if (body.look->isStatic || body.state.velocity.squaredNorm() < Real(1e-4)) continue;
    const Vec2 tip = body.state.position + kVelocitySeconds * body.state.velocity;
    arrow(list, pixel(view, body.state.position), pixel(view, tip), colour);
  }
}

void OverlayRenderer::drawContacts(ImDrawList& list, const ViewTransform& view,
                                   std::span<const DrawnBody> bodies) {
  findContacts(bodies, contacts_);
  const ImU32 point = packed(palette::kContact);
  const ImU32 normal = packed(palette::kNormal);
  for (const ShownContact& contact : contacts_) {
    const ImVec2 at = pixel(view, contact.point);
    arrow(list, at, pixel(view, contact.point + kNormalLength * contact.normal), normal);
    list.AddCircleFilled(at, 3.5f, point);
  }
}

}  // namespace impulse::viewer
