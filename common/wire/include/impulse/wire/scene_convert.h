#pragma once
/// Scenes on the wire: a world's whole state (impulse/world_state.h) as a
/// serialised `Scene` message (proto/impulse.proto, docs/scenes.md), for
/// SaveScene / LoadScene and for scene files.

#include <cstdint>
#include <string>
#include <string_view>

#include "impulse.pb.h"
#include "impulse/wire/convert.h"
#include "impulse/world.h"
#include "impulse/world_state.h"

namespace impulse::wire {

/// The version this build writes; a scene with a higher one is refused.
inline constexpr std::uint32_t kSceneVersion = 3;  // 2: fields; 3: shapes of their own

void toWire(const WorldState& state, v1::Scene* out);
/// The world's whole state, serialised.
std::string saveScene(const World& world);

/// A Scene as the engine's state. Refused, with the reason, when it has a
/// newer version, a body without a shape or a joint without a kind; the
/// numbers themselves are checked by World::importState.
Decoded<WorldState> stateFromWire(const v1::Scene& scene);
/// Slot counts a scene may carry into a world whose body limit is
/// `maxBodies`, checked before any slot is built: a free slot costs a few
/// bytes on the wire and hundreds in memory. A world's own save always fits
/// (its slots never outnumber its body limit, its contacts come from
/// bodies within it).
struct SceneSlotLimits {
  std::size_t bodies;    ///< body slots, live or free: the body limit
  std::size_t shapes;    ///< shape slots: the world's shape limit (kShapesPerBodyOfLimit per body)
  std::size_t contacts;  ///< contact slots: kContactSlotsPerShape per shape
  std::size_t joints;    ///< joint slots: kJointSlotsPerBody per body
  std::size_t treeNodes; ///< nodes of each broad-phase tree, free ones included
};
inline constexpr std::size_t kContactSlotsPerShape = 16;
inline constexpr std::size_t kJointSlotsPerBody = 4;
SceneSlotLimits sceneSlotLimits(int maxBodies);

/// Id counters a scene may carry: far enough from the top that they cannot
/// wrap in the world's life.
inline constexpr std::uint32_t kMaxNextFieldId = std::uint32_t(1) << 31;
inline constexpr std::uint64_t kMaxNextCreationOrder = std::uint64_t(1) << 62;

/// Parses `bytes` and loads the scene into `world`; refused, with the
/// reason and the world as it was, when the bytes do not parse as a Scene,
/// carry more slots than sceneSlotLimits(world's body limit) or counters
/// past the limits above or below ids in use, or stateFromWire or
/// World::importState refuses it.
InputResult loadScene(World& world, std::string_view bytes);

}  // namespace impulse::wire
