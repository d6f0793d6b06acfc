// World's queries: point, ray casts, shape casts and overlaps. Each asks the
// broad phase for the shapes its path or area reaches (a ray clips its
// length as hits are found), then tests those shapes exactly.

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "ray_cast.h"
#include "shape_cast.h"
#include "world_data.h"

namespace impulse {
namespace {

// ---- Input checks: the error names the field, empty when it is fine ----

std::string checkTranslation(const Vec2& translation) {
  // A finite vector can still overflow its squared length.
  if (!isFinite(translation) || !isFinite(translation.squaredNorm())) {
    return "translation is not finite";
  }
  if (translation.squaredNorm() == 0) return "translation has zero length: a cast needs a direction";
  return {};
}

std::string checkRay(const Vec2& origin, const Vec2& translation) {
  if (!isFinite(origin)) return "origin is not finite";
  return checkTranslation(translation);
}

std::string checkTransform(const Transform& transform, const char* field) {
  if (!isFinite(transform.p)) return std::string(field) + " position is not finite";
  const Real lengthSquared = transform.q.c * transform.q.c + transform.q.s * transform.q.s;
  if (!isFinite(lengthSquared) || std::abs(lengthSquared - 1) > Real(1e-3)) {
    return std::string(field) + " rotation is not a unit rotation (cosine, sine)";
  }
  return {};
}

std::string checkQueryShape(const Shape& shape, const ShapeLimits& limits) {
  const ShapeError error = validateShape(shape, limits);
  if (error != ShapeError::None) return "shape: " + std::string(describe(error));
  return {};
}

std::string checkMaxResults(int maxResults, const char* field) {
  if (maxResults >= 1 && maxResults <= kMaxQueryResults) return {};
  return std::string(field) + " must be in 1.." + std::to_string(kMaxQueryResults) + ", got " +
         std::to_string(maxResults);
}

// The first error of several checks, empty when all pass.
std::string firstError(std::initializer_list<std::string> errors) {
  for (const std::string& error : errors) {
    if (!error.empty()) return error;
  }
  return {};
}

// ---- Shapes as queries see them ----

// Queries never see sensors, nor the shapes their filter refuses.
bool isVisible(const ShapeSlot& slot, const QueryFilter& filter) {
  return !slot.interaction.isSensor && queryAccepts(filter, slot.interaction.filter);
}

const Transform& transformOf(const WorldData& world, std::int32_t shape) {
  return world.bodies[world.shapes[shape].body].transform;
}

DynamicTree::Ray rayOf(const Vec2& origin, const Vec2& translation) {
  return {origin, translation, 1, Vec2::Zero()};
}

CastHit makeHit(const WorldData& world, std::int32_t shape, const Vec2& point, const Vec2& normal,
                Real fraction) {
  return {world.shapeIdOf(shape), world.idOf(world.shapes[shape].body), point, normal, fraction};
}

// The nearest of the hits offered, equal fractions going to the lower shape
// slot whatever order the broad phase offers them in.
class NearestHit {
 public:
  bool beats(Real fraction, std::int32_t shape) const {
    return shape_ < 0 || fraction < fraction_ || (fraction == fraction_ && shape < shape_);
  }
  void keep(const CastHit& hit, std::int32_t shape) {
    hit_ = hit;
    fraction_ = hit.fraction;
    shape_ = shape;
  }
  std::optional<CastHit> hit() const { return hit_; }

