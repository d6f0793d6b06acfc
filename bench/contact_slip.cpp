#include "contact_slip.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "joint_error.h"
#include "placed_polygon.h"
#include "spawn_schedule.h"

namespace bench {

namespace {

// Box2D v3's rule (CollisionFilter).
bool collide(const CollisionFilter& a, const CollisionFilter& b) {
  if (a.group == b.group && a.group != 0) return a.group > 0;
  return (a.category & b.mask) != 0 && (b.category & a.mask) != 0;
}

bool mayTouch(const BodyDesc& a, const BodyDesc& b) {
  return !(a.isStatic && b.isStatic) && collide(a.shape.filter, b.shape.filter);
}

struct ContactPoint {
  Vec2d point;
  Vec2d normal;  ///< from the first polygon to the second
};

// The part of the segment p-q whose projection on `axis` (from `origin`)
// falls within [0, length], or nothing.
std::optional<std::pair<Vec2d, Vec2d>> clipToFace(Vec2d p, Vec2d q, const Vec2d& origin,
                                                  const Vec2d& axis, double length) {
  const double sp = dot(sub(p, origin), axis), sq = dot(sub(q, origin), axis);
  if (std::max(sp, sq) < 0 || std::min(sp, sq) > length) return std::nullopt;
  auto at = [&](double s) {
    const double t = (s - sp) / (sq - sp);
    return Vec2d{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
  };
  const Vec2d clippedP = sp < 0 ? at(0) : sp > length ? at(length) : p;
  const Vec2d clippedQ = sq < 0 ? at(0) : sq > length ? at(length) : q;
  return std::pair{clippedP, clippedQ};
}

// Where two convex polygons touch (within ContactSlipProbe::kTouching): the
// face one lies farthest out from (or least deep into), clipped against the
// other's edge that faces it most; the contact is the middle of the
// clipped points that come within reach of that face, each taken midway
// between the two surfaces.
std::optional<ContactPoint> contactOf(const std::vector<Vec2d>& first,
                                      const std::vector<Vec2d>& second) {
  const DeepestFace onFirst = deepestFace(first, second), onSecond = deepestFace(second, first);
  const bool firstHoldsFace = onFirst.separation >= onSecond.separation;
  const std::vector<Vec2d>& reference = firstHoldsFace ? first : second;
  const std::vector<Vec2d>& incident = firstHoldsFace ? second : first;
  const DeepestFace face = firstHoldsFace ? onFirst : onSecond;
  if (face.separation > ContactSlipProbe::kTouching) return std::nullopt;

  const Vec2d n = edgeNormal(reference, face.edge);
  const Vec2d v1 = reference[face.edge], v2 = reference[(face.edge + 1) % reference.size()];
  const double length = std::hypot(v2.x - v1.x, v2.y - v1.y);
  const Vec2d along{(v2.x - v1.x) / length, (v2.y - v1.y) / length};
  std::size_t facing = 0;
  for (std::size_t i = 1; i < incident.size(); ++i) {
    if (dot(edgeNormal(incident, i), n) < dot(edgeNormal(incident, facing), n)) facing = i;
  }
  const auto clipped =
      clipToFace(incident[facing], incident[(facing + 1) % incident.size()], v1, along, length);
  if (!clipped) return std::nullopt;

  Vec2d sum{};
  int count = 0;
  for (const Vec2d& q : {clipped->first, clipped->second}) {
    const double separation = dot(sub(q, v1), n);
    if (separation > ContactSlipProbe::kTouching) continue;
    sum = {sum.x + q.x - 0.5 * separation * n.x, sum.y + q.y - 0.5 * separation * n.y};
    ++count;
  }
  if (count == 0) return std::nullopt;
  const double sign = firstHoldsFace ? 1 : -1;
  return ContactPoint{{sum.x / count, sum.y / count}, {sign * n.x, sign * n.y}};
}

}  // namespace

ContactSlipProbe::ContactSlipProbe(const SceneDescription& scene) : scene_(scene) {
  std::vector<Pose> poses;
  for (int i = 0; i < static_cast<int>(scene.bodies.size()); ++i) {
    const BodyDesc& body = scene.bodies[std::size_t(i)];
    if (body.shape.kind != ShapeKind::Polygon || !body.extraShapes.empty()) continue;
    polygons_.push_back(i);
    poses.push_back(describedPose(body));
  }
  findTouches(poses);
}

void ContactSlipProbe::observe(const EngineAdapter& engine) {
  std::vector<Pose> poses;
  for (int i : polygons_) poses.push_back(engine.pose(i));
  for (const Touch& touch : touches_) {
    const Vec2d a = worldPoint(poses[touch.polygons.first], touch.localA);
    const Vec2d b = worldPoint(poses[touch.polygons.second], touch.localB);
    double& slip = slip_[touch.polygons];
    slip += dot(sub(b, a), touch.tangent);
    largest_ = std::max(largest_, std::abs(slip));
  }
  findTouches(poses);
}

void ContactSlipProbe::findTouches(const std::vector<Pose>& poses) {
  touches_.clear();
  std::vector<PlacedShape> placed;
  for (std::size_t j = 0; j < polygons_.size(); ++j) {
    placed.push_back(place(scene_.bodies[std::size_t(polygons_[j])], poses[j]));
  }
  for (std::size_t j = 0; j < polygons_.size(); ++j) {
    for (std::size_t k = j + 1; k < polygons_.size(); ++k) {
      const BodyDesc& first = scene_.bodies[std::size_t(polygons_[j])];
      const BodyDesc& second = scene_.bodies[std::size_t(polygons_[k])];
      const double reach = first.shape.extent() + second.shape.extent() + kTouching;
      const Vec2d apart = sub(placed[k].centre, placed[j].centre);
      if (!mayTouch(first, second) || std::hypot(apart.x, apart.y) > reach) continue;
      const auto contact = contactOf(placed[j].vertices, placed[k].vertices);
      if (!contact) continue;
      touches_.push_back({{j, k},
                          localPoint(poses[j], contact->point),
                          localPoint(poses[k], contact->point),
                          {-contact->normal.y, contact->normal.x}});
    }
  }
}

}  // namespace bench
