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
/// Parses `bytes` and loads the scene into `world`; refused, with the
/// reason and the world as it was, when the bytes do not parse as a Scene
/// or stateFromWire or World::importState refuses it.
InputResult loadScene(World& world, std::string_view bytes);

}  // namespace impulse::wire
