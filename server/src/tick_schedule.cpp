#include "impulse/server/tick_schedule.h"

#include <algorithm>
#include <numeric>

namespace impulse::server {

TickSchedule::TickSchedule(Clock::duration period, Clock::time_point start, int maxCatchUp)
    : period_(period), start_(start), maxCatchUp_(std::max(1, maxCatchUp)) {}

TickSchedule::Due TickSchedule::due(Clock::time_point now) {
  if (now < start_) return {};
  // Ticks 0..passed-1 have deadlines at or before now.
  const std::int64_t passed = (now - start_) / period_ + 1;
  const std::int64_t late = passed - next_;
  if (late <= 0) return {};
  Due result;
  result.run = int(std::min<std::int64_t>(late, maxCatchUp_));
  result.skipped = late - result.run;
  next_ = passed;
  skipped_ += result.skipped;
  return result;
}

Clock::time_point TickSchedule::nextDeadline() const { return start_ + next_ * period_; }

TickTimes::TickTimes(std::size_t window) : samples_(std::max<std::size_t>(1, window), 0.0) {}

void TickTimes::record(double milliseconds) {
  last_ = milliseconds;
  samples_[next_] = milliseconds;
  next_ = (next_ + 1) % samples_.size();
  count_ = std::min(count_ + 1, samples_.size());
}

double TickTimes::mean() const {
  if (count_ == 0) return 0;
  // Before the window fills, only the first count_ slots hold samples.
  return std::accumulate(samples_.begin(), samples_.begin() + std::ptrdiff_t(count_), 0.0) /
         double(count_);
}

double TickTimes::max() const {
  if (count_ == 0) return 0;
  return *std::max_element(samples_.begin(), samples_.begin() + std::ptrdiff_t(count_));
}

}  // namespace impulse::server
