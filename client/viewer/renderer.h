#pragma once
/// Draws the scene: bodies (filled and outlined, circles with a radius line
/// that shows rotation), preset markers, the selection and drawing previews.
/// All fills of a frame go to the GPU (or software rasteriser) in one
/// SDL_RenderGeometry batch.

#include <SDL.h>

#include <optional>
#include <span>
#include <vector>

#include "controls.h"
#include "impulse/preset.h"
#include "interpolated_world.h"
#include "palette.h"
#include "view_transform.h"

namespace impulse::viewer {

class WorldRenderer {
 public:
  explicit WorldRenderer(SDL_Renderer* renderer) : renderer_(renderer) {}

  /// Background of the window and of the scene rectangle.
  void drawBackground(const ViewTransform& view);
  void drawBodies(const ViewTransform& view, std::span<const DrawnBody> bodies,
                  std::optional<std::uint32_t> selected);
  void drawMarkers(const ViewTransform& view, std::span<const Marker> markers);
  /// The polygon or circle being drawn, and the polygon cursor dot.
  void drawPreview(const ViewTransform& view, const Controls& controls);

 private:
  void setColour(Colour c);
  /// Appends a filled convex fan (first point is a vertex) to the batch.
  void fillFan(std::span<const SDL_FPoint> points, Colour colour);
  void flushFills();
  void circleOutline(const ViewTransform& view, const Vec2& centre, Real radius, Real startAngle,
                     std::vector<SDL_FPoint>& out) const;
  void fillDisc(SDL_FPoint centre, float radius, Colour colour);

  SDL_Renderer* renderer_;
  std::vector<SDL_Vertex> vertices_;
  std::vector<int> indices_;
  std::vector<SDL_FPoint> outline_;
  std::vector<SDL_FPoint> previewLine_;  // the polygon being drawn, in pixels
  std::vector<std::vector<SDL_FPoint>> outlines_;
  std::vector<Colour> outlineColours_;
};

}  // namespace impulse::viewer
