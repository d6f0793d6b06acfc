// The drawing tools of Controls: polygon, circle, capsule, segment and chain
// drawn with the pointer, the ray tool's drag, and the standard shapes stamped at the cursor.
#include <algorithm>

#include "chain_drawing.h"
#include "controls.h"
#include "impulse/client/number_format.h"
#include "standard_shapes.h"

namespace impulse::viewer {

namespace {

std::vector<client::Point> toPoints(std::span<const Vec2> points) {
  std::vector<client::Point> out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back(toPoint(p));
  return out;
}

}  // namespace

bool Controls::pointerValid() const {
  if (mode_ != DrawMode::Polygon && mode_ != DrawMode::Chain) return false;
  std::vector<Vec2> candidate = points_;
  candidate.push_back(pointer_);
  const ShapeError error = mode_ == DrawMode::Polygon ? checkPolygonInProgress(candidate)
                                                      : checkChainInProgress(candidate);
  return error == ShapeError::None;
}

Real Controls::circleRadius() const {
  return dragStart_ ? (dragEnd_ - *dragStart_).norm() : Real(0);
}

void Controls::cancelDrawing() {
  mode_ = DrawMode::None;
  points_.clear();
  dragStart_.reset();
  dragging_ = false;
  ray_.clear();
}

client::SpawnOptions Controls::spawnOptions() const {
  client::SpawnOptions options;
  options.material = material_;
  options.isStatic = nextStatic_;
  options.ignoreGravity = !nextFeelsGravity_;
  return options;
}

void Controls::toggleMode(DrawMode mode, double now) {
  if (mode_ != mode) {
    cancelDrawing();
    mode_ = mode;
    return;
  }
  if (finishDrawing(now)) cancelDrawing();
}

bool Controls::finishDrawing(double now) {
  switch (mode_) {
    case DrawMode::Polygon: return finishPolygon(now);
    case DrawMode::Circle: return finishCircle(now);
    case DrawMode::Capsule: return finishCapsule(now);
    case DrawMode::Segment: return finishSegment(now);
    case DrawMode::Chain: return finishChain(false, now);
    // The ray tool makes nothing: pressed again, it is left.
    case DrawMode::Ray:
    case DrawMode::None: break;
  }
  return true;
}

void Controls::pressWhileDrawing(const Vec2& at) {
  if (mode_ == DrawMode::Polygon || mode_ == DrawMode::Chain) {
    if (pointerValid()) points_.push_back(at);
    return;
  }
  // Circle, capsule, segment and ray: the drag from the press.
  dragStart_ = at;
  dragEnd_ = at;
  dragging_ = true;
  if (mode_ == DrawMode::Ray) ray_.aim({at, at});
}

bool Controls::finishPolygon(double now) {
  if (points_.size() >= std::size_t(kMinPolygonVertices)) {
    send(client::spawnPolygon(toPoints(points_), spawnOptions()), "polygon");
  } else {
    notify("Polygon cancelled: it needs at least 3 points", now);
  }
  return true;
}

bool Controls::finishCircle(double now) {
  if (circleRadius() > 0) {
    send(client::spawnCircle(toPoint(*dragStart_), double(circleRadius()), spawnOptions()), "circle");
  } else {
    notify("Circle cancelled: drag from its centre to set the radius", now);
  }
  return true;
}

bool Controls::finishCapsule(double now) {
  if (dragStart_ && dragEnd_ != *dragStart_) {
    send(client::spawnCapsule(toPoint(*dragStart_), toPoint(dragEnd_), double(capsuleRadius_),
                              spawnOptions()),
         "capsule");
  } else {
    notify("Capsule cancelled: drag from one end to the other", now);
  }
  return true;
}

bool Controls::finishSegment(double now) {
  // A segment has no area: it is always scenery (static).
  if (dragStart_ && dragEnd_ != *dragStart_) {
    send(client::spawnSegment(toPoint(*dragStart_), toPoint(dragEnd_), spawnOptions()), "segment");
  } else {
    notify("Segment cancelled: drag from one end to the other", now);
  }
  return true;
}

bool Controls::finishChain(bool loop, double now) {
  if (points_.size() < 2) {
    notify("Chain cancelled: click at least 2 points", now);
    return true;
  }
  const std::vector<Vec2> points = loop ? closedChainPoints(points_) : openChainPoints(points_);
  // A loop's closing segment is new: the engine may refuse it. The drawing
  // stays, so H can still finish it open.
  if (const ShapeError error = buildChain(points, loop).error; error != ShapeError::None) {
    notify("Chain not closed: " + std::string(describe(error)), now);
    return false;
  }
  send(client::spawnChain(toPoints(points), loop, spawnOptions()), "chain");
  return true;
}

void Controls::closeChain(double now) {
  if (mode_ != DrawMode::Chain) {
    notify("Shift+H closes a chain: H starts one, clicks place its points", now);
    return;
  }
  if (finishChain(true, now)) cancelDrawing();
}

void Controls::spawnStandardShape(int sides) {
  send(client::spawnPolygon(toPoints(regularPolygon(sides, pointer_, shapeSize_)), spawnOptions()),
       std::string(standardShapeName(sides)));
}

void Controls::resizeShapes(Real factor, double now) {
  // In capsule mode the size keys set the capsule's radius.
  if (mode_ == DrawMode::Capsule) {
    capsuleRadius_ = std::clamp(capsuleRadius_ * factor, kMinCapsuleRadius, kMaxCapsuleRadius);
    notify("Capsule radius: " + client::formatNumber(capsuleRadius_, 2) + " m", now);
    return;
  }
  shapeSize_ = std::clamp(shapeSize_ * factor, kMinShapeSize, kMaxShapeSize);
  notify("Standard shapes: " + client::formatNumber(shapeSize_, 2) + " m to a corner", now);
}

}  // namespace impulse::viewer
