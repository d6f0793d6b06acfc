#include "shape_pair.h"

#include <algorithm>
#include <array>
#include <concepts>
#include <limits>
#include <utility>
#include <variant>

#include "manifold_internal.h"

namespace impulse {
namespace {

using namespace narrow;

// ---- The collide table ----
//
// One overload per unordered pair of shape types, A's type first. The table
// below is generated from this set, and a static_assert refuses to compile
// when a pair has no overload, or one in each order.

Manifold pairManifold(const Circle& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                      Real speculativeDistance) {
  return collideCircles(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Capsule& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                      Real speculativeDistance) {
  return collideCapsuleAndCircle(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Capsule& a, const Transform& xfA, const Capsule& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collideCapsules(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Segment& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                      Real speculativeDistance) {
  return collideSegmentAndCircle(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Segment& a, const Transform& xfA, const Capsule& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collideSegmentAndCapsule(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Segment& a, const Transform& xfA, const Polygon& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collideSegmentAndPolygon(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Polygon& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                      Real speculativeDistance) {
  return collidePolygonAndCircle(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Polygon& a, const Transform& xfA, const Capsule& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collidePolygonAndCapsule(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const Polygon& a, const Transform& xfA, const Polygon& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collidePolygons(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const ChainSegment& a, const Transform& xfA, const Circle& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collideChainSegmentAndCircle(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const ChainSegment& a, const Transform& xfA, const Capsule& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collideChainSegmentAndCapsule(a, xfA, b, xfB, speculativeDistance);
}
Manifold pairManifold(const ChainSegment& a, const Transform& xfA, const Polygon& b,
                      const Transform& xfB, Real speculativeDistance) {
  return collideChainSegmentAndPolygon(a, xfA, b, xfB, speculativeDistance);
}
// Boundaries have no inside to push out of: no contact between two of them
// (shapesCanCollide lets the world skip these pairs altogether).
Manifold pairManifold(const Segment&, const Transform&, const Segment&, const Transform&, Real) {
  return {};
}
Manifold pairManifold(const ChainSegment&, const Transform&, const Segment&, const Transform&,
                      Real) {
  return {};
}
Manifold pairManifold(const ChainSegment&, const Transform&, const ChainSegment&, const Transform&,
                      Real) {
  return {};
}

using Geometry = decltype(Shape::geometry);
static_assert(std::variant_size_v<Geometry> == kShapeTypeCount);

template <std::size_t I>
using GeometryAt = std::variant_alternative_t<I, Geometry>;

template <std::size_t I, std::size_t J>
constexpr bool kHasEntry = requires(const GeometryAt<I>& a, const GeometryAt<J>& b,
                                    const Transform& xf, Real distance) {
  { pairManifold(a, xf, b, xf, distance) } -> std::same_as<Manifold>;
};

template <std::size_t I, std::size_t J>
Manifold collideEntry(const void* a, const Transform& xfA, const void* b, const Transform& xfB,
                      Real speculativeDistance) {
  return pairManifold(*static_cast<const GeometryAt<I>*>(a), xfA,
                      *static_cast<const GeometryAt<J>*>(b), xfB, speculativeDistance);
}

template <std::size_t I, std::size_t J>
constexpr CollideFunction entryOf() {
  if constexpr (kHasEntry<I, J>) {
    return &collideEntry<I, J>;
  } else {
    return nullptr;
  }
}

// Exactly one order of each unordered pair (the pair of a type with itself
// included) has an overload.
template <std::size_t I, std::size_t J>
constexpr bool exactlyOneOrder() {
  if constexpr (I == J) {
    return kHasEntry<I, J>;
  } else {
    return int(kHasEntry<I, J>) + int(kHasEntry<J, I>) == 1;
  }
}

template <std::size_t I, std::size_t... J>
constexpr bool rowComplete(std::index_sequence<J...>) {
  return (exactlyOneOrder<I, J>() && ...);
}

template <std::size_t... I>
constexpr bool tableComplete(std::index_sequence<I...> rows) {
  return (rowComplete<I>(rows) && ...);
}

static_assert(tableComplete(std::make_index_sequence<kShapeTypeCount>{}),
              "every pair of shape types needs exactly one pairManifold overload, in one order");

using CollideTable = std::array<std::array<CollideFunction, kShapeTypeCount>, kShapeTypeCount>;

template <std::size_t I, std::size_t... J>
constexpr std::array<CollideFunction, kShapeTypeCount> makeRow(std::index_sequence<J...>) {
  return {entryOf<I, J>()...};
}

template <std::size_t... I>
constexpr CollideTable makeTable(std::index_sequence<I...> rows) {
  return {makeRow<I>(rows)...};
}

constexpr CollideTable kCollideTable = makeTable(std::make_index_sequence<kShapeTypeCount>{});

// The manifold of the pair computed the other way round, seen from the
// first shape: the normal reversed, the anchors and id features swapped.
Manifold reversed(const Manifold& manifold) {
  Manifold result = manifold;
  result.normal = -manifold.normal;
  for (int i = 0; i < manifold.pointCount; ++i) {
    std::swap(result.points[i].anchorA, result.points[i].anchorB);
    result.points[i].id = swapFeatures(manifold.points[i].id);
  }
  return result;
}

// ---- Separation ----

// A shape's core (a point, a segment or a convex polygon) and the radius
// around it, in its body's frame.
struct Core {
  Polygon polygon;  // count 1 for a circle's centre
  Real radius = 0;
};

Core coreOf(ShapeRef shape) {
  switch (shape.type) {
    case ShapeType::Circle: {
      const auto& circle = *static_cast<const Circle*>(shape.geometry);
      Core core;
      core.polygon.count = 1;
      core.polygon.vertices[0] = circle.center;
      core.radius = circle.radius;
      return core;
    }
    case ShapeType::Capsule: {
      const auto& capsule = *static_cast<const Capsule*>(shape.geometry);
      return {makeTwoSidedPolygon(capsule.center1, capsule.center2, 0), capsule.radius};
    }
    case ShapeType::Segment: {
      const auto& segment = *static_cast<const Segment*>(shape.geometry);
      return {makeTwoSidedPolygon(segment.point1, segment.point2, 0), 0};
    }
    case ShapeType::Polygon: {
      Core core{*static_cast<const Polygon*>(shape.geometry), 0};
      core.radius = core.polygon.radius;
      core.polygon.radius = 0;
      return core;
    }
    case ShapeType::ChainSegment: {
      // Continuous collision treats a chain segment as two-sided.
      const auto& chain = *static_cast<const ChainSegment*>(shape.geometry);
      return {makeTwoSidedPolygon(chain.segment.point1, chain.segment.point2, 0), 0};
    }
  }
  return {};
}

Real distanceToCore(const Polygon& core, const Vec2& p) {
  return core.count == 1 ? (p - core.vertices[0]).norm() : distanceToBoundary(core, p);
}

// Segment cores in (near) parallel make a degenerate Minkowski difference,
// whose edge normals do not decide overlap.
bool parallelSegments(const Polygon& a, const Polygon& b) {
  Vec2 da = (a.vertices[1] - a.vertices[0]).normalized();
  Vec2 db = (b.vertices[1] - b.vertices[0]).normalized();
  return std::abs(cross(da, db)) < Real(1e-6);
}

// Signed distance of two cores, b given in a's frame:
//   SAT over the edge normals of each core with two or more vertices
//   overlapping (SAT <= 0) and the normals decide it (a polygon involved, or
//   two segments not parallel): minus the depth, the SAT value
//   otherwise apart (or degenerate: a point or parallel segments, which
//   touch at most): the closest pair is a vertex of one and an edge or
//   vertex of the other
Real coreSeparation(const Polygon& a, const Polygon& b) {
  Real sat = -std::numeric_limits<Real>::max();
  if (a.count >= 2) sat = findMaxSeparation(a, b).separation;
  if (b.count >= 2) sat = std::max(sat, findMaxSeparation(b, a).separation);
  bool decisive =
      a.count >= 3 || b.count >= 3 || (a.count == 2 && b.count == 2 && !parallelSegments(a, b));
  if (sat <= 0 && decisive) {
    return sat;
  }
  // A point core's own distances to the other's vertices add nothing to
  // its distance to the other's boundary.
  Real distance = std::numeric_limits<Real>::max();
  if (b.count > 1) {
    for (int i = 0; i < a.count; ++i)
      distance = std::min(distance, distanceToCore(b, a.vertices[i]));
  }
  if (a.count > 1 || b.count == 1) {
    for (int i = 0; i < b.count; ++i)
      distance = std::min(distance, distanceToCore(a, b.vertices[i]));
  }
  return distance;
}

}  // namespace

CollideFunction collideFunction(ShapeType a, ShapeType b) {
  auto indexA = static_cast<std::size_t>(a);
  auto indexB = static_cast<std::size_t>(b);
  // Types may come from decoded network data: an unknown value has no function.
  if (indexA >= kCollideTable.size() || indexB >= kCollideTable[indexA].size()) {
    return nullptr;
  }
  return kCollideTable[indexA][indexB];
}

bool shapesCanCollide(ShapeType a, ShapeType b) { return isSolid(a) || isSolid(b); }

Manifold collide(ShapeRef a, const Transform& xfA, ShapeRef b, const Transform& xfB,
                 Real speculativeDistance) {
  if (CollideFunction function = collideFunction(a.type, b.type)) {
    return function(a.geometry, xfA, b.geometry, xfB, speculativeDistance);
  }
  CollideFunction function = collideFunction(b.type, a.type);
  return reversed(function(b.geometry, xfB, a.geometry, xfA, speculativeDistance));
}

Manifold collide(const Shape& a, const Transform& xfA, const Shape& b, const Transform& xfB,
                 Real speculativeDistance) {
  return collide(refOf(a), xfA, refOf(b), xfB, speculativeDistance);
}

// The distance is symmetric: a circle is measured in its partner's frame,
// A's frame otherwise, and two circles in world, as before shapes had more
// types, so the results of circles and sharp polygons keep their bits.
Real computeSeparation(ShapeRef a, const Transform& xfA, ShapeRef b, const Transform& xfB) {
  Core coreA = coreOf(a);
  Core coreB = coreOf(b);
  if (coreA.polygon.count == 1 && coreB.polygon.count == 1) {
    Vec2 centerA =
        coreA.polygon.vertices[0].isZero() ? xfA.p : xfA.apply(coreA.polygon.vertices[0]);
    Vec2 centerB =
        coreB.polygon.vertices[0].isZero() ? xfB.p : xfB.apply(coreB.polygon.vertices[0]);
    return (centerB - centerA).norm() - coreA.radius - coreB.radius;
  }
  if (coreA.polygon.count == 1) {
    return computeSeparation(b, xfB, a, xfA);
  }
  Transform relative = relativeTransform(xfA, xfB);
  Polygon localB = transformPolygon(coreB.polygon, relative);
  if (coreB.polygon.count == 1) localB.vertices[0] = placeInA(relative, coreB.polygon.vertices[0]);
  return coreSeparation(coreA.polygon, localB) - coreA.radius - coreB.radius;
}

}  // namespace impulse
