// impulse-cli's `at`: a command stamped for a tick of the room
// (ClientMessage.for_tick), absolutely or ahead of the tick last seen.
#include <gtest/gtest.h>

#include "script.h"

namespace impulse::cli {
namespace {

TEST(StampWord, AtTickStampsTheCommandItself) {
  const auto parsed = parseScriptLine("at 120 circle 1 2 0.5 wood");
  ASSERT_TRUE(parsed.command) << parsed.error;
  EXPECT_TRUE(parsed.command->message.has_spawn_circle());
  EXPECT_EQ(parsed.command->message.spawn_circle().radius(), 0.5);
  ASSERT_TRUE(parsed.command->message.has_for_tick());
  EXPECT_EQ(parsed.command->message.for_tick(), 120u);
  EXPECT_FALSE(parsed.command->ticksAhead);
}

TEST(StampWord, AtPlusNLeavesTheStampToTheTickSeenWhenSent) {
  const auto parsed = parseScriptLine("at +6 impulse 3 0 5");
  ASSERT_TRUE(parsed.command) << parsed.error;
  EXPECT_TRUE(parsed.command->message.has_apply_impulse());
  EXPECT_FALSE(parsed.command->message.has_for_tick()) << "stamped when the line runs";
  EXPECT_EQ(parsed.command->ticksAhead, 6u);
}

TEST(StampWord, BadStampsAreRefusedNamingTheProblem) {
  const auto error = [](std::string_view line) {
    const auto parsed = parseScriptLine(line);
    EXPECT_FALSE(parsed.command) << line;
    return parsed.error;
  };
  EXPECT_EQ(error("at 12"), "at TICK COMMAND | at +N COMMAND: expected a tick and a command after at");
  EXPECT_NE(error("at soon circle 1 2 0.5").find("'soon' is not a tick"), std::string::npos);
  EXPECT_NE(error("at -3 circle 1 2 0.5").find("'-3' is not a tick"), std::string::npos);
  EXPECT_NE(error("at +x circle 1 2 0.5").find("'+x' is not a tick"), std::string::npos);
  EXPECT_NE(error("at 5 bodies").find("only commands sent to the server can be stamped"), std::string::npos);
  EXPECT_NE(error("at 5 circle 1 2").find("circle"), std::string::npos) << "the command's own usage";
}

}  // namespace
}  // namespace impulse::cli
