#pragma once
/// Draws the scene into an ImGui draw list (anti-aliased fills and lines):
/// bodies filled in their material colour with a contrasting outline and a
/// rotation mark, sleeping bodies outlined in the sleep colour, preset
/// markers, the selection and the drawing previews. Everything is clipped
/// to the scene viewport.

#include <imgui.h>

#include <map>
#include <optional>
#include <span>
#include <vector>

#include "controls.h"
#include "event_flashes.h"
#include "impulse/field_kinds.h"
#include "impulse/scenes/presets.h"
#include "interpolated_world.h"
#include "joint_figure.h"
#include "palette.h"
#include "view_transform.h"

namespace impulse::viewer {

/// ImGui's packed colour of a palette colour.
ImU32 packed(Colour colour);

/// Stripes across a convex outline on screen, the kinematic look: from lower
/// left to upper right, every 9 pixels counted from `anchor` (a body's
/// centre, so they travel with the body).
void hatchConvex(ImDrawList& list, std::span<const ImVec2> outline, ImVec2 anchor, ImU32 colour);

class WorldRenderer {
 public:
  /// Fills the viewport and the scene rectangle, and clips what follows to
  /// the viewport until end().
  void begin(ImDrawList& list, const ViewTransform& view);
  void end(ImDrawList& list);
  void drawBodies(ImDrawList& list, const ViewTransform& view, std::span<const DrawnBody> bodies,
                  std::optional<std::uint32_t> selected, std::optional<std::uint32_t> grabbed);
  void drawMarkers(ImDrawList& list, const ViewTransform& view, std::span<const Marker> markers);
  /// Joints over the bodies: rods and ropes as lines (a rope thinner), springs
  /// as zig-zags, pins as small rings, sliders as a line with a ring.
  void drawJoints(ImDrawList& list, const ViewTransform& view,
                  std::span<const JointFigure> joints);
  /// Fields under the bodies: liquids tinted, fan cones, a gravitation marker.
  void drawFields(ImDrawList& list, const ViewTransform& view,
                  const std::map<std::uint32_t, FieldDef>& fields);
  /// The hand: a line from the held point of a grabbed body to the cursor.
  void drawGrab(ImDrawList& list, const ViewTransform& view, const Vec2& held, const Vec2& cursor);
  /// The shape being drawn (polygon, circle, capsule, segment or chain),
  /// and the cursor dot of the point-placing tools.
  void drawPreview(ImDrawList& list, const ViewTransform& view, const Controls& controls);
  /// The ray tool: the ray aimed (thin while its cast is on the way), the
  /// answered ray solid up to its hit, the hit point, the hit surface's
  /// normal as an arrow and the hit shape of `hitBody` outlined.
  void drawRay(ImDrawList& list, const ViewTransform& view, const RayTool& ray,
               const DrawnBody* hitBody);
  /// The event flashes at `now`: hit marks where they happened, glows on
  /// the bodies of `world` that they name.
  void drawFlashes(ImDrawList& list, const ViewTransform& view, const EventFlashes& flashes,
                   const InterpolatedWorld& world, double now);

 private:
  /// How one body's shapes are drawn.
  struct ShapeColours {
    ImU32 fill = 0;
    ImU32 edge = 0;
    float thickness = 1;
    bool small = false;  ///< too small on screen for an outline of its own
    ImU32 hatch = 0;     ///< stripes over the fill (kinematic bodies); none when 0
    bool dashed = false; ///< a thin dashed outline (sensors)
  };
  void drawBody(ImDrawList& list, const ViewTransform& view, const DrawnBody& body,
                const SurfaceLook& surface, float thickness);
  void drawShape(ImDrawList& list, const ViewTransform& view, const Transform& xf, const Shape& shape,
                 const ShapeColours& colours);
  void drawSensorShape(ImDrawList& list, const ViewTransform& view, const Transform& xf, const Shape& shape,
                       const ShapeColours& colours);
  /// The body's shapes again in `colours` (only the shape `shapeId` when
  /// given): the ray's hit, a flash.
  void drawOver(ImDrawList& list, const ViewTransform& view, const DrawnBody& body,
                std::optional<std::uint32_t> shapeId, const ShapeColours& colours);
  void drawFluid(ImDrawList& list, const ViewTransform& view, const FluidDef& fluid);
  void drawFan(ImDrawList& list, const ViewTransform& view, const FanDef& fan);
  void drawGravitationMarker(ImDrawList& list, const ViewTransform& view);
  void drawPointsPreview(ImDrawList& list, const ViewTransform& view, const Controls& controls);
  void drawCirclePreview(ImDrawList& list, const ViewTransform& view, const Controls& controls);
  void drawLinePreview(ImDrawList& list, const ViewTransform& view, const Controls& controls);

  std::vector<ImVec2> points_;
  std::vector<Vec2> outline_;
  std::vector<Vec2> springPoints_;
  std::vector<ImVec2> inset_;
  std::vector<PixelPoint> path_;
  std::vector<PixelPoint> dashes_;
};

}  // namespace impulse::viewer
