#pragma once
/// The bodies of every room together, against the server-wide limit
/// (--max-total-bodies): --max-bodies bounds one room, and players may make
/// rooms, so without this nothing bounds the server's total load.
///
/// Each room's Simulation holds a Share and reports its body count through
/// it after every change (from the room's strand); the total is an atomic
/// sum, exact for the room asking and current for the others.

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace impulse::server {

class ServerBodies {
 public:
  explicit ServerBodies(std::int64_t limit) : limit_(limit) {}
  ServerBodies(const ServerBodies&) = delete;
  ServerBodies& operator=(const ServerBodies&) = delete;

  /// One room's part of the total.
  class Share {
   public:
    /// Shares own the total: a room may outlive the server by a moment.
    explicit Share(std::shared_ptr<ServerBodies> total = nullptr) : total_(std::move(total)) {}
    Share(Share&& other) noexcept;
    Share& operator=(Share&&) = delete;
    ~Share();
    /// The room now holds `bodies`.
    void set(std::int64_t bodies);
    /// Why the room may not grow by `added` bodies (empty when it may).
    std::string refusal(std::int64_t added) const;

   private:
    std::shared_ptr<ServerBodies> total_;
    std::int64_t counted_ = 0;
  };

  std::int64_t total() const { return total_.load(); }
  std::int64_t limit() const { return limit_; }

 private:
  std::atomic<std::int64_t> total_ = 0;
  std::int64_t limit_;
};

}  // namespace impulse::server
