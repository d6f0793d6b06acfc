#include "impulse/server/fair_queue.h"

namespace impulse::server {

void FairQueue::push(std::uint32_t client, v1::ClientMessage&& message, std::size_t bytes) {
  queues_[client].push_back({client, std::move(message), bytes});
  ++size_;
}

std::optional<QueuedCommand> FairQueue::pop() {
  auto it = nextServed();
  if (it == queues_.end()) return std::nullopt;
  QueuedCommand command = std::move(it->second.front());
  it->second.pop_front();
  --size_;
  nextClient_ = it->first + 1;
  // Only clients with work keep a queue, so a pop never scans idle ones.
  if (it->second.empty()) queues_.erase(it);
  return command;
}

FairQueue::Queues::iterator FairQueue::nextServed() {
  // Held clients are few (those with a Step in progress): skipping them
  // costs a step or two.
  const auto start = queues_.lower_bound(nextClient_);
  for (auto it = start; it != queues_.end(); ++it) {
    if (!held_.contains(it->first)) return it;
  }
  for (auto it = queues_.begin(); it != start; ++it) {
    if (!held_.contains(it->first)) return it;
  }
  return queues_.end();
}

std::size_t FairQueue::dropClient(std::uint32_t client) {
  held_.erase(client);
  const auto it = queues_.find(client);
  if (it == queues_.end()) return 0;
  const std::size_t dropped = it->second.size();
  size_ -= dropped;
  queues_.erase(it);
  return dropped;
}

}  // namespace impulse::server
