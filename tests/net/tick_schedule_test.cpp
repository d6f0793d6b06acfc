// The tick schedule: deadlines on a fixed grid (no drift whatever the timer
// latency) and bounded catch-up after an overrun.
#include "impulse/server/tick_schedule.h"

#include <gtest/gtest.h>

#include <random>

namespace impulse::server {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;

TEST(TickSchedule, NoDriftOverAnHourOfLateWakeups) {
  const Clock::time_point start{};
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / 60));
  TickSchedule schedule(period, start);
  std::mt19937 random(7);
  std::int64_t ran = 0;
  Clock::time_point now = start;
  // An hour of ticks, each wakeup 0-3 ms after its deadline.
  for (int i = 0; i < 60 * 3600; ++i) {
    now = schedule.nextDeadline() + microseconds(random() % 3000);
    const auto due = schedule.due(now);
    ASSERT_EQ(due.skipped, 0);
    ran += due.run;
    // Every slot whose deadline passed has been taken, no more.
    ASSERT_EQ(schedule.slots(), (now - start) / period + 1);
  }
  EXPECT_EQ(ran, schedule.slots());
  // The grid is exact: tick k at start + k * period.
  EXPECT_EQ(schedule.nextDeadline(), start + schedule.slots() * period);
  EXPECT_LT(now - start - (ran - 1) * period, period);
}

TEST(TickSchedule, OverrunRunsAFewLateTicksAndSkipsTheRest) {
  const Clock::time_point start{};
  TickSchedule schedule(milliseconds(10), start, 4);
  EXPECT_EQ(schedule.due(start).run, 1);
  // One second late: 100 deadlines passed.
  const auto due = schedule.due(start + milliseconds(1005));
  EXPECT_EQ(due.run, 4);
  EXPECT_EQ(due.skipped, 96);
  EXPECT_EQ(schedule.skipped(), 96);
  // Still on the grid, and the next deadline is in the future.
  EXPECT_EQ(schedule.nextDeadline(), start + milliseconds(1010));
  EXPECT_EQ(schedule.due(start + milliseconds(1009)).run, 0);
  EXPECT_EQ(schedule.due(start + milliseconds(1010)).run, 1);
}

TEST(TickSchedule, EarlyWakeupRunsNothing) {
  const Clock::time_point start{};
  TickSchedule schedule(milliseconds(10), start);
  EXPECT_EQ(schedule.due(start - milliseconds(1)).run, 0);
  EXPECT_EQ(schedule.due(start).run, 1);
  EXPECT_EQ(schedule.due(start + milliseconds(9)).run, 0);
}

TEST(TickTimes, MeanAndMaxOverTheWindow) {
  TickTimes times(3);
  EXPECT_EQ(times.mean(), 0);
  times.record(1);
  times.record(2);
  EXPECT_DOUBLE_EQ(times.mean(), 1.5);
  times.record(6);
  times.record(4);  // the 1 leaves the window
  EXPECT_DOUBLE_EQ(times.mean(), 4);
  EXPECT_DOUBLE_EQ(times.max(), 6);
  EXPECT_DOUBLE_EQ(times.last(), 4);
}

}  // namespace
}  // namespace impulse::server
