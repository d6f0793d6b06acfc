#pragma once
/// A step's events (impulse/events.h) as an Events message.

#include <cstdint>

#include "impulse.pb.h"
#include "impulse/events.h"

namespace impulse::wire {

/// Most events one Events message carries, over all its lists; past it the
/// message says `truncated` (a tick of a pile's first landing stays well
/// under it, and a frame of this many events fits the frame limit).
inline constexpr int kMaxEventsPerMessage = 4096;

/// The events in `out`, list by list in the order Events declares them, up
/// to kMaxEventsPerMessage.
void toWire(const StepEvents& events, std::uint64_t tick, std::uint64_t sequence, v1::Events* out);

}  // namespace impulse::wire
