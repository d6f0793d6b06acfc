#include "options.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

namespace impulse::viewer {
namespace {

ParsedViewerOptions parse(std::vector<std::string_view> args) { return parseViewerOptions(args); }

TEST(ViewerOptions, DefaultsConnectToLocalPort7777InA1280x720Window) {
  const auto parsed = parse({});
  ASSERT_TRUE(parsed.options);
  EXPECT_EQ(parsed.options->connect.host, "127.0.0.1");
  EXPECT_EQ(parsed.options->connect.port, 7777);
  EXPECT_EQ(parsed.options->width, 1280);
  EXPECT_EQ(parsed.options->height, 720);
  EXPECT_EQ(parsed.options->frames, 0);
}

TEST(ViewerOptions, ParsesEveryFlag) {
  const auto parsed = parse({"--connect", "10.0.0.2:9000", "--size=1024x768", "--preset", "4",
                             "--screenshot", "a.bmp", "--no-vsync"});
  ASSERT_TRUE(parsed.options) << parsed.error;
  EXPECT_EQ(parsed.options->connect.host, "10.0.0.2");
  EXPECT_EQ(parsed.options->connect.port, 9000);
  EXPECT_EQ(parsed.options->width, 1024);
  EXPECT_EQ(parsed.options->preset, 4);
  EXPECT_EQ(parsed.options->screenshot, "a.bmp");
  EXPECT_EQ(parsed.options->frames, 60);  // a screenshot needs frames to settle
  EXPECT_FALSE(parsed.options->vsync);
}

TEST(ViewerOptions, TokenComesFromTheFlag_ElseFromImpulseToken) {
  unsetenv("IMPULSE_TOKEN");
  EXPECT_EQ(parse({}).options->connect.token, "");
  EXPECT_EQ(parse({"--token", "t0k"}).options->connect.token, "t0k");
  setenv("IMPULSE_TOKEN", "from-env", 1);
  EXPECT_EQ(parse({}).options->connect.token, "from-env");
  EXPECT_EQ(parse({"--token=t0k"}).options->connect.token, "t0k");
  unsetenv("IMPULSE_TOKEN");
  EXPECT_FALSE(parse({"--token"}).options);  // a value is required
}

TEST(ViewerOptions, RoomIsSentInHello_DefaultTheDefaultRoom) {
  EXPECT_EQ(parse({}).options->connect.room, "");  // Hello.room "" is the room "default"
  EXPECT_EQ(parse({"--room", "match-7"}).options->connect.room, "match-7");
  EXPECT_FALSE(parse({"--room"}).options);  // a value is required
}

TEST(ViewerOptions, QuantizedAsksForCompactSnapshots_DefaultPlain) {
  EXPECT_EQ(parse({}).options->connect.snapshotEncoding, v1::SNAPSHOT_ENCODING_PLAIN);
  EXPECT_EQ(parse({"--quantized"}).options->connect.snapshotEncoding, v1::SNAPSHOT_ENCODING_QUANTIZED);
}

TEST(ViewerOptions, RefusesBadValuesWithAMessage) {
  for (const auto& args : std::vector<std::vector<std::string_view>>{
           {"--connect", "nohost"}, {"--size", "80x60"}, {"--preset", "22"}, {"--frames"},
           {"--bogus", "1"}}) {
    const auto parsed = parse(args);
    EXPECT_FALSE(parsed.options) << args[0];
    EXPECT_FALSE(parsed.error.empty()) << args[0];
  }
  EXPECT_TRUE(parse({"--help"}).help);
  // The message names the flag as the user wrote it.
  EXPECT_NE(parse({"--preset", "22"}).error.find("--preset"), std::string::npos);
}

TEST(ViewerOptions, UsageListsEveryFlagInAlignedColumns) {
  const std::string usage = viewerUsage();
  std::size_t column = std::string::npos;
  for (const char* flag : {"--connect", "--size", "--preset", "--screenshot", "--frames",
                           "--no-vsync", "--token", "-h,--help"}) {
    const auto at = usage.find(std::string("  ") + flag) + 2;
    ASSERT_NE(at, std::string::npos + 2) << flag;
    // Each description starts in the same column as the others.
    const auto lineStart = usage.rfind('\n', at) + 1;
    const auto lineEnd = usage.find('\n', at);
    const std::string line = usage.substr(lineStart, lineEnd - lineStart);
    const auto gap = line.find("  ", at - lineStart + std::string(flag).size());
    ASSERT_NE(gap, std::string::npos) << line;
    const auto text = line.find_first_not_of(' ', gap);
    if (column == std::string::npos) column = text;
    EXPECT_EQ(text, column) << line;
  }
}

}  // namespace
}  // namespace impulse::viewer
