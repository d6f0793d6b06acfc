#pragma once
/// Per-client command rate limit: a token bucket that refills at `rate`
/// commands per second and holds at most `burst`.

#include "impulse/server/tick_schedule.h"

namespace impulse::server {

class RateLimiter {
 public:
  RateLimiter(double rate, double burst, Clock::time_point now);
  /// Takes one token: false when the client is over its rate.
  bool take(Clock::time_point now);
  /// How long until a token can be taken (zero when one can now).
  Clock::duration untilAvailable(Clock::time_point now);

 private:
  void refill(Clock::time_point now);

  double rate_;
  double burst_;
  double tokens_;
  Clock::time_point last_;
};

}  // namespace impulse::server
