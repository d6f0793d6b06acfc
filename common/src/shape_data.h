#pragma once
// A shape as the step sees it (the public face is ShapeDef, ShapeId and
// World's shape functions). Shapes live in one slot array; each body threads
// its shapes through `nextInBody`, in the order they were added. A slot holds
// no geometry: each type's geometry lives in a pool of its own, at the size
// of its type (a circle takes 12 bytes, a polygon 268), and the slot points
// at it, so the arrays the step strides over hold no polygon-sized slots.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <variant>
#include <vector>

#include "edge_list.h"
#include "free_list.h"
#include "impulse/body.h"
#include "impulse/material.h"
#include "impulse/shape.h"
#include "shape_ref.h"

namespace impulse {

// Laid out by who reads it: the first cache line holds what every step
// reads of a moving body's shapes (the narrow phase the geometry; the
// boxes' update the geometry, its body, the next shape, the proxy and the
// generation), the rest what pairs read when they begin.
struct alignas(64) ShapeSlot {
  /// The geometry, in the body's frame (origin at its centre of mass): its
  /// type and its address in that type's pool (ShapeGeometries).
  ShapeRef geometry;
  std::int32_t body = kNullIndex;
  std::int32_t nextInBody = kNullIndex;
  std::int32_t proxyKey = kNullIndex;
  std::uint32_t generation = 0;
  /// Rolling resistance acts on round shapes only: their radius, else 0.
  Real rollingRadius = 0;
  /// The geometry's place in its type's pool.
  std::int32_t geometryIndex = kNullIndex;
  Material material = Material::Solid;
  bool alive = false;
  /// The material's coefficients with any override applied.
  MaterialProperties coefficients{};
  ShapeInteraction interaction;

  ShapeType type() const { return geometry.type; }
  ShapeRef ref() const { return geometry; }
  bool rolls() const { return rollingRadius > 0; }
};

/// One type's geometries in chunks that are never moved or freed while the
/// world lives, so an address handed out stays valid however the pool grows.
/// Shapes of the same geometry, bit for bit, share one place: the narrow
/// phase then reads a crowd of equal boxes' few polygons from cache instead
/// of a copy per shape from memory (on v3's smash, the first loads of a
/// polygon had been the polygon collision's costliest instructions). A
/// place is freed when its last shape lets it go; freed places are handed
/// out again, last freed first.
template <class Geometry>
class GeometryPool {
 public:
  std::int32_t add(const Geometry& geometry) {
    const std::size_t key = hashOf(geometry);
    if (const std::int32_t same = find(key, geometry); same != kNullIndex) {
      ++users_[std::size_t(same)];
      return same;
    }
    const std::int32_t index = free_.acquire(std::size_t(count_));
    if (index == count_) {
      if (index % kPerChunk == 0) chunks_.push_back(std::make_unique<Geometry[]>(kPerChunk));
      ++count_;
      users_.push_back(0);
    }
    at(index) = geometry;
    users_[std::size_t(index)] = 1;
    byHash_.emplace(key, index);
    return index;
  }
  void remove(std::int32_t index) {
    if (--users_[std::size_t(index)] > 0) return;
    auto [entry, end] = byHash_.equal_range(hashOf(at(index)));
    while (entry->second != index) ++entry;
    byHash_.erase(entry);
    free_.release(index);
  }
  /// Places that live shapes hold (shapes of one geometry share one).
  std::int32_t liveCount() const { return count_ - std::int32_t(free_.slots().size()); }
  Geometry& at(std::int32_t index) { return chunks_[std::size_t(index / kPerChunk)][index % kPerChunk]; }

 private:
  // About 16 KiB a chunk: 1365 circles or 61 polygons side by side.
  static constexpr std::int32_t kPerChunk = std::max<std::int32_t>(1, std::int32_t(16384 / sizeof(Geometry)));

  // Geometries compared by their bytes: the same bytes are the same values,
  // whatever padding a type has (these are floats and ints alone, none).
  static std::string_view bytesOf(const Geometry& geometry) {
    return {reinterpret_cast<const char*>(&geometry), sizeof(Geometry)};
  }
  static std::size_t hashOf(const Geometry& geometry) { return std::hash<std::string_view>{}(bytesOf(geometry)); }

  // The place holding the same geometry, if any.
  std::int32_t find(std::size_t key, const Geometry& geometry) {
    for (auto [entry, end] = byHash_.equal_range(key); entry != end; ++entry) {
      if (bytesOf(at(entry->second)) == bytesOf(geometry)) return entry->second;
    }
    return kNullIndex;
  }

  std::vector<std::unique_ptr<Geometry[]>> chunks_;
  std::int32_t count_ = 0;           ///< places handed out at least once
  std::vector<std::int32_t> users_;  ///< per place, the shapes that hold it
  std::unordered_multimap<std::size_t, std::int32_t> byHash_;  ///< live places by their geometry's hash
  FreeList free_;
};

/// The world's shape geometry, one pool per type. Which place a geometry
/// takes changes nothing the step computes (it reads through the address),
/// so a loaded world need not put its shapes where the saved one had them.
class ShapeGeometries {
 public:
  /// Stores a copy of the shape's geometry for the slot, giving back any
  /// geometry the slot held.
  void store(ShapeSlot& slot, const Shape& shape) {
    release(slot);
    std::visit(
        [&](const auto& geometry) {
          auto& pool = poolOf<std::decay_t<decltype(geometry)>>();
          slot.geometryIndex = pool.add(geometry);
          slot.geometry = {shape.type(), &pool.at(slot.geometryIndex)};
        },
        shape.geometry);
  }

  /// Gives the slot's geometry back to its pool (nothing when it has none).
  void release(ShapeSlot& slot) {
    if (slot.geometryIndex == kNullIndex) return;
    visitGeometry(slot.geometry, [&](const auto& geometry) {
      poolOf<std::decay_t<decltype(geometry)>>().remove(slot.geometryIndex);
    });
    slot.geometry = {};
    slot.geometryIndex = kNullIndex;
  }

  /// How many geometries of the type live shapes hold (none: no shape is of
  /// the type).
  template <class Geometry>
  std::int32_t liveCount() const {
    return std::get<GeometryPool<Geometry>>(pools_).liveCount();
  }

 private:
  template <class Geometry>
  GeometryPool<Geometry>& poolOf() {
    return std::get<GeometryPool<Geometry>>(pools_);
  }

  std::tuple<GeometryPool<Circle>, GeometryPool<Capsule>, GeometryPool<Segment>, GeometryPool<Polygon>,
             GeometryPool<ChainSegment>>
      pools_;
};

}  // namespace impulse
