#pragma once
/// What the world's queries answer: ray casts, shape casts and overlaps
/// (World::castRayClosest, castRay, castShape, overlapAABB, overlapShape).
///
/// Every query goes through the broad phase, so its cost grows with the
/// shapes it touches, not with the world. Queries never see sensor shapes,
/// and see a shape only when queryAccepts(filter, its collision filter).

#include <optional>
#include <string>
#include <vector>

#include "impulse/body.h"
#include "impulse/constants.h"
#include "impulse/math.h"

namespace impulse {

/// Most results one list query may ask for (its maxResults).
inline constexpr int kMaxQueryResults = 4096;

/// A shape cast stops advancing when its shape is this close to another
/// (metres): the reported pose is at most this far from touching, and
/// never overlapping.
inline constexpr Real kShapeCastTolerance = Real(0.1) * kLinearSlop;

/// Where a ray or a cast shape first touches one shape.
struct CastHit {
  ShapeId shape;
  BodyId body;
  /// World point on the hit shape's surface.
  Vec2 point = Vec2::Zero();
  /// Unit normal of the hit shape's surface at the point, facing the ray
  /// (or the cast shape).
  Vec2 normal = Vec2::Zero();
  /// The touch is at origin + fraction * translation, fraction in [0, 1].
  Real fraction = 0;
};

/// A query with one answer: the first hit, none, or why the query was refused.
struct CastResult {
  std::optional<CastHit> hit;
  /// Empty when the query ran; otherwise it names the field that was wrong.
  std::string error;
  bool ok() const { return error.empty(); }
};

/// A query with a list of answers, at most the maxResults asked for.
template <typename T>
struct QueryResult {
  std::vector<T> results;
  /// More results existed than maxResults: the list holds the first ones in
  /// its order (for ray casts, the nearest).
  bool truncated = false;
  /// Empty when the query ran; otherwise it names the field that was wrong.
  std::string error;
  bool ok() const { return error.empty(); }
};

}  // namespace impulse
