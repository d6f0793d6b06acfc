#pragma once
/// Commands stamped with the tick they are meant for (ClientMessage.for_tick,
/// docs/networked-play.md): they wait here until the room reaches that tick,
/// and are then applied in (tick, client, arrival) order, so two clients'
/// inputs for one tick meet at that tick whatever order they arrived in.

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "impulse/server/fair_queue.h"

namespace impulse::server {

/// Where a stamp puts its command, seen from the room's tick now.
enum class StampTiming { Unstamped, Waits, Now, Late };

/// How a command's stamp relates to `tick`, or (in `refusal`) why it is
/// refused: more than `maxDelay` ticks ahead or behind.
struct StampCheck {
  StampTiming timing = StampTiming::Unstamped;
  std::string refusal;
};
StampCheck checkStamp(const v1::ClientMessage& message, std::uint64_t tick, std::uint64_t maxDelay);

class StampedCommands {
 public:
  /// Keeps a command until its for_tick comes.
  void schedule(QueuedCommand&& command);
  /// The commands whose tick is `tick` or earlier, in (tick, client,
  /// arrival) order; they are forgotten here. Valid until the next call.
  std::vector<QueuedCommand>& takeDue(std::uint64_t tick);
  /// Forgets a client's commands (it left).
  void dropClient(std::uint32_t client);
  void clear() { waiting_.clear(); }
  std::size_t size() const { return waiting_.size(); }

 private:
  // A multimap keeps arrival order among equal keys.
  std::multimap<std::pair<std::uint64_t, std::uint32_t>, QueuedCommand> waiting_;
  std::vector<QueuedCommand> due_;
};

}  // namespace impulse::server
