#pragma once
/// Commands waiting for a tick, one queue per client, served round-robin:
/// each client with work gets one command in turn, so a client that
/// pipelines a hundred thousand commands delays another client's command by
/// at most one of its own, not by its whole backlog. A held client's
/// commands wait (behind its Step in progress) while the others are served.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <set>

#include "impulse.pb.h"

namespace impulse::server {

struct QueuedCommand {
  std::uint32_t client = 0;
  v1::ClientMessage message;
  /// Frame size, given back to the client's read budget once applied.
  std::size_t bytes = 0;
};

class FairQueue {
 public:
  void push(std::uint32_t client, v1::ClientMessage&& message, std::size_t bytes);
  /// The next command in round-robin order over the clients with work that
  /// are not held; nothing when there is none.
  std::optional<QueuedCommand> pop();
  /// Serves none of the client's commands until release().
  void hold(std::uint32_t client) { held_.insert(client); }
  void release(std::uint32_t client) { held_.erase(client); }
  /// Forgets every command of a client (it disconnected); returns how many.
  std::size_t dropClient(std::uint32_t client);
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

 private:
  using Queues = std::map<std::uint32_t, std::deque<QueuedCommand>>;
  /// The queue to serve next, or end() when every client with work is held.
  Queues::iterator nextServed();

  Queues queues_;
  std::set<std::uint32_t> held_;
  /// Serve the first client whose id is at least this one next (wrapping).
  std::uint32_t nextClient_ = 0;
  std::size_t size_ = 0;
};

}  // namespace impulse::server
