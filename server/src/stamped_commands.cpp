#include "impulse/server/stamped_commands.h"

namespace impulse::server {

namespace {

std::string stampRefusal(std::uint64_t stamp, std::uint64_t distance, const char* direction,
                         std::uint64_t tick, std::uint64_t maxDelay) {
  return "for_tick " + std::to_string(stamp) + " is " + std::to_string(distance) + " ticks " + direction +
         " the room's tick " + std::to_string(tick) + ": at most " + std::to_string(maxDelay) +
         " may be (the server's --max-input-delay)";
}

}  // namespace

StampCheck checkStamp(const v1::ClientMessage& message, std::uint64_t tick, std::uint64_t maxDelay) {
  if (!message.has_for_tick()) return {};
  const std::uint64_t stamp = message.for_tick();
  if (stamp > tick) {
    if (stamp - tick > maxDelay) return {{}, stampRefusal(stamp, stamp - tick, "ahead of", tick, maxDelay)};
    return {StampTiming::Waits, {}};
  }
  if (tick - stamp > maxDelay) return {{}, stampRefusal(stamp, tick - stamp, "behind", tick, maxDelay)};
  return {stamp == tick ? StampTiming::Now : StampTiming::Late, {}};
}

void StampedCommands::schedule(QueuedCommand&& command) {
  const std::pair key{command.message.for_tick(), command.client};
  waiting_.emplace(key, std::move(command));
}

std::vector<QueuedCommand>& StampedCommands::takeDue(std::uint64_t tick) {
  due_.clear();
  const auto end = waiting_.upper_bound({tick, ~std::uint32_t(0)});
  for (auto it = waiting_.begin(); it != end; ++it) due_.push_back(std::move(it->second));
  waiting_.erase(waiting_.begin(), end);
  return due_;
}

void StampedCommands::dropClient(std::uint32_t client) {
  std::erase_if(waiting_, [&](const auto& entry) { return entry.first.second == client; });
}

}  // namespace impulse::server
