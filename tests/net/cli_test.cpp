// impulse-cli against the real server: one JSON line per command, errors
// that name the line, and exit codes.
#include <sys/wait.h>

#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "impulse/wire/scene_text.h"
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

// A fresh directory for a test's files, removed with it.
class ScratchDirectory {
 public:
  ScratchDirectory()
      : path_(std::filesystem::temp_directory_path() /
              ("impulse-cli-test-" + std::to_string(getpid()) + "-" +
               std::to_string(counter_++))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  static inline int counter_ = 0;
  std::filesystem::path path_;
};

std::string readFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The text of member `name` in a one-line JSON report ("[4,10]" for an
// array, "4" for a number), empty when absent.
std::string member(const std::string& line, const std::string& name) {
  const auto at = line.find("\"" + name + "\":");
  if (at == std::string::npos) return {};
  const auto begin = at + name.size() + 3;
  const auto end = line[begin] == '[' ? line.find(']', begin) + 1 : line.find_first_of(",}", begin);
  return line.substr(begin, end - begin);
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
      R"([static] [asleep] [nograv] [NAME=VALUE...]: missing argument 3")"))
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

TEST(Cli, AFarRoomsLinesGiveItsOrigin_AndItsRefusalsTheClientsCoordinates) {
  ServerProcess server({"--paused"});
  // Centred on 80 037.5 m: the room computes around (80 000, 0).
  const auto run = runCli(server.port(), "circle 80200 5 0.5\nrooms\n", false,
                          "--room far --room-bounds 79987.5 -10 80087.5 90 --");
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.lines.size(), 3u);
  EXPECT_TRUE(
      contains(run.lines[0],
               R"("world_min":[79987.5,-10],"world_max":[80087.5,90],"world_origin":[80000,0])"))
      << run.lines[0];
  EXPECT_TRUE(contains(
      run.lines[1], "circle: position is outside the world bounds (79987.5, -10) to (80087.5, 90)"))
      << run.lines[1];
  EXPECT_TRUE(contains(run.lines[2], R"("name":"far","clients":1,"bodies":)")) << run.lines[2];
  EXPECT_TRUE(
      contains(run.lines[2],
               R"("world_min":[79987.5,-10],"world_max":[80087.5,90],"world_origin":[80000,0]})"))
      << run.lines[2];
}

TEST(Cli, NetworkedPlayWordsSetTheAreaAndBudget_AndRefusalsNameTheArgument) {
  ServerProcess server({"--paused"});
  const auto run = runCli(server.port(), "area 0 0 10 10\nbudget 32000\narea all\nbudget off\n"
                                         "area 5 5 1 1\nbudget 0\n");
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.lines.size(), 7u);
  for (int line = 1; line <= 4; ++line) EXPECT_TRUE(contains(run.lines[line], R"("ok":true)")) << run.lines[line];
  EXPECT_TRUE(contains(run.lines[5], "area X2 Y2 must exceed area X1 Y1")) << run.lines[5];
  EXPECT_TRUE(contains(run.lines[6], "budget BYTES_PER_SECOND 0 must be in [1000, 125000000]")) << run.lines[6];
}

TEST(Cli, BodyEditWordsEditAndTheirErrorsUseTheScriptsWords) {
  ServerProcess server({"--paused"});
  const auto run = runCli(server.port(), "$ball = circle 5 5 0.5\nteleport $ball 1000 5\nmaterial $ball metal\n"
                                         "body-type $ball static\n");
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.lines.size(), 5u);
  EXPECT_TRUE(contains(run.lines[2], "line 2: teleport: position is outside the world bounds (-25, -25) to (50, 45)"))
      << run.lines[2];
  EXPECT_TRUE(contains(run.lines[3], R"("ok":true)")) << run.lines[3];
  EXPECT_TRUE(contains(run.lines[4], R"("ok":true)")) << run.lines[4];
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

TEST(Cli, HelpListsEveryMaterialTheLimitsAndTheLanguage) {
  FILE* pipe = popen((std::string(IMPULSE_CLI_BINARY) + " --help").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string help;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) help += buffer;
  EXPECT_EQ(pclose(pipe), 0);
  for (const char* material : {"solid (500", "ice (100", "wood (700", "metal (2000",
                               "rubber (200", "stone (", "glass (", "foam ("}) {
    EXPECT_TRUE(contains(help, material)) << material << " in\n" << help;
  }
  EXPECT_TRUE(contains(help, "polygons 3-16 vertices, radius 0.02-20 m")) << help;
  EXPECT_TRUE(contains(help, "max_step_ticks")) << help;
  EXPECT_TRUE(contains(help, "repeat N [$I] { ... }")) << help;
  EXPECT_TRUE(contains(help, "$NAME = COMMAND")) << help;
}

