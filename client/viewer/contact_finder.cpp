#include "contact_finder.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "impulse/manifold.h"

namespace impulse::viewer {

namespace {

Transform transformOf(const DrawnBody& body) {
  return {body.state.position, Rot::fromAngle(body.state.angle)};
}

// Calls visit(shape) for each of the body's shapes.
template <class Visit>
void forEachShape(const BodyLook& look, Visit&& visit) {
  visit(look.shape);
  for (const Shape& extra : look.extraShapes) visit(extra);
}

AABB boundsOf(const DrawnBody& body) {
  const Transform xf = transformOf(body);
  std::optional<AABB> box;
  forEachShape(*body.look, [&](const Shape& shape) {
    const AABB shapeBox = computeAABB(shape, xf);
    box = box ? box->unite(shapeBox) : shapeBox;
  });
  return *box;
}

// Every shape of one body against every shape of the other.
void collidePair(const DrawnBody& a, const DrawnBody& b, Real tolerance, std::vector<ShownContact>& out) {
  const Transform xfA = transformOf(a);
  const Transform xfB = transformOf(b);
  forEachShape(*a.look, [&](const Shape& first) {
    forEachShape(*b.look, [&](const Shape& second) {
      const Manifold manifold = collide(first, xfA, second, xfB);
      for (int i = 0; i < manifold.pointCount; ++i) {
        if (manifold.points[i].separation > tolerance) continue;
        out.push_back({manifold.points[i].point, manifold.normal});
      }
    });
  });
}

}  // namespace

void findContacts(std::span<const DrawnBody> bodies, std::vector<ShownContact>& out,
                  Real tolerance) {
  out.clear();
  std::vector<AABB> boxes(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    boxes[i] = boundsOf(bodies[i]);
  }
  std::vector<std::size_t> order(bodies.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].lower.x() < boxes[b].lower.x(); });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::size_t a = order[i];
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const std::size_t b = order[j];
      if (boxes[b].lower.x() > boxes[a].upper.x() + tolerance) break;
      if (bodies[a].look->isStatic && bodies[b].look->isStatic) continue;
      if (!boxes[a].overlaps(boxes[b])) continue;
      collidePair(bodies[a], bodies[b], tolerance, out);
    }
  }
}

}  // namespace impulse::viewer
