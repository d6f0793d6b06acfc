// The server's log lines as people read them: ISO 8601 times, numbers
// without std::to_string's six fixed decimals.
#include <gtest/gtest.h>

#include "impulse/server/log.h"
#include "impulse/wire/plain_numbers.h"

namespace impulse::server {
namespace {

TEST(LogFormat, LinesStartWithAnIsoTimeInUtc_NumbersArePlain) {
  using namespace std::chrono;
  // 2026-11-25T19:31:23.456Z
  const sys_time<milliseconds> at = sys_days(year(2026) / November / 25) + hours(19) +
                                    minutes(31) + seconds(23) + milliseconds(456);
  EXPECT_EQ(formatLogLine(at, "serving preset 0 at 60.000000 Hz, paused"),
            "2026-11-25T19:31:23.456Z impulse-server serving preset 0 at 60 Hz, paused");
  EXPECT_EQ(formatLogLine(sys_days(year(2027) / January / 1), "stopped"),
            "2027-01-01T00:00:00.000Z impulse-server stopped");
}

TEST(PlainNumbers, SixFixedDecimalsLoseTheirTrailingZeros_AllElseStays) {
  EXPECT_EQ(wire::plainNumbers("(-25.000000, -25.000000) to (50.000000, 45.000000)"),
            "(-25, -25) to (50, 45)");
  EXPECT_EQ(wire::plainNumbers("tick 0.100000 ms, 12.345678 ms"), "tick 0.1 ms, 12.345678 ms");
  EXPECT_EQ(wire::plainNumbers("-0.000000"), "0");
  for (const char* kept : {"v2 1.5 12.0000001 tick 600", "1.000000000", "a.000000", ""}) {
    EXPECT_EQ(wire::plainNumbers(kept), kept);
  }
}

}  // namespace
}  // namespace impulse::server
