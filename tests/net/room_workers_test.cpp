// --room-workers: how many stepping threads one room's step may work on.
#include <gtest/gtest.h>

#include <vector>

#include "impulse/server/options.h"

namespace impulse::server {
namespace {

ParsedOptions parse(std::vector<std::string_view> args) { return parseOptions(args); }

TEST(RoomWorkers, DefaultsToEveryRoomThread) {
  const auto parsed = parse({"--room-threads", "3"});
  ASSERT_TRUE(parsed.options) << parsed.error;
  EXPECT_EQ(workersPerRoom(*parsed.options), 3);
}

TEST(RoomWorkers, TakesAnyCountUpToTheRoomThreads) {
  const auto parsed = parse({"--room-workers=1", "--room-threads", "4"});
  ASSERT_TRUE(parsed.options) << parsed.error;
  EXPECT_EQ(workersPerRoom(*parsed.options), 1);
}

TEST(RoomWorkers, MoreThanTheRoomThreads_IsRefusedByName) {
  const auto parsed = parse({"--room-workers", "3", "--room-threads", "2"});
  EXPECT_FALSE(parsed.options);
  EXPECT_EQ(parsed.error,
            "--room-workers 3 exceeds --room-threads 2: a room works on the stepping threads only");
}

TEST(RoomWorkers, OutOfRange_IsRefused) {
  const auto parsed = parse({"--room-workers", "0"});
  EXPECT_FALSE(parsed.options);
  EXPECT_NE(parsed.error.find("--room-workers"), std::string::npos) << parsed.error;
}

}  // namespace
}  // namespace impulse::server
