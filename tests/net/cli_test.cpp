// impulse-cli against the real server: one JSON line per command, errors
// that name the line, and exit codes.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(Cli, RunsEveryCommandAndPrintsOneJsonLineEach) {
  ServerProcess server({"--paused"});
  const std::string script =
      "# every command of the grammar\n"
      "preset 3\n"
      "circle 5 10 0.5 rubber\n"
      "polygon 8 10 9 10 9 11 8 11 wood static\n"
      "circle 12 10 0.3 metal nograv\n"
      "gravity 0 -5\n"
      "nudge 1 0\n"
      "reset-gravity\n"
      "step 30\n"
      "query 4\n"
      "impulse 4 10 0\n"
      "remove 6\n"
      "bodies\n"
      "resume\n"
      "wait-snapshot\n"
      "pause\n"
      "ping\n"
      "clear\n"
      "bodies\n";
  const auto run = runCli(server.port(), script);
  EXPECT_EQ(run.exitCode, 0);
  ASSERT_EQ(run.lines.size(), 19u);  // the connect line, then one per command
  EXPECT_TRUE(contains(run.lines[0], R"("command":"connect","ok":true)")) << run.lines[0];
  for (const auto& line : run.lines) {
    EXPECT_EQ(line.front(), '{');
    EXPECT_EQ(line.back(), '}');
    EXPECT_TRUE(contains(line, R"("ok":true)")) << line;
  }
  EXPECT_TRUE(contains(run.lines[1], R"({"line":2,"command":"preset","ok":true)")) << run.lines[1];
  EXPECT_TRUE(contains(run.lines[2], R"("body_id":4)")) << run.lines[2];
  EXPECT_TRUE(contains(run.lines[8], R"("command":"step","ok":true,"tick":30,"state_hash":")"))
      << run.lines[8];
  EXPECT_TRUE(contains(run.lines[9], R"("shape":"circle","radius":0.5,"material":"RUBBER")"))
      << run.lines[9];
  EXPECT_TRUE(contains(run.lines[12], R"("command":"bodies","ok":true,"tick":30,"count":5)"))
      << run.lines[12];
  EXPECT_TRUE(contains(run.lines[14], R"("command":"wait-snapshot","ok":true)")) << run.lines[14];
  EXPECT_TRUE(contains(run.lines[16], R"("server_tick":)")) << run.lines[16];
  EXPECT_TRUE(contains(run.lines[18], R"("count":0,"bodies":[])")) << run.lines[18];
}

TEST(Cli, ErrorsNameTheLineAndTheProblem) {
  ServerProcess server({"--paused"});
  const std::string script =
      "circle 1 2\n"
      "\n"
      "polygon 1 1 2 2\n"
      "query 999\n"
      "circle nan 5 1\n"
      "fly away\n"
      "step 5\n";
  const auto run = runCli(server.port(), script);
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.lines.size(), 7u);
  EXPECT_TRUE(contains(
      run.lines[1],
      R"("error":"line 1: circle X Y R [MATERIAL] [static] [nograv]: missing argument 3")"))
      << run.lines[1];
  EXPECT_TRUE(contains(
      run.lines[2],
      R"({"line":3,"command":"polygon","ok":false,"error":"line 3: spawn_polygon: 2 vertices given)"))
      << run.lines[2];
  EXPECT_TRUE(contains(run.lines[3], R"("error":"line 4: query_body: unknown body id 999")"))
      << run.lines[3];
  EXPECT_TRUE(
      contains(run.lines[4], R"("error":"line 5: spawn_circle.center.x is not a finite number")"))
      << run.lines[4];
  EXPECT_TRUE(contains(run.lines[5], R"("error":"line 6: unknown command 'fly'")")) << run.lines[5];
  // Later lines still run.
  EXPECT_TRUE(contains(run.lines[6], R"({"line":7,"command":"step","ok":true,"tick":5)"))
      << run.lines[6];
}

TEST(Cli, ReadsStdin) {
  ServerProcess server({"--paused"});
  const auto run = runCli(server.port(), "circle 4 4 0.25\nstep 2\n", true);
  EXPECT_EQ(run.exitCode, 0);
  ASSERT_EQ(run.lines.size(), 3u);
  EXPECT_TRUE(contains(run.lines[2], R"("tick":2)")) << run.lines[2];
}

TEST(Cli, UnreachableServerExitsWithTwo) {
  std::uint16_t port = 0;
  {
    ServerProcess server;
    port = server.port();
  }
  const auto run = runCli(port, "ping\n");
  EXPECT_EQ(run.exitCode, 2);
  ASSERT_EQ(run.lines.size(), 1u);
  EXPECT_TRUE(contains(run.lines[0], R"("ok":false,"error":"line 0: connection: cannot connect)"))
      << run.lines[0];
}

}  // namespace
}  // namespace impulse::net_test
