#include "contact_finder.h"

#include <algorithm>
#include <numeric>

#include "impulse/manifold.h"

namespace impulse::viewer {

namespace {

Transform transformOf(const DrawnBody& body) {
  return {body.state.position, Rot::fromAngle(body.state.angle)};
}

void collidePair(const DrawnBody& a, const DrawnBody& b, Real tolerance,
                 std::vector<ShownContact>& out) {
  const Shape* first = &a.look->shape;
  const Shape* second = &b.look->shape;
  Transform xfFirst = transformOf(a);
  Transform xfSecond = transformOf(b);
  Real flip = 1;
  // The dispatch table wants the pair in one order; the normal then points
  // the other way.
  CollideFunction collide = collideFunction(first->type, second->type);
  if (collide == nullptr) {
    std::swap(first, second);
    std::swap(xfFirst, xfSecond);
    collide = collideFunction(first->type, second->type);
    flip = -1;
  }
  const Manifold manifold = collide(*first, xfFirst, *second, xfSecond);
  for (int i = 0; i < manifold.pointCount; ++i) {
    if (manifold.points[i].separation > tolerance) continue;
    out.push_back({manifold.points[i].point, flip * manifold.normal});
  }
}

}  // namespace

void findContacts(std::span<const DrawnBody> bodies, std::vector<ShownContact>& out,
                  Real tolerance) {
  out.clear();
  std::vector<AABB> boxes(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    boxes[i] = computeAABB(bodies[i].look->shape, transformOf(bodies[i]));
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
