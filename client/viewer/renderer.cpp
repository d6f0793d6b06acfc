#include "renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "dashes.h"

namespace impulse::viewer {

namespace {

ImVec2 pixel(const ViewTransform& view, const Vec2& world) {
  const PixelPoint p = view.toPixels(world);
  return {p.x, p.y};
}

Vec2 unit(Real angle) { return Vec2(std::cos(angle), std::sin(angle)); }

// Outlines thinner than this vanish against the fill; thicker ones swallow
// small bodies.
constexpr float kOutline = 1.6f;
constexpr float kEmphasis = 2.6f;
// Bodies smaller than this (pixels across) are outlined by an underlay: the
// shape in the outline colour with the fill inset over it. SDL's software
// renderer pays for thin triangles (lines) far more than for fills, and a
// scene of thousands of bodies is mostly small ones.
constexpr float kSmallBody = 16;
// Sensors are edged by dashes this long with gaps this long, this thick (pixels).
constexpr float kSensorDash = 6;
constexpr float kSensorGap = 4;
constexpr float kSensorLine = 1.2f;
// The ray tool's normal arrow, pixels, at any zoom.
constexpr float kRayNormalPixels = 32;

// Segments for a circle of `pixels` radius: the chords stray less than half a
// pixel from the circle, so it looks round at any size, and small circles
// (most of a large scene) take few triangles.
int circleSegments(float pixels) {
  constexpr float kMaxError = 0.45f;
  if (pixels <= kMaxError) return 8;
  const float segments = std::numbers::pi_v<float> / std::acos(1 - kMaxError / pixels);
  return std::clamp(int(std::ceil(segments)), 8, 96);
}

// The corners of a circle of `pixels` radius on screen, `segments` of them.
void circlePoints(ImVec2 centre, float pixels, int segments, std::vector<ImVec2>& out) {
  out.clear();
  for (int i = 0; i < segments; ++i) {
    const float a = 2 * std::numbers::pi_v<float> * float(i) / float(segments);
    out.push_back({centre.x + pixels * std::cos(a), centre.y + pixels * std::sin(a)});
  }
}

// `colour` with its alpha scaled by `factor` (0-1).
ImU32 faded(Colour colour, float factor) {
  colour.a = std::uint8_t(float(colour.a) * std::clamp(factor, 0.0f, 1.0f));
  return packed(colour);
}

// `points` (a convex polygon on screen) moved inwards by `inset` pixels.
void insetConvex(const std::vector<ImVec2>& points, float inset, std::vector<ImVec2>& out) {
  ImVec2 centre{0, 0};
  for (const ImVec2& p : points) centre = {centre.x + p.x, centre.y + p.y};
  centre = {centre.x / float(points.size()), centre.y / float(points.size())};
  // Inward unit normal of the edge from a to b.
  auto inward = [&](ImVec2 a, ImVec2 b) {
    ImVec2 n{a.y - b.y, b.x - a.x};
    const float length = std::max(std::sqrt(n.x * n.x + n.y * n.y), 1e-6f);
    n = {n.x / length, n.y / length};
    const bool outward = (centre.x - a.x) * n.x + (centre.y - a.y) * n.y < 0;
    return outward ? ImVec2{-n.x, -n.y} : n;
  };
  out.clear();
  const std::size_t count = points.size();
  for (std::size_t i = 0; i < count; ++i) {
    const ImVec2 before = inward(points[(i + count - 1) % count], points[i]);
    const ImVec2 after = inward(points[i], points[(i + 1) % count]);
    // Along the corner's bisector, far enough that both edges move by `inset`.
    const float scale = inset / std::max(1 + before.x * after.x + before.y * after.y, 0.1f);
    out.push_back({points[i].x + scale * (before.x + after.x),
                   points[i].y + scale * (before.y + after.y)});
  }
}

// Draws with some of ImGui's anti-aliasing switched off.
void without(ImDrawList& list, ImDrawListFlags off, const std::function<void()>& draw) {
  const ImDrawListFlags flags = list.Flags;
  list.Flags &= ~off;
  draw();
  list.Flags = flags;
}

}  // namespace

void hatchConvex(ImDrawList& list, std::span<const ImVec2> outline, ImVec2 anchor, ImU32 colour) {
  constexpr float kStripeSpacing = 9;
  constexpr float kStripeWidth = 2.5f;
  // Distance along the stripes' normal, (1, 1) / sqrt(2) on screen.
  const auto across = [&](ImVec2 p) { return (p.x - anchor.x + p.y - anchor.y) * std::numbers::sqrt2_v<float> / 2; };
  float lowest = across(outline[0]), highest = lowest;
  for (const ImVec2& p : outline) {
    lowest = std::min(lowest, across(p));
    highest = std::max(highest, across(p));
  }
  const std::size_t count = outline.size();
  for (float c = std::ceil(lowest / kStripeSpacing) * kStripeSpacing; c < highest; c += kStripeSpacing) {
    // A line meets a convex outline's edges at most twice.
    std::array<ImVec2, 2> ends;
    std::size_t found = 0;
    for (std::size_t i = 0; i < count && found < 2; ++i) {
      const ImVec2 a = outline[i], b = outline[(i + 1) % count];
      const float da = across(a) - c, db = across(b) - c;
      if ((da < 0) == (db < 0)) continue;
      const float t = da / (da - db);
      ends[found++] = {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
    }
    if (found == 2) list.AddLine(ends[0], ends[1], colour, kStripeWidth);
  }
}

ImU32 packed(Colour c) { return IM_COL32(c.r, c.g, c.b, c.a); }

void WorldRenderer::begin(ImDrawList& list, const ViewTransform& view) {
  const PixelRect& v = view.viewport();
  list.PushClipRect({v.x, v.y}, {v.x + v.w, v.y + v.h}, false);
  // The scene's list is drawn without the font texture (see ImGuiRenderer):
  // its lines must be anti-aliased by geometry, not by texture.
  list.Flags &= ~ImDrawListFlags_AntiAliasedLinesUseTex;
  list.AddRectFilled({v.x, v.y}, {v.x + v.w, v.y + v.h}, packed(palette::kBackground));
  list.AddRectFilled({view.left(), view.top()},
                     {view.left() + view.width(), view.top() + view.height()},
                     packed(palette::kSceneBackground));
}

void WorldRenderer::end(ImDrawList& list) { list.PopClipRect(); }

namespace {

// A rounded corner: the arc of `radius` around `corner` from the outward
// normal `from` to `to` (anticlockwise), in about 8 steps per quarter turn.
void appendArc(std::vector<Vec2>& outline, const Vec2& corner, Real radius, const Vec2& from, const Vec2& to) {
  Real start = std::atan2(from.y(), from.x());
  Real end = std::atan2(to.y(), to.x());
  if (end < start) end += 2 * std::numbers::pi_v<Real>;
  const int steps = std::max(1, int(std::ceil((end - start) / (std::numbers::pi_v<Real> / 16))));
  for (int i = 0; i <= steps; ++i) outline.push_back(corner + radius * unit(start + (end - start) * Real(i) / Real(steps)));
}

// The outline (body-local, anticlockwise) of a convex core rounded by `radius`.
void roundedOutline(std::span<const Vec2> core, std::span<const Vec2> normals, Real radius, std::vector<Vec2>& outline) {
  outline.clear();
  const std::size_t n = core.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (radius <= 0) {
      outline.push_back(core[i]);
    } else {
      appendArc(outline, core[i], radius, normals[(i + n - 1) % n], normals[i]);
    }
  }
}

// The outline of a solid, non-circular shape (polygon or capsule).
void solidOutline(const Shape& shape, std::vector<Vec2>& outline) {
  if (shape.type() == ShapeType::Polygon) {
    const Polygon& polygon = shape.polygon();
    roundedOutline(std::span(polygon.vertices.data(), std::size_t(polygon.count)),
                   std::span(polygon.normals.data(), std::size_t(polygon.count)), polygon.radius, outline);
    return;
  }
  const Capsule& capsule = shape.capsule();
  const Vec2 axis = (capsule.center2 - capsule.center1).normalized();
  const Vec2 right(axis.y(), -axis.x());
  const std::array<Vec2, 2> core{capsule.center1, capsule.center2};
  const std::array<Vec2, 2> normals{right, -right};
  roundedOutline(core, normals, capsule.radius, outline);
}

// The two ends of a boundary shape (segment or chain segment).
std::array<Vec2, 2> boundaryEnds(const Shape& shape) {
  const Segment& segment = shape.type() == ShapeType::Segment ? shape.segment() : shape.chainSegment().segment;
  return {segment.point1, segment.point2};
}

// Where the rotation mark (a line from the centre of mass) ends, body-local:
// a circle's rim along its local x axis, a polygon's first edge's middle,
// else the rim along x.
Vec2 rotationMark(const Shape& first, Real extent) {
  if (first.type() == ShapeType::Circle) return first.circle().center + Vec2(first.circle().radius, 0);
  if (first.type() == ShapeType::Polygon) return Real(0.5) * (first.polygon().vertices[0] + first.polygon().vertices[1]);
  return Vec2(extent, 0);
}

}  // namespace

void WorldRenderer::drawShape(ImDrawList& list, const ViewTransform& view, const Transform& xf, const Shape& shape,
                              const ShapeColours& colours) {
  if (colours.dashed) return drawSensorShape(list, view, xf, shape, colours);
  switch (shape.type()) {
    case ShapeType::Circle: {
      const ImVec2 centre = pixel(view, xf.apply(shape.circle().center));
      const float pixels = shape.circle().radius * view.scale();
      const int segments = circleSegments(pixels);
      if (colours.small) {
        without(list, ImDrawListFlags_AntiAliasedFill, [&] {
          list.AddCircleFilled(centre, pixels, colours.edge, segments);
          list.AddCircleFilled(centre, pixels - std::min(colours.thickness, 1.5f), colours.fill, segments);
        });
      } else {
        // Fills go without ImGui's anti-aliased fringe: the anti-aliased
        // outline covers every edge, and the fringe would double the triangles.
        without(list, ImDrawListFlags_AntiAliasedFill,
                [&] { list.AddCircleFilled(centre, pixels, colours.fill, segments); });
        if (colours.hatch != 0) {
          circlePoints(centre, pixels, segments, points_);
          hatchConvex(list, points_, pixel(view, xf.p), colours.hatch);
        }
        list.AddCircle(centre, pixels, colours.edge, segments, colours.thickness);
      }
      return;
    }
    case ShapeType::Segment:
    case ShapeType::ChainSegment: {
      // A boundary has no inside to fill: it is drawn as a thick line in the
      // fill colour, so terrain reads as ground, edged in the outline colour.
      const auto ends = boundaryEnds(shape);
      const ImVec2 from = pixel(view, xf.apply(ends[0])), to = pixel(view, xf.apply(ends[1]));
      list.AddLine(from, to, colours.edge, std::max(colours.thickness, 1.0f) + 3.0f);
      list.AddLine(from, to, colours.fill, 3.0f);
      return;
    }
    case ShapeType::Polygon:
    case ShapeType::Capsule: break;
  }
  solidOutline(shape, outline_);
  points_.clear();
  for (const Vec2& vertex : outline_) points_.push_back(pixel(view, xf.apply(vertex)));
  if (colours.small) {
    insetConvex(points_, std::min(colours.thickness, 1.5f), inset_);
    without(list, ImDrawListFlags_AntiAliasedFill, [&] {
      list.AddConvexPolyFilled(points_.data(), int(points_.size()), colours.edge);
      list.AddConvexPolyFilled(inset_.data(), int(inset_.size()), colours.fill);
    });
  } else {
    without(list, ImDrawListFlags_AntiAliasedFill,
            [&] { list.AddConvexPolyFilled(points_.data(), int(points_.size()), colours.fill); });
    if (colours.hatch != 0) hatchConvex(list, points_, pixel(view, xf.p), colours.hatch);
    list.AddPolyline(points_.data(), int(points_.size()), colours.edge, ImDrawFlags_Closed, colours.thickness);
  }
}

void WorldRenderer::drawSensorShape(ImDrawList& list, const ViewTransform& view, const Transform& xf,
                                    const Shape& shape, const ShapeColours& colours) {
  // A sensor is a region, not a solid: a faint fill edged by dashes.
  bool closed = true;
  switch (shape.type()) {
    case ShapeType::Circle: {
      const float pixels = shape.circle().radius * view.scale();
      circlePoints(pixel(view, xf.apply(shape.circle().center)), pixels, circleSegments(pixels), points_);
      break;
    }
    case ShapeType::Segment:
    case ShapeType::ChainSegment: {
      const auto ends = boundaryEnds(shape);
      points_ = {pixel(view, xf.apply(ends[0])), pixel(view, xf.apply(ends[1]))};
      closed = false;
      break;
    }
    case ShapeType::Polygon:
    case ShapeType::Capsule:
      solidOutline(shape, outline_);
      points_.clear();
      for (const Vec2& vertex : outline_) points_.push_back(pixel(view, xf.apply(vertex)));
      break;
  }
  if (closed) {
    without(list, ImDrawListFlags_AntiAliasedFill,
            [&] { list.AddConvexPolyFilled(points_.data(), int(points_.size()), colours.fill); });
  }
  path_.clear();
  for (const ImVec2& p : points_) path_.push_back({p.x, p.y});
  dashesAlong(path_, closed, kSensorDash, kSensorGap, dashes_);
  for (std::size_t i = 0; i + 1 < dashes_.size(); i += 2) {
    list.AddLine({dashes_[i].x, dashes_[i].y}, {dashes_[i + 1].x, dashes_[i + 1].y}, colours.edge,
                 colours.thickness);
  }
}

void WorldRenderer::drawBody(ImDrawList& list, const ViewTransform& view, const DrawnBody& body,
                             const SurfaceLook& surface, float thickness) {
  const BodyLook& look = *body.look;
  const Transform xf{body.state.position, Rot::fromAngle(body.state.angle)};
  Real extent = computeExtent(look.shape);
  for (const Shape& extra : look.extraShapes) extent = std::max(extent, computeExtent(extra));
  const bool small = 2 * extent * view.scale() < kSmallBody;
  // Kinematic bodies (platforms, doors, pushers) are machinery: their
  // material's fill, striped in the outline colour, unlike plain moving
  // bodies and dark static scenery.
  const ImU32 hatch = look.isKinematic && !small && !surface.dashed ? packed(surface.outline) : 0;
  const ShapeColours colours{packed(surface.fill), packed(surface.outline), thickness, small, hatch,
                             surface.dashed};
  drawShape(list, view, xf, look.shape, colours);
  for (const Shape& extra : look.extraShapes) drawShape(list, view, xf, extra, colours);
  if (look.isStatic) return;
  const Vec2 mark = xf.apply(rotationMark(look.shape, extent));
  list.AddLine(pixel(view, xf.p), pixel(view, mark), colours.edge, colours.small ? 1.0f : thickness);
}

void WorldRenderer::drawBodies(ImDrawList& list, const ViewTransform& view,
                               std::span<const DrawnBody> bodies,
                               std::optional<std::uint32_t> selected,
                               std::optional<std::uint32_t> grabbed) {
  // Static scenery first, so moving bodies are drawn over it.
  for (const bool statics : {true, false}) {
    for (const DrawnBody& body : bodies) {
      const BodyLook& look = *body.look;
      if (look.isStatic != statics) continue;
      const bool asleep = !look.isStatic && !body.state.awake;
      const bool marked = body.state.id == selected || body.state.id == grabbed;
      SurfaceLook surface = surfaceLook(look.material, look.isStatic, asleep, look.flags.isSensor);
      if (marked) surface.outline = palette::kSelection;
      const float thin = surface.dashed ? kSensorLine : kOutline;
      drawBody(list, view, body, surface, marked || asleep ? kEmphasis : thin);
    }
  }
}

void WorldRenderer::drawMarkers(ImDrawList& list, const ViewTransform& view,
                                std::span<const Marker> markers) {
  // Markers under a few centimetres are points (the polygon tutorial's
  // corners); larger ones are rings (the circle tutorial's radius).
  constexpr Real kPointMarker = Real(0.15);
  const ImU32 colour = packed(palette::kMarker);
  for (const Marker& marker : markers) {
    const ImVec2 centre = pixel(view, marker.center);
    if (marker.radius > kPointMarker) {
      list.AddCircle(centre, marker.radius * view.scale(), colour, 0, kOutline);
      list.AddCircleFilled(centre, 2.5f, colour);
    } else {
      list.AddCircleFilled(centre, std::max(5.0f, marker.radius * view.scale()), colour);
    }
  }
}

void WorldRenderer::drawJoints(ImDrawList& list, const ViewTransform& view,
                               std::span<const JointFigure> joints) {
  const ImU32 colour = packed(palette::kJoint);
  // Pins a fixed few pixels wide: a hinge is a point at any zoom.
  constexpr float kPinRadius = 4;
  for (const JointFigure& joint : joints) {
    const ImVec2 a = pixel(view, joint.a);
    const ImVec2 b = pixel(view, joint.b);
    switch (joint.look) {
      case JointLook::Rod: list.AddLine(a, b, colour, kEmphasis); break;
      case JointLook::Rope: list.AddLine(a, b, colour, 1.0f); break;
      case JointLook::Spring: {
        // Teeth about every 12 px, however long the spring is drawn.
        const float pixels = std::hypot(b.x - a.x, b.y - a.y);
        const int teeth = std::clamp(int(pixels / 12), 3, 40);
        zigzag(joint.a, joint.b, teeth, 5 / view.scale(), springPoints_);
        points_.clear();
        for (const Vec2& p : springPoints_) points_.push_back(pixel(view, p));
        list.AddPolyline(points_.data(), int(points_.size()), colour, ImDrawFlags_None, kOutline);
        break;
      }
      case JointLook::Slider:
        list.AddLine(a, b, colour, kOutline);
        list.AddCircle(a, kPinRadius, colour, 0, kOutline);
        break;
      case JointLook::Pin: list.AddCircle(a, kPinRadius, colour, 0, kEmphasis); break;
      case JointLook::Pull: drawGrab(list, view, joint.a, joint.b); break;
    }
  }
}

void WorldRenderer::drawGrab(ImDrawList& list, const ViewTransform& view, const Vec2& held,
                             const Vec2& cursor) {
  const ImU32 colour = packed(palette::kSelection);
  list.AddLine(pixel(view, held), pixel(view, cursor), colour, kOutline);
  list.AddCircleFilled(pixel(view, held), 3.5f, colour);
}

void WorldRenderer::drawPreview(ImDrawList& list, const ViewTransform& view,
                                const Controls& controls) {
  switch (controls.mode()) {
    case DrawMode::Polygon:
    case DrawMode::Chain: drawPointsPreview(list, view, controls); return;
    case DrawMode::Circle: drawCirclePreview(list, view, controls); return;
    case DrawMode::Capsule:
    case DrawMode::Segment: drawLinePreview(list, view, controls); return;
    // The ray is drawn with its answer (drawRay).
    case DrawMode::Ray:
    case DrawMode::None: return;
  }
}

void WorldRenderer::drawPointsPreview(ImDrawList& list, const ViewTransform& view,
                                      const Controls& controls) {
  // A polygon shows its inside and the edge that would close it; a chain is
  // a line, closed only when asked.
  const bool polygon = controls.mode() == DrawMode::Polygon;
  const ImU32 preview = packed(palette::kPreview);
  points_.clear();
  for (const Vec2& p : controls.placedPoints()) points_.push_back(pixel(view, p));
  if (polygon && points_.size() >= 3) {
    Colour translucent = palette::kPreview;
    translucent.a = 70;
    // Either winding may be drawn; the fringe would assume one.
    without(list, ImDrawListFlags_AntiAliasedFill, [&] {
      list.AddConvexPolyFilled(points_.data(), int(points_.size()), packed(translucent));
    });
  }
  list.AddPolyline(points_.data(), int(points_.size()), preview, ImDrawFlags_None, kOutline);
  for (const ImVec2& p : points_) list.AddCircleFilled(p, 3, preview);
  const ImVec2 cursor = pixel(view, controls.pointer());
  const bool valid = controls.pointerValid();
  if (!points_.empty() && valid) {
    // Guides from the last point to the cursor and on to the first.
    const ImU32 guide = packed(palette::kDimText);
    list.AddLine(points_.back(), cursor, guide);
    if (polygon) list.AddLine(cursor, points_.front(), guide);
  }
  list.AddCircleFilled(cursor, 5, packed(valid ? palette::kValid : palette::kInvalid));
}

void WorldRenderer::drawCirclePreview(ImDrawList& list, const ViewTransform& view,
                                      const Controls& controls) {
  if (!controls.dragStart()) return;
  const ImU32 preview = packed(palette::kPreview);
  const Vec2 centre = *controls.dragStart();
  const Real r = controls.circleRadius();
  const ImVec2 c = pixel(view, centre);
  if (r > 0) {
    list.AddCircle(c, r * view.scale(), preview, 0, kOutline);
    const Vec2 toPointer = controls.pointer() - centre;
    const Vec2 direction = toPointer.norm() > 0 ? Vec2(toPointer.normalized()) : Vec2(1, 0);
    list.AddLine(c, pixel(view, centre + r * direction), preview, kOutline);
  }
  list.AddCircleFilled(c, 3, preview);
}

void WorldRenderer::drawLinePreview(ImDrawList& list, const ViewTransform& view,
                                    const Controls& controls) {
  if (!controls.dragStart()) return;
  const ImU32 preview = packed(palette::kPreview);
  const Vec2 start = *controls.dragStart();
  const Vec2 end = controls.dragEnd();
  const ImVec2 a = pixel(view, start), b = pixel(view, end);
  if (controls.mode() == DrawMode::Capsule) {
    // The capsule as it would be made; a press not yet dragged shows its round end.
    const Real radius = controls.capsuleRadius();
    if (end == start) {
      list.AddCircle(a, radius * view.scale(), preview, 0, kOutline);
    } else {
      solidOutline(Shape::makeCapsule(start, end, radius), outline_);
      points_.clear();
      for (const Vec2& vertex : outline_) points_.push_back(pixel(view, vertex));
      list.AddPolyline(points_.data(), int(points_.size()), preview, ImDrawFlags_Closed, kOutline);
    }
  }
  list.AddLine(a, b, preview, kOutline);
  list.AddCircleFilled(a, 3, preview);
  list.AddCircleFilled(b, 3, preview);
}

void WorldRenderer::drawOver(ImDrawList& list, const ViewTransform& view, const DrawnBody& body,
                             std::optional<std::uint32_t> shapeId, const ShapeColours& colours) {
  const Transform xf{body.state.position, Rot::fromAngle(body.state.angle)};
  const BodyLook& look = *body.look;
  for (std::size_t i = 0; i <= look.extraShapes.size(); ++i) {
    if (shapeId && (i >= look.shapeIds.size() || look.shapeIds[i] != *shapeId)) continue;
    drawShape(list, view, xf, i == 0 ? look.shape : look.extraShapes[i - 1], colours);
  }
}

void WorldRenderer::drawRay(ImDrawList& list, const ViewTransform& view, const RayTool& ray,
                            const DrawnBody* hitBody) {
  const auto& answer = ray.answer();
  if (ray.aimed() && (!answer || answer->ray != *ray.aimed())) {
    list.AddLine(pixel(view, ray.aimed()->origin), pixel(view, ray.aimed()->end), packed(palette::kPreview), 1.0f);
  }
  if (!answer) return;
  const RayFigure figure = rayFigure(*answer, kRayNormalPixels / view.scale());
  const ImU32 colour = packed(palette::kRay);
  const ImVec2 origin = pixel(view, figure.origin);
  const ImVec2 reach = pixel(view, figure.reach);
  list.AddCircleFilled(origin, 3.5f, colour);
  list.AddLine(origin, reach, colour, kEmphasis);
  if (!figure.hit) return;
  // Past the hit the ray is what it would have gone on to: faint.
  list.AddLine(reach, pixel(view, figure.end), faded(palette::kRay, 0.3f), 1.0f);
  const ImU32 hitColour = packed(palette::kRayHit);
  if (hitBody != nullptr) {
    drawOver(list, view, *hitBody, answer->hit->shape, {.fill = 0, .edge = hitColour, .thickness = kEmphasis});
  }
  const ImVec2 tip = pixel(view, figure.normalTip);
  list.AddLine(reach, tip, hitColour, kEmphasis);
  list.AddTriangleFilled(tip, pixel(view, figure.barbs[0]), pixel(view, figure.barbs[1]), hitColour);
  list.AddCircleFilled(reach, 4.5f, hitColour);
}

void WorldRenderer::drawFlashes(ImDrawList& list, const ViewTransform& view, const EventFlashes& flashes,
                                const InterpolatedWorld& world, double now) {
  for (const Flash& flash : flashes.flashes()) {
    const float intensity = EventFlashes::intensity(flash, now);
    if (intensity <= 0) continue;
    if (flash.kind == Flash::Kind::Hit) {
      // A ring that widens as it fades around a fading core, at the hit.
      const HitMark mark = hitMark(flash.speed);
      const float pixels = std::max(3.0f, float(mark.radius) * view.scale());
      const ImVec2 at = pixel(view, flash.point);
      const float light = mark.brightness * intensity;
      list.AddCircleFilled(at, pixels, faded(palette::kHitFlash, 0.6f * light));
      list.AddCircle(at, pixels * (1.5f - 0.5f * intensity), faded(palette::kHitFlash, light), 0, 2.0f);
      continue;
    }
    const DrawnBody* body = world.findDrawn(flash.body);
    if (body == nullptr) continue;
    const bool sensor = flash.kind == Flash::Kind::SensorBegin;
    const Colour colour = sensor ? palette::kSensorFlash : palette::kContactFlash;
    drawOver(list, view, *body, std::nullopt,
             {.fill = sensor ? faded(colour, 0.45f * intensity) : 0,
              .edge = faded(colour, intensity),
              .thickness = sensor ? 3.0f : 2.0f});
  }
}

}  // namespace impulse::viewer