 private:
  std::optional<CastHit> hit_;
  Real fraction_ = 0;
  std::int32_t shape_ = -1;
};

std::optional<ShapeRayHit> rayCastSlot(const WorldData& world, std::int32_t shape,
                                       const QueryFilter& filter, const Vec2& origin,
                                       const Vec2& translation) {
  const ShapeSlot& slot = world.shapes[shape];
  if (!isVisible(slot, filter)) return std::nullopt;
  return rayCastShape(slot.ref(), transformOf(world, shape), origin, translation);
}

// The shape slots found, in slot order, as ids: at most maxResults of them.
QueryResult<ShapeId> listShapes(const WorldData& world, std::vector<std::int32_t>& shapes,
                                int maxResults) {
  std::sort(shapes.begin(), shapes.end());
  QueryResult<ShapeId> result;
  result.truncated = static_cast<int>(shapes.size()) > maxResults;
  if (result.truncated) shapes.resize(static_cast<std::size_t>(maxResults));
  result.results.reserve(shapes.size());
  for (std::int32_t shape : shapes) result.results.push_back(world.shapeIdOf(shape));
  return result;
}

}  // namespace

std::optional<BodyId> World::queryPoint(const Vec2& point, const QueryFilter& filter) const {
  if (!isFinite(point)) return std::nullopt;
  const WorldData& w = *impl_;
  std::optional<std::int32_t> best;
  w.broadPhase.query(AABB{point, point}, [&](std::int32_t shape) {
    const ShapeSlot& slot = w.shapes[shape];
    const bool newer = !best || w.bodies[slot.body].creationOrder > w.bodies[*best].creationOrder;
    if (newer && isVisible(slot, filter) && containsPoint(slot.ref(), transformOf(w, shape), point)) {
      best = slot.body;
    }
    return true;
  });
  if (!best) return std::nullopt;
  return w.idOf(*best);
}

CastResult World::castRayClosest(const Vec2& origin, const Vec2& translation,
                                 const QueryFilter& filter) const {
  if (std::string error = checkRay(origin, translation); !error.empty()) return {std::nullopt, error};
  const WorldData& w = *impl_;
  NearestHit nearest;
  w.broadPhase.rayCast(rayOf(origin, translation), [&](std::int32_t shape, Real maxFraction) {
    const std::optional<ShapeRayHit> hit = rayCastSlot(w, shape, filter, origin, translation);
    if (!hit || !nearest.beats(hit->fraction, shape)) return maxFraction;
    nearest.keep(makeHit(w, shape, origin + hit->fraction * translation, hit->normal, hit->fraction),
                 shape);
    return hit->fraction;
  });
  return {nearest.hit(), {}};
}

QueryResult<CastHit> World::castRay(const Vec2& origin, const Vec2& translation,
                                    const QueryFilter& filter, int maxHits) const {
  QueryResult<CastHit> result;
  result.error = firstError({checkRay(origin, translation), checkMaxResults(maxHits, "maxHits")});
  if (!result.ok()) return result;
  const WorldData& w = *impl_;
  struct SlotHit {
    std::int32_t shape;
    ShapeRayHit hit;
  };
  std::vector<SlotHit> hits;
  w.broadPhase.rayCast(rayOf(origin, translation), [&](std::int32_t shape, Real maxFraction) {
    if (std::optional<ShapeRayHit> hit = rayCastSlot(w, shape, filter, origin, translation)) {
      hits.push_back({shape, *hit});
    }
    return maxFraction;
  });
  std::sort(hits.begin(), hits.end(), [](const SlotHit& a, const SlotHit& b) {
    return a.hit.fraction != b.hit.fraction ? a.hit.fraction < b.hit.fraction : a.shape < b.shape;
  });
  result.truncated = static_cast<int>(hits.size()) > maxHits;
  if (result.truncated) hits.resize(static_cast<std::size_t>(maxHits));
  result.results.reserve(hits.size());
  for (const SlotHit& h : hits) {
    result.results.push_back(
        makeHit(w, h.shape, origin + h.hit.fraction * translation, h.hit.normal, h.hit.fraction));
  }
  return result;
}

CastResult World::castShape(const Shape& shape, const Transform& start, const Vec2& translation,
                            const QueryFilter& filter) const {
  const WorldData& w = *impl_;
  const std::string solid =
      isSolid(shape.type()) ? std::string() : "shape must be a circle, capsule or polygon";
  const std::string error = firstError({solid, checkQueryShape(shape, w.settings.shapeLimits),
                                        checkTransform(start, "start"), checkTranslation(translation)});
  if (!error.empty()) return {std::nullopt, error};
  // The shape's box swept along the translation finds the candidates.
  const AABB box = computeAABB(shape, start);
  const DynamicTree::Ray sweep{Real(0.5) * (box.lower + box.upper), translation, 1,
                               Real(0.5) * (box.upper - box.lower)};
  NearestHit nearest;
  w.broadPhase.rayCast(sweep, [&](std::int32_t other, Real maxFraction) {
    const ShapeSlot& slot = w.shapes[other];
    if (!isVisible(slot, filter)) return maxFraction;
    const std::optional<ShapeCastTouch> touch =
        castShapeAgainst(refOf(shape), start, translation, slot.ref(), transformOf(w, other));
    if (!touch || !nearest.beats(touch->fraction, other)) return maxFraction;
    nearest.keep(makeHit(w, other, touch->point, touch->normal, touch->fraction), other);
    return touch->fraction;
  });
  return {nearest.hit(), {}};
}

QueryResult<ShapeId> World::overlapAABB(const AABB& box, const QueryFilter& filter,
                                        int maxResults) const {
  std::string error = checkMaxResults(maxResults, "maxResults");
  if (!isFinite(box.lower) || !isFinite(box.upper)) {
    error = "box is not finite";
  } else if (box.lower.x() > box.upper.x() || box.lower.y() > box.upper.y()) {
    error = "box lower corner must not be above or right of its upper corner";
  }
  if (!error.empty()) return {{}, false, error};
  const WorldData& w = *impl_;
  std::vector<std::int32_t> found;
  w.broadPhase.query(box, [&](std::int32_t shape) {
    const ShapeSlot& slot = w.shapes[shape];
    if (isVisible(slot, filter) && computeAABB(slot.ref(), transformOf(w, shape)).overlaps(box)) {
      found.push_back(shape);
    }
    return true;
  });
  return listShapes(w, found, maxResults);
}

QueryResult<ShapeId> World::overlapShape(const Shape& shape, const Transform& transform,
                                         const QueryFilter& filter, int maxResults) const {
  const WorldData& w = *impl_;
  const std::string error =
      firstError({checkQueryShape(shape, w.settings.shapeLimits), checkTransform(transform, "transform"),
                  checkMaxResults(maxResults, "maxResults")});
  if (!error.empty()) return {{}, false, error};
  const ShapeRef query = refOf(shape);
  std::vector<std::int32_t> found;
  w.broadPhase.query(computeAABB(shape, transform), [&](std::int32_t other) {
    const ShapeSlot& slot = w.shapes[other];
    if (isVisible(slot, filter) &&
        computeSeparation(query, transform, slot.ref(), transformOf(w, other)) < 0) {
      found.push_back(other);
    }
    return true;
  });
  return listShapes(w, found, maxResults);
}

}  // namespace impulse
