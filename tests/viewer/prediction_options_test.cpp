// The viewer's prediction flags: on by default, --no-predict, and
// --added-rtt to try a slow link on loopback; bad values refused by name.
#include <gtest/gtest.h>

#include <vector>

#include "options.h"

namespace impulse::viewer {
namespace {

ParsedViewerOptions parse(std::vector<std::string_view> args) { return parseViewerOptions(args); }

TEST(ViewerPredictionOptions, PredictsByDefault_NoPredictTurnsItOff) {
  EXPECT_TRUE(parse({}).options->predict);
  EXPECT_FALSE(parse({"--no-predict"}).options->predict);
  EXPECT_NE(viewerUsage().find("--no-predict"), std::string::npos);
}

TEST(ViewerPredictionOptions, AddedRoundTripInMilliseconds) {
  EXPECT_EQ(parse({}).options->connect.addedRoundTrip.count(), 0);
  const auto parsed = parse({"--added-rtt", "150"});
  ASSERT_TRUE(parsed.options) << parsed.error;
  EXPECT_EQ(parsed.options->connect.addedRoundTrip.count(), 150);
  for (const char* bad : {"-5", "10001", "slow"}) {
    const auto refused = parse({"--added-rtt", bad});
    EXPECT_FALSE(refused.options) << bad;
    EXPECT_NE(refused.error.find("--added-rtt"), std::string::npos) << bad << ": " << refused.error;
  }
}

}  // namespace
}  // namespace impulse::viewer
