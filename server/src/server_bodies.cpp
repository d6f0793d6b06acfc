#include "impulse/server/server_bodies.h"

#include <utility>

namespace impulse::server {

ServerBodies::Share::Share(Share&& other) noexcept
    : total_(std::move(other.total_)), counted_(std::exchange(other.counted_, 0)) {}

ServerBodies::Share::~Share() { set(0); }

void ServerBodies::Share::set(std::int64_t bodies) {
  if (total_ == nullptr) return;
  total_->total_ += bodies - counted_;
  counted_ = bodies;
}

std::string ServerBodies::Share::refusal(std::int64_t added) const {
  if (total_ == nullptr || added <= 0) return {};
  const std::int64_t total = total_->total();
  if (total + added <= total_->limit()) return {};
  return "server body limit reached: the rooms together hold " + std::to_string(total) +
         " bodies of at most " + std::to_string(total_->limit()) +
         " (--max-total-bodies); this room holds " + std::to_string(counted_) +
         ", adding " + std::to_string(added) + " would pass it";
}

}  // namespace impulse::server
