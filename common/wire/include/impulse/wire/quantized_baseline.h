#pragma once
/// What both ends of a compact snapshot stream hold between snapshots: every
/// body's state as the client decoded it, and the tick it belongs to. The
/// next snapshot is coded against it (docs/snapshots.md).

#include <cstdint>
#include <map>

#include "impulse/wire/quantized_state.h"

namespace impulse::wire::quantized {

struct Baseline {
  /// By body id, ascending: the order bodies are coded in.
  std::map<std::uint32_t, State> bodies;
  std::uint64_t tick = 0;
  /// False until a key frame (or after a failed decode): deltas need one.
  bool valid = false;
};

}  // namespace impulse::wire::quantized