TEST(Cli, SaveThenLoadOfTheSameFileInOneScriptLoadsWhatWasSaved) {
  ServerProcess server({"--paused"});
  const ScratchDirectory directory;
  for (const std::string name : {"world.scene", "level.json"}) {
    SCOPED_TRACE(name);
    const std::string file = directory.file(name);
    // The file does not exist before the script: the load must wait for
    // the save's reply, which writes it.
    const std::string script = "clear\n"
                               "$ball = circle 5 10 0.5\n"
                               "save " + file + "\n"
                               "step 60\n"
                               "load " + file + "\n"
                               "query $ball\n";
    const auto run = runCli(server.port(), script);
    EXPECT_EQ(run.exitCode, 0);
    ASSERT_EQ(run.lines.size(), 7u);
    EXPECT_TRUE(contains(run.lines[3], R"("command":"save","ok":true)")) << run.lines[3];
    EXPECT_TRUE(contains(run.lines[5], R"({"line":5,"command":"load","ok":true)")) << run.lines[5];
    // Back where it was saved, at rest: not where a second of falling took it.
    EXPECT_EQ(member(run.lines[6], "position"), "[5,10]") << run.lines[6];
    EXPECT_EQ(member(run.lines[6], "velocity"), "[0,0]") << run.lines[6];
  }
}

TEST(Cli, VariablesKeepIdsAndNumbers_RepeatRunsABlockWithItsCounter) {
  ServerProcess server({"--paused"});
  const std::string script =
      "$x = 4               # a number\n"
      "repeat 4 $i {\n"
      "  $ball = circle $x 10 0.4 rubber\n"
      "  impulse $ball 0 $i\n"
      "  $x = $x + 2.5\n"
      "}\n"
      "$hook = circle 12.5 16 0.3 static\n"
      "$rod = distance $hook $ball 12.5 16 11.5 10\n"
      "query-joint $rod\n"
      "query $ball\n";
  const auto run = runCli(server.port(), script);
  EXPECT_EQ(run.exitCode, 0);
  ASSERT_EQ(run.lines.size(), 13u);
  // Four passes of two lines each, under their own line numbers; the
  // sandbox holds bodies 1-3, so the balls are 4-7.
  for (int pass = 0; pass < 4; ++pass) {
    const std::string& circle = run.lines[1 + 2 * pass];
    EXPECT_TRUE(contains(circle, R"({"line":3,"command":"circle","ok":true,"body_id":)" +
                                     std::to_string(4 + pass)))
        << circle;
    EXPECT_TRUE(contains(run.lines[2 + 2 * pass], R"({"line":4,"command":"impulse","ok":true)"));
  }
  EXPECT_TRUE(contains(run.lines[9], R"("body_id":8)")) << run.lines[9];
  EXPECT_TRUE(contains(run.lines[10], R"("joint_id":1)")) << run.lines[10];
  EXPECT_TRUE(contains(run.lines[11], R"("joint":{"id":1,"body_a":8,"body_b":7)"))
      << run.lines[11];
  // The last ball: x = 4 + 3 * 2.5, pushed up by 4 N*s in the last pass.
  EXPECT_TRUE(contains(run.lines[12], R"("id":7,"shape":"circle")")) << run.lines[12];
  EXPECT_EQ(member(run.lines[12], "position"), "[11.5,10]") << run.lines[12];
  EXPECT_NE(member(run.lines[12], "velocity"), "[0,0]") << run.lines[12];
}

TEST(Cli, VariablesWithoutAValueAndUnbalancedBlocksAreLineErrors) {
  ServerProcess server({"--paused"});
  const std::string script =
      "circle $nowhere 5 1\n"
      "$bad = circle 5 5\n"
      "query $bad\n"
      "$tick = step 1\n"
      "}\n"
      "repeat many {\n"
      "}\n"
      "repeat 2 {\n"
      "ping\n";
  const auto run = runCli(server.port(), script);
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.lines.size(), 8u);
  EXPECT_TRUE(contains(run.lines[1], R"({"line":1,"command":"circle","ok":false,"error":"line 1: )"
                                     R"($nowhere has no value)"))
      << run.lines[1];
  EXPECT_TRUE(contains(run.lines[2], "line 2: circle X Y R")) << run.lines[2];
  EXPECT_TRUE(contains(run.lines[3], "line 3: $bad has no value: line 2, which sets it, failed"))
      << run.lines[3];
  EXPECT_TRUE(contains(run.lines[4], "line 4: $tick = step: its reply has no id")) << run.lines[4];
  EXPECT_TRUE(contains(run.lines[5], R"({"line":5,"command":"}","ok":false)")) << run.lines[5];
  EXPECT_TRUE(contains(run.lines[6], "line 6: repeat N [$I] {: N must be a whole number"))
      << run.lines[6];
  // The unclosed block never runs: its ping has no line.
  EXPECT_TRUE(contains(run.lines[7], "line 8: no } closes this repeat")) << run.lines[7];
}

