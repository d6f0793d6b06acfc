// impulse-cli against the real server: one JSON line per command, errors
// that name the line, and exit codes.
#include <sys/wait.h>

#include <cctype>
#include <cstdio>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A '.' followed by ten or more digits: a number printed with its double
// widening's digits. Scanned by hand: std::regex trips GCC 12's
// -Wmaybe-uninitialized in sanitizer builds.
bool hasLongFraction(const std::string& line) {
  for (std::size_t dot = line.find('.'); dot != std::string::npos; dot = line.find('.', dot + 1)) {
    std::size_t digits = 0;
    while (dot + 1 + digits < line.size() &&
           std::isdigit(static_cast<unsigned char>(line[dot + 1 + digits]))) {
      ++digits;
    }
    if (digits >= 10) return true;
  }
  return false;
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
  // Numbers as people write them: integral values without ".0", single
  // precision state without the digits of its double widening.
  EXPECT_TRUE(contains(run.lines[0], R"("tick_hz":60,"snapshot_hz":30)")) << run.lines[0];
  for (const auto& line : run.lines) EXPECT_FALSE(hasLongFraction(line)) << line;
}

TEST(Cli, JointWordsMakeEveryKind_AndQueryJointDescribesOne) {
  ServerProcess server({"--paused"});
  const std::string script =
      "circle 12.5 16 0.3 static\n"
      "circle 12.5 10 0.5\n"
      "circle 9 10 0.4\n"
      "distance 4 5 12.5 16 12.5 10 5 2000 0\n"
      "rope 5 6 12.5 10 9 10\n"
      "revolute 6 0 6 14 limit -1 1 motor 2 50\n"
      "prismatic 5 6 11 10 1 0 limit -1 1 spring 100 5 collide\n"
      "weld 5 6 11 10 1000 50\n"
      "wheel 5 6 9 10 0 1 spring 500 20 motor -3 40\n"
      "mouse 6 9 10 500 100 10\n"
      "target 7 10 11\n"
      "motor 3 1.5 60\n"
      "step 10\n"
      "query-joint 1\n"
      "remove-joint 2\n"
      "remove 5\n"
      "query-joint 1\n"
      "revolute 6 0 6 14 limit 1\n";
  const auto run = runCli(server.port(), script);
  ASSERT_EQ(run.lines.size(), 19u);
  for (std::size_t i = 1; i <= 16; ++i) {
    EXPECT_TRUE(contains(run.lines[i], R"("ok":true)")) << run.lines[i];
  }
  for (std::size_t i = 4; i <= 10; ++i) {
    EXPECT_TRUE(contains(run.lines[i], R"("joint_id":)" + std::to_string(i - 3))) << run.lines[i];
  }
  EXPECT_TRUE(contains(run.lines[14], R"("joint":{"id":1,"body_a":4,"body_b":5,"kind":"distance")"))
      << run.lines[14];
  // The body took its joints with it; a bad line names its problem.
  EXPECT_TRUE(contains(run.lines[17], "query-joint: unknown joint id 1")) << run.lines[17];
  EXPECT_TRUE(contains(run.lines[18], R"("ok":false)")) << run.lines[18];
  EXPECT_EQ(run.exitCode, 1);
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
  // A line that does not parse is reported under the command it names.
  EXPECT_TRUE(contains(
      run.lines[1],
      R"({"line":1,"command":"circle","ok":false,"error":"line 1: circle X Y R [MATERIAL] )"
      R"([static] [nograv] [NAME=VALUE...]: missing argument 3")"))
      << run.lines[1];
  // The server's refusals name the fields as the script writes them.
  EXPECT_TRUE(contains(
      run.lines[2],
      R"({"line":3,"command":"polygon","ok":false,"error":"line 3: polygon: 2 vertices given)"))
      << run.lines[2];
  EXPECT_TRUE(contains(run.lines[3], R"("error":"line 4: query: unknown body id 999")"))
      << run.lines[3];
  EXPECT_TRUE(contains(run.lines[4], R"("error":"line 5: circle X is not a finite number")"))
      << run.lines[4];
  EXPECT_TRUE(contains(run.lines[5], R"({"line":6,"command":"fly","ok":false,"error":"line 6: unknown command 'fly'")"))
      << run.lines[5];
  // Later lines still run.
  EXPECT_TRUE(contains(run.lines[6], R"({"line":7,"command":"step","ok":true,"tick":5)"))
      << run.lines[6];
}

TEST(Cli, ServerErrorsUseTheScriptsWordsAndPlainNumbers) {
  ServerProcess server({"--paused"});
  const auto run = runCli(server.port(), "polygon 1 1 2 nan 3 1\ncircle 100 5 1\n");
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.lines.size(), 3u);
  EXPECT_TRUE(contains(run.lines[1], R"("error":"line 1: polygon Y2 is not a finite number")"))
      << run.lines[1];
  // The server writes the bounds with six decimals; the report as people do.
  EXPECT_TRUE(contains(run.lines[2], "(-25, -25) to (50, 45)")) << run.lines[2];
  EXPECT_FALSE(contains(run.lines[2], ".000000")) << run.lines[2];
}

TEST(Cli, ReadsStdin) {
  ServerProcess server({"--paused"});
  const auto run = runCli(server.port(), "circle 4 4 0.25\nstep 2\n", true);
  EXPECT_EQ(run.exitCode, 0);
  ASSERT_EQ(run.lines.size(), 3u);
  EXPECT_TRUE(contains(run.lines[2], R"("tick":2)")) << run.lines[2];
}

TEST(Cli, HelpListsTheFlagsInAlignedColumnsAndTheScriptGrammar) {
  FILE* pipe = popen((std::string(IMPULSE_CLI_BINARY) + " --help").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string help;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) help += buffer;
  EXPECT_EQ(pclose(pipe), 0);
  std::size_t column = std::string::npos;
  for (const std::string flag : {"  --connect HOST:PORT", "  --timeout MS", "  -h,--help"}) {
    const auto at = help.find(flag);
    ASSERT_NE(at, std::string::npos) << flag << " in\n" << help;
    const auto lineStart = help.rfind('\n', at) + 1;
    const auto description = help.find_first_not_of(' ', at + flag.size()) - lineStart;
    if (column == std::string::npos) column = description;
    EXPECT_EQ(description, column) << flag;
  }
  EXPECT_TRUE(contains(help, "polygon X1 Y1 X2 Y2 X3 Y3")) << help;
}

TEST(Cli, BadFlagValuesNameTheFlag) {
  const std::string command = std::string(IMPULSE_CLI_BINARY) + " --timeout -5 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  EXPECT_EQ(WEXITSTATUS(pclose(pipe)), 2);
  EXPECT_TRUE(contains(output, "--timeout")) << output;
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
