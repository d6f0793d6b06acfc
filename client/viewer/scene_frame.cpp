#include "scene_frame.h"

#include "view_transform.h"

namespace impulse::viewer {

namespace {

// `area` grown about its centre to at least the preset scene's size.
AABB atLeastPresetScene(const AABB& area) {
  const Vec2 centre = (area.lower + area.upper) / 2;
  const Vec2 half = (area.upper - area.lower).cwiseMax(kSceneSize) / 2;
  return {centre - half, centre + half};
}

AABB areaOf(std::span<const Vec2> points) {
  AABB area{points.front(), points.front()};
  for (const Vec2& p : points) area = area.unite({p, p});
  return area;
}

}  // namespace

bool opensOnBodies(const AABB& roomBounds) {
  return !roomBounds.contains(kPresetScene) &&
         (roomBounds.upper - roomBounds.lower).maxCoeff() > kLargestFramedRoom;
}

AABB openingFrame(const AABB& roomBounds, std::span<const Vec2> bodies) {
  if (roomBounds.contains(kPresetScene)) return kPresetScene;
  if (!opensOnBodies(roomBounds)) return roomBounds;
  if (bodies.empty()) {
    const Vec2 centre = (roomBounds.lower + roomBounds.upper) / 2;
    return atLeastPresetScene({centre, centre});
  }
  return atLeastPresetScene(areaOf(bodies).expanded(kBodiesAreaMargin));
}

}  // namespace impulse::viewer