TEST(Cli, StepOfAnyLengthGoesInTheServersPiecesAndIsOneLine) {
  ServerProcess server({"--paused"});
  const auto run = runCli(server.port(), "step 1500\nstep 7\n");
  EXPECT_EQ(run.exitCode, 0);
  ASSERT_EQ(run.lines.size(), 3u);
  EXPECT_TRUE(contains(run.lines[0], R"("tick":0)")) << run.lines[0];
  EXPECT_TRUE(contains(run.lines[1], R"({"line":1,"command":"step","ok":true,"tick":1500,)"))
      << run.lines[1];
  EXPECT_TRUE(contains(run.lines[2], R"("tick":1507)")) << run.lines[2];
}

// Level files are the binary scene in protobuf's JSON mapping: each form
// converts to the other bit-exactly, for scenes with joints, contacts,
// fields and sleeping bodies.
TEST(Cli, LevelFilesRoundTripBitExactlyThroughTheBinaryForm) {
  ServerProcess server({"--paused"});
  const ScratchDirectory directory;
  for (const int preset : {1, 8, 13, 14, 16}) {
    SCOPED_TRACE(preset);
    const std::string binary = directory.file("scene.bin");
    const std::string text = directory.file("scene.json");
    const auto run = runCli(server.port(), "preset " + std::to_string(preset) +
                                               "\nstep 90\nsave " + binary + "\nsave " + text +
                                               "\n");
    ASSERT_EQ(run.exitCode, 0) << run.lines.back();
    const std::string bytes = readFile(binary);
    const std::string json = readFile(text);
    ASSERT_GT(bytes.size(), 100u);
    EXPECT_TRUE(contains(json, "\"bodies\": [")) << json.substr(0, 200);
    std::string error;
    EXPECT_EQ(wire::sceneFromJson(json, error), bytes) << error;
    EXPECT_EQ(wire::sceneToJson(bytes, error), json) << error;
  }
}

TEST(Cli, AHandEditedLevelFileLoads_AndABadOneIsRefusedWithItsReason) {
  ServerProcess server({"--paused"});
  const ScratchDirectory directory;
  const std::string level = directory.file("level.json");
  ASSERT_EQ(runCli(server.port(), "clear\ncircle 5 10 0.5 rubber\nsave " + level + "\n").exitCode,
            0);
  std::string json = readFile(level);
  // A designer moves the ball and makes it larger (its mass follows from
  // the radius and its density when the scene loads).
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"\"x\": 5", "\"x\": 7.5"},
        {"\"radius\": 0.5", "\"radius\": 0.8"}}) {
    const auto at = json.find(from);
    ASSERT_NE(at, std::string::npos) << from << " in\n" << json;
    json.replace(at, from.size(), to);
  }
  std::ofstream(level) << json;
  const auto run = runCli(server.port(), "load " + level + "\nquery 1\n");
  EXPECT_EQ(run.exitCode, 0) << run.lines.back();
  ASSERT_EQ(run.lines.size(), 3u);
  EXPECT_EQ(member(run.lines[2], "position"), "[7.5,10]") << run.lines[2];
  EXPECT_EQ(member(run.lines[2], "radius"), "0.8") << run.lines[2];
  // 200 kg/m2 (rubber) * pi * 0.8^2
  EXPECT_NEAR(std::stod(member(run.lines[2], "mass")), 402.124, 0.01) << run.lines[2];

  std::ofstream(level) << "{\"bodies\": [{\"radius\": 2}]}";
  const auto bad = runCli(server.port(), "load " + level + "\n");
  EXPECT_EQ(bad.exitCode, 1);
  ASSERT_EQ(bad.lines.size(), 2u);
  EXPECT_TRUE(contains(bad.lines[1], "line 1: load FILE: not a scene in JSON:")) << bad.lines[1];
  EXPECT_TRUE(contains(bad.lines[1], "radius")) << bad.lines[1];
}

TEST(Cli, VelocitySetsABodysVelocity_AndRefusalsSayWhy) {
  ServerProcess server({"--paused"});
  const std::string script =
      "$ball = circle 5 10 0.5\n"
      "velocity $ball 3 -1 2\n"
      "query $ball\n"
      "velocity $ball nan 0\n"
      "velocity 1 1 1\n";
  const auto run = runCli(server.port(), script);
  EXPECT_EQ(run.exitCode, 1);
  ASSERT_EQ(run.lines.size(), 6u);
  EXPECT_TRUE(contains(run.lines[2], R"({"line":2,"command":"velocity","ok":true)")) << run.lines[2];
  EXPECT_EQ(member(run.lines[3], "velocity"), "[3,-1]") << run.lines[3];
  EXPECT_EQ(member(run.lines[3], "angular_velocity"), "2") << run.lines[3];
  EXPECT_TRUE(contains(run.lines[4], "line 4: velocity VX is not a finite number")) << run.lines[4];
  // Body 1 is the sandbox's floor: static bodies do not move.
  EXPECT_TRUE(contains(run.lines[5], R"("line":5,"command":"velocity","ok":false,"error":"line 5: velocity: )"))
      << run.lines[5];
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
