#pragma once
/// Fixed-rate tick scheduling against a steady clock, and tick timing.

#include <chrono>
#include <cstdint>
#include <vector>

namespace impulse::server {

using Clock = std::chrono::steady_clock;

/// Tick k is due at start + k * period: deadlines come from the tick count,
/// never from "now + period", so timer latency does not accumulate into
/// drift. After an overrun at most `maxCatchUp` late ticks run back to back;
/// older ones are skipped (counted) so an overloaded server never spirals.
class TickSchedule {
 public:
  struct Due {
    int run = 0;               ///< ticks to run now
    std::int64_t skipped = 0;  ///< late ticks dropped
  };

  TickSchedule(Clock::duration period, Clock::time_point start, int maxCatchUp = 4);

  /// The ticks whose deadline has passed at `now`; advances the schedule.
  Due due(Clock::time_point now);
  /// When the next tick is due.
  Clock::time_point nextDeadline() const;
  /// Counts `ticks` of those due() returned to run as skipped instead.
  void skip(int ticks) { skipped_ += ticks; }
  /// Tick slots consumed so far (run + skipped).
  std::int64_t slots() const { return next_; }
  std::int64_t skipped() const { return skipped_; }
  Clock::time_point start() const { return start_; }
  Clock::duration period() const { return period_; }

 private:
  Clock::duration period_;
  Clock::time_point start_;
  int maxCatchUp_;
  std::int64_t next_ = 0;
  std::int64_t skipped_ = 0;
};

/// Durations of the most recent ticks (a window of fixed length).
class TickTimes {
 public:
  explicit TickTimes(std::size_t window);
  void record(double milliseconds);
  double last() const { return last_; }
  double mean() const;
  double max() const;

 private:
  std::vector<double> samples_;
  std::size_t next_ = 0;
  std::size_t count_ = 0;
  double last_ = 0;
};

}  // namespace impulse::server
