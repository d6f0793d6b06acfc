// impulse-server flags: defaults, both spellings, and range errors.
#include "impulse/server/options.h"

#include <gtest/gtest.h>

#include <vector>

namespace impulse::server {
namespace {

ParsedOptions parse(std::vector<std::string_view> args) { return parseOptions(args); }

TEST(ServerOptions, DefaultsMatchTheIssue) {
  const auto parsed = parse({});
  ASSERT_TRUE(parsed.options);
  EXPECT_EQ(parsed.options->bind, "127.0.0.1");
  EXPECT_EQ(parsed.options->port, 7777);
  EXPECT_EQ(parsed.options->tickHz, 60);
  EXPECT_EQ(parsed.options->snapshotHz, 30);
  EXPECT_EQ(parsed.options->preset, 0);
  EXPECT_FALSE(parsed.options->paused);
  EXPECT_EQ(parsed.options->maxFrameBytes, std::size_t(1) << 20);
}

TEST(ServerOptions, AcceptsSeparateAndInlineValues) {
  const auto parsed =
      parse({"--port", "0", "--tick-hz=120", "--snapshot-hz", "20", "--paused", "--preset=9",
             "--bind", "0.0.0.0", "--max-clients", "3", "--max-bodies", "500", "--max-frame-bytes",
             "4096", "--substeps", "8", "--stall-timeout", "2.5", "--token", "t0k3n",
             "--admin-token=adm1n", "--idle-timeout", "7", "--max-clients-per-address", "5",
             "--max-commands-per-second", "300"});
  ASSERT_TRUE(parsed.options) << parsed.error;
  const auto& o = *parsed.options;
  EXPECT_EQ(o.port, 0);
  EXPECT_EQ(o.tickHz, 120);
  EXPECT_EQ(o.snapshotHz, 20);
  EXPECT_TRUE(o.paused);
  EXPECT_EQ(o.preset, 9);
  EXPECT_EQ(o.bind, "0.0.0.0");
  EXPECT_EQ(o.maxClients, 3);
  EXPECT_EQ(o.maxBodies, 500);
  EXPECT_EQ(o.maxFrameBytes, 4096u);
  EXPECT_EQ(o.subSteps, 8);
  EXPECT_EQ(o.stallTimeoutSeconds, 2.5);
  EXPECT_EQ(o.token, "t0k3n");
  EXPECT_EQ(o.adminToken, "adm1n");
  EXPECT_EQ(o.idleTimeoutSeconds, 7);
  EXPECT_EQ(o.maxClientsPerAddress, 5);
  EXPECT_EQ(o.maxCommandsPerSecond, 300);
}

TEST(ServerOptions, RefusesToBindBeyondLoopbackWithoutAToken) {
  const auto open = parse({"--bind", "0.0.0.0"});
  EXPECT_FALSE(open.options);
  EXPECT_NE(open.error.find("refusing to bind 0.0.0.0 without a token"), std::string::npos)
      << open.error;
  EXPECT_TRUE(parse({"--bind", "127.0.0.2"}).options);
  EXPECT_TRUE(parse({"--bind", "::1"}).options);
  // The token may come from the environment (main passes it as a default).
  ServerOptions fromEnvironment;
  fromEnvironment.token = "secret";
  const std::vector<std::string_view> args = {"--bind", "0.0.0.0"};
  EXPECT_TRUE(parseOptions(args, fromEnvironment).options);
}

TEST(ServerOptions, RefusesBadValuesWithTheFlagName) {
  const std::vector<std::pair<std::vector<std::string_view>, std::string>> cases = {
      {{"--port", "70000"}, "--port"},
      {{"--tick-hz", "0"}, "--tick-hz"},
      {{"--tick-hz", "abc"}, "--tick-hz"},
      {{"--preset", "22"}, "--preset"},
      {{"--snapshot-hz", "90"}, "--snapshot-hz may not exceed --tick-hz"},
      {{"--port"}, "--port needs a value"},
      {{"--paused=yes"}, "--paused takes no value"},
      {{"--frobnicate"}, "unknown option '--frobnicate'"},
      {{"--max-input-delay", "601"}, "--max-input-delay expects an integer in 0..600, got '601'"},
  };
  for (const auto& [args, expected] : cases) {
    const auto parsed = parse(args);
    EXPECT_FALSE(parsed.options) << expected;
    EXPECT_NE(parsed.error.find(expected), std::string::npos) << parsed.error;
  }
}

// Issue 30's limits: fields per room, their cost, rooms per address.
TEST(ServerOptions, RoomLimitsOfIssue30) {
  const auto defaults = parse({});
  ASSERT_TRUE(defaults.options);
  EXPECT_EQ(defaults.options->maxFields, 64);
  EXPECT_EQ(defaults.options->maxFieldCost, 1'000'000u);
  EXPECT_EQ(defaults.options->maxRoomsPerAddress, 4);
  const auto parsed =
      parse({"--max-fields", "3", "--max-field-cost=5000", "--max-rooms-per-address", "2"});
  ASSERT_TRUE(parsed.options) << parsed.error;
  EXPECT_EQ(parsed.options->maxFields, 3);
  EXPECT_EQ(parsed.options->maxFieldCost, 5000u);
  EXPECT_EQ(parsed.options->maxRoomsPerAddress, 2);
  EXPECT_EQ(parse({"--max-rooms-per-address", "0"}).error,
            "--max-rooms-per-address expects an integer in 1..1000, got '0'");
  EXPECT_EQ(parse({"--max-fields", "-1"}).error,
            "--max-fields expects an integer in 0..10000, got '-1'");
}

TEST(ServerOptions, HelpListsEveryFlag) {
  EXPECT_TRUE(parse({"--help"}).help);
  const std::string text = usage();
  for (const char* flag :
       {"--bind", "--port", "--tick-hz", "--snapshot-hz", "--substeps", "--preset", "--paused",
        "--max-clients", "--max-bodies", "--max-frame-bytes", "--max-fields", "--max-field-cost",
        "--max-rooms-per-address", "--room-stall-seconds", "--max-total-bodies", "--help"}) {
    EXPECT_NE(text.find(flag), std::string::npos) << flag;
  }
}

}  // namespace
}  // namespace impulse::server
