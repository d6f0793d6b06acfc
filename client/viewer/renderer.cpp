#include "renderer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace impulse::viewer {

namespace {

SDL_Color sdl(Colour c) { return {c.r, c.g, c.b, c.a}; }

SDL_FPoint point(PixelPoint p) { return {p.x, p.y}; }

// Segments for a circle of `pixels` radius: smooth at any size, cheap when small.
int circleSegments(float pixels) {
  return std::clamp(int(pixels * 0.6f), 10, 64);
}

}  // namespace

void WorldRenderer::setColour(Colour c) { SDL_SetRenderDrawColor(renderer_, c.r, c.g, c.b, c.a); }

void WorldRenderer::drawBackground(const ViewTransform& view) {
  setColour(palette::kBackground);
  SDL_RenderClear(renderer_);
  setColour(palette::kSceneBackground);
  const SDL_FRect scene{view.left(), view.top(), view.width(), view.height()};
  SDL_RenderFillRectF(renderer_, &scene);
}

void WorldRenderer::fillFan(std::span<const SDL_FPoint> points, Colour colour) {
  if (points.size() < 3) return;
  const int base = int(vertices_.size());
  for (const SDL_FPoint& p : points) vertices_.push_back({p, sdl(colour), {0, 0}});
  for (int i = 1; i + 1 < int(points.size()); ++i) {
    indices_.insert(indices_.end(), {base, base + i, base + i + 1});
  }
}

void WorldRenderer::fillDisc(SDL_FPoint centre, float radius, Colour colour) {
  const int n = circleSegments(radius);
  outline_.clear();
  for (int i = 0; i < n; ++i) {
    const float a = float(i) * 2 * std::numbers::pi_v<float> / float(n);
    outline_.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
  }
  fillFan(outline_, colour);
}

void WorldRenderer::flushFills() {
  if (!indices_.empty()) {
    SDL_RenderGeometry(renderer_, nullptr, vertices_.data(), int(vertices_.size()),
                       indices_.data(), int(indices_.size()));
  }
  vertices_.clear();
  indices_.clear();
}

void WorldRenderer::circleOutline(const ViewTransform& view, const Vec2& centre, Real radius,
                                  Real startAngle, std::vector<SDL_FPoint>& out) const {
  const int n = circleSegments(radius * view.scale());
  out.clear();
  for (int i = 0; i <= n; ++i) {
    const Real a = startAngle + Real(i) * 2 * std::numbers::pi_v<Real> / Real(n);
    out.push_back(point(view.toPixels(centre + radius * Vec2(std::cos(a), std::sin(a)))));
  }
}

void WorldRenderer::drawBodies(const ViewTransform& view, std::span<const DrawnBody> bodies,
                               std::optional<std::uint32_t> selected) {
  // Static scenery first, so moving bodies are drawn over it.
  outlines_.resize(std::max(outlines_.size(), bodies.size()));
  outlineColours_.clear();
  std::size_t count = 0;
  for (const bool statics : {true, false}) {
    for (const DrawnBody& body : bodies) {
      const BodyLook& look = *body.look;
      if (look.isStatic != statics) continue;
      const bool asleep = !look.isStatic && !body.state.awake;
      const Colour fill = bodyFill(look.material, look.isStatic, asleep);
      Colour edge = bodyOutline(look.material, look.isStatic, asleep);
      if (selected && *selected == body.state.id) edge = palette::kSelection;
      std::vector<SDL_FPoint>& line = outlines_[count++];
      const Transform xf{body.state.position, Rot::fromAngle(body.state.angle)};
      if (look.shape.type == ShapeType::Circle) {
        const Real r = look.shape.circle.radius;
        // The outline starts and ends at the body's angle, so one more point
        // at the centre draws the radius line that shows rotation.
        circleOutline(view, xf.p, r, body.state.angle, line);
        fillFan(std::span(line).first(line.size() - 1), fill);
        line.push_back(point(view.toPixels(xf.p)));
      } else {
        const Polygon& polygon = look.shape.polygon;
        line.clear();
        for (int i = 0; i < polygon.count; ++i) {
          line.push_back(point(view.toPixels(xf.apply(polygon.vertices[i]))));
        }
        fillFan(line, fill);
        line.push_back(line.front());
      }
      outlineColours_.push_back(edge);
    }
  }
  flushFills();
  for (std::size_t i = 0; i < count; ++i) {
    setColour(outlineColours_[i]);
    SDL_RenderDrawLinesF(renderer_, outlines_[i].data(), int(outlines_[i].size()));
  }
}

void WorldRenderer::drawMarkers(const ViewTransform& view, std::span<const Marker> markers) {
  // Markers under a few centimetres are points (the polygon tutorial's
  // corners); larger ones are rings (the circle tutorial's radius).
  constexpr Real kPointMarker = Real(0.15);
  setColour(palette::kMarker);
  for (const Marker& marker : markers) {
    const SDL_FPoint centre = point(view.toPixels(marker.center));
    if (marker.radius > kPointMarker) {
      circleOutline(view, marker.center, marker.radius, 0, outline_);
      SDL_RenderDrawLinesF(renderer_, outline_.data(), int(outline_.size()));
      fillDisc(centre, 2.5f, palette::kMarker);
    } else {
      fillDisc(centre, std::max(5.0f, marker.radius * view.scale()), palette::kMarker);
    }
  }
  flushFills();
}

void WorldRenderer::drawPreview(const ViewTransform& view, const Controls& controls) {
  if (controls.mode() == DrawMode::Polygon) {
    const auto& points = controls.polygonPoints();
    std::vector<SDL_FPoint>& line = previewLine_;
    line.clear();
    for (const Vec2& p : points) line.push_back(point(view.toPixels(p)));
    if (line.size() >= 3) {
      Colour translucent = palette::kPreview;
      translucent.a = 70;
      fillFan(line, translucent);
      flushFills();
    }
    setColour(palette::kPreview);
    SDL_RenderDrawLinesF(renderer_, line.data(), int(line.size()));
    for (const SDL_FPoint& p : line) fillDisc(p, 3, palette::kPreview);
    const SDL_FPoint cursor = point(view.toPixels(controls.pointer()));
    const bool valid = controls.pointerValid();
    if (!line.empty() && valid) {
      // Guides from the last point to the cursor and on to the first.
      setColour(palette::kDimText);
      SDL_RenderDrawLineF(renderer_, line.back().x, line.back().y, cursor.x, cursor.y);
      SDL_RenderDrawLineF(renderer_, cursor.x, cursor.y, line.front().x, line.front().y);
    }
    fillDisc(cursor, 5, valid ? palette::kValid : palette::kInvalid);
    flushFills();
  } else if (controls.mode() == DrawMode::Circle && controls.circleCenter()) {
    const Vec2 centre = *controls.circleCenter();
    const Real r = controls.circleRadius();
    setColour(palette::kPreview);
    if (r > 0) {
      circleOutline(view, centre, r, 0, outline_);
      SDL_RenderDrawLinesF(renderer_, outline_.data(), int(outline_.size()));
      const Vec2 toPointer = controls.pointer() - centre;
      const Vec2 direction = toPointer.norm() > 0 ? Vec2(toPointer.normalized()) : Vec2(1, 0);
      const SDL_FPoint c = point(view.toPixels(centre));
      const SDL_FPoint rim = point(view.toPixels(centre + r * direction));
      SDL_RenderDrawLineF(renderer_, c.x, c.y, rim.x, rim.y);
    }
    fillDisc(point(view.toPixels(centre)), 3, palette::kPreview);
    flushFills();
  }
}

}  // namespace impulse::viewer
