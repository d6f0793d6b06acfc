// The impulse-cli grammar: each command's message, and errors that say what
// was expected and what was wrong.
#include "script.h"

#include <gtest/gtest.h>

#include "variables.h"

#include <cmath>

namespace impulse::cli {
namespace {

ScriptCommand parseOk(std::string_view line) {
  auto parsed = parseScriptLine(line);
  EXPECT_TRUE(parsed.error.empty()) << line << ": " << parsed.error;
  EXPECT_TRUE(parsed.command.has_value()) << line;
  return parsed.command.value_or(ScriptCommand{});
}

std::string parseError(std::string_view line) {
  const auto parsed = parseScriptLine(line);
  EXPECT_FALSE(parsed.command.has_value()) << line;
  return parsed.error;
}

TEST(CliScript, BlankAndCommentLinesAreSkipped) {
  for (const char* line : {"", "   ", "# a comment", "\t# indented comment", "\r"}) {
    const auto parsed = parseScriptLine(line);
    EXPECT_FALSE(parsed.command.has_value()) << line;
    EXPECT_TRUE(parsed.error.empty()) << line;
  }
}

TEST(CliScript, CircleWithFlagsInAnyOrder) {
  const auto command = parseOk("circle 1.5 -2 0.25 nograv RUBBER static  # trailing comment");
  const auto& spawn = command.message.spawn_circle();
  EXPECT_EQ(spawn.center().x(), 1.5);
  EXPECT_EQ(spawn.center().y(), -2);
  EXPECT_EQ(spawn.radius(), 0.25);
  EXPECT_EQ(spawn.options().material(), v1::RUBBER);
  EXPECT_TRUE(spawn.options().is_static());
  EXPECT_TRUE(spawn.options().ignore_gravity());
}

TEST(CliScript, PolygonTakesPairsThenFlags) {
  const auto command = parseOk("polygon 0 0 1 0 1 1 0 1 ice");
  const auto& spawn = command.message.spawn_polygon();
  ASSERT_EQ(spawn.vertices_size(), 4);
  EXPECT_EQ(spawn.vertices(2).x(), 1);
  EXPECT_EQ(spawn.vertices(2).y(), 1);
  EXPECT_EQ(spawn.options().material(), v1::ICE);
}

TEST(CliScript, EveryCommandBuildsItsMessage) {
  EXPECT_EQ(parseOk("preset 9 metal").message.load_preset().preset(), 9);
  EXPECT_EQ(parseOk("preset 9 metal").message.load_preset().material(), v1::METAL);
  EXPECT_TRUE(parseOk("pause").message.set_paused().paused());
  EXPECT_FALSE(parseOk("resume").message.set_paused().paused());
  EXPECT_EQ(parseOk("step 120").message.step().ticks(), 120u);
  EXPECT_EQ(parseOk("gravity 0 -3.5").message.set_gravity().gravity().y(), -3.5);
  EXPECT_EQ(parseOk("nudge 1 0").message.nudge_gravity().delta().x(), 1);
  EXPECT_TRUE(parseOk("reset-gravity").message.has_reset_gravity());
  EXPECT_TRUE(parseOk("clear").message.has_clear());
  EXPECT_EQ(parseOk("remove 7").message.remove_body().body_id(), 7u);
  EXPECT_EQ(parseOk("query 8").message.query_body().body_id(), 8u);
  const auto impulse = parseOk("impulse 3 1 2 4 5").message.apply_impulse();
  EXPECT_EQ(impulse.body_id(), 3u);
  EXPECT_EQ(impulse.point().y(), 5);
  EXPECT_FALSE(parseOk("impulse 3 1 2").message.apply_impulse().has_point());
  EXPECT_EQ(parseOk("bodies").kind, ScriptCommand::Kind::Bodies);
  EXPECT_EQ(parseOk("wait-snapshot").kind, ScriptCommand::Kind::WaitSnapshot);
  EXPECT_TRUE(parseOk("ping").message.has_ping());
}

TEST(CliScript, PropertiesAndNewMaterialsReachTheOptions) {
  const auto command = parseOk(
      "circle 5 8 0.5 stone density=300 friction=0.25 restitution=0.5 damping=1.5 "
      "angular-damping=0.75 gravity-scale=-2");
  const auto& options = command.message.spawn_circle().options();
  EXPECT_EQ(options.material(), v1::STONE);
  EXPECT_EQ(options.density(), 300);
  EXPECT_EQ(options.friction(), 0.25);
  EXPECT_EQ(options.restitution(), 0.5);
  EXPECT_EQ(options.linear_damping(), 1.5);
  EXPECT_EQ(options.angular_damping(), 0.75);
  EXPECT_EQ(options.gravity_scale(), -2);
  const auto polygon = parseOk("polygon 0 0 1 0 1 1 foam");
  const auto& plain = polygon.message.spawn_polygon().options();
  EXPECT_EQ(plain.material(), v1::FOAM);
  EXPECT_FALSE(plain.has_density()) << "unset: the material's";
  EXPECT_FALSE(plain.has_gravity_scale());
  EXPECT_EQ(parseOk("circle 1 1 1 GLASS").message.spawn_circle().options().material(), v1::GLASS);
  EXPECT_EQ(parseOk("time-scale 0.25").message.set_time_scale().scale(), 0.25);
}

TEST(CliScript, NonFiniteNumbersAreSentForTheServerToRefuse) {
  EXPECT_TRUE(std::isnan(parseOk("circle nan 1 1").message.spawn_circle().center().x()));
  EXPECT_TRUE(std::isinf(parseOk("gravity inf 0").message.set_gravity().gravity().x()));
}

TEST(CliScript, BodyEditWordsBuildTheirMessages) {
  const auto teleport = parseOk("teleport 4 1.5 -2 0.25").message.set_transform();
  EXPECT_EQ(teleport.body_id(), 4u);
  EXPECT_EQ(teleport.position().x(), 1.5);
  EXPECT_EQ(teleport.angle(), 0.25);
  EXPECT_EQ(parseOk("teleport 4 1 2").message.set_transform().angle(), 0);
  EXPECT_EQ(parseOk("material 5 glass").message.set_material().material(), v1::GLASS);
  EXPECT_EQ(parseOk("body-type 6 kinematic").message.set_body_type().type(), v1::BODY_TYPE_KINEMATIC);
  EXPECT_EQ(parseOk("body-type 6 static").message.set_body_type().type(), v1::BODY_TYPE_STATIC);
  EXPECT_EQ(parseOk("body-type 6 dynamic").message.set_body_type().type(), v1::BODY_TYPE_DYNAMIC);
  const auto asleep = parseOk("circle 1 2 0.5 asleep").message.spawn_circle().options();
  EXPECT_TRUE(asleep.has_is_awake());
  EXPECT_FALSE(asleep.is_awake());
  EXPECT_FALSE(parseOk("circle 1 2 0.5").message.spawn_circle().options().has_is_awake()) << "unset: awake";

  EXPECT_EQ(parseError("material 5 plastic"), "material ID MATERIAL: 'plastic' is not a material");
  EXPECT_EQ(parseError("material 5"), "material ID MATERIAL: MATERIAL is missing");
  EXPECT_EQ(parseError("body-type 6 floating"),
            "body-type ID static|kinematic|dynamic: 'floating' is not a body type (static, kinematic or dynamic)");
  EXPECT_EQ(parseError("teleport 4 1"), "teleport ID X Y [ANGLE]: missing argument 3");
}

TEST(CliScript, ErrorsNameTheUsageAndTheProblem) {
  const std::string circle = "circle X Y R [MATERIAL] [static] [asleep] [nograv] [NAME=VALUE...]: ";
  EXPECT_EQ(parseError("circle 1 2"), circle + "missing argument 3");
  EXPECT_EQ(parseError("circle 1 x 3"), circle + "'x' is not a number");
  EXPECT_EQ(parseError("circle 1 2 3 plastic"),
            circle + "unexpected 'plastic' (material, static, kinematic, asleep, nograv, sensor, "
                     "contact-events, hit-events or no-sensor-events)");
  EXPECT_EQ(parseError("circle 1 2 3 colour=4"),
            circle + "unexpected 'colour=4' (density=, friction=, restitution=, damping=, "
                     "angular-damping=, gravity-scale=, category=, mask= or group=)");
  EXPECT_EQ(parseError("circle 1 2 3 density=heavy"),
            circle + "'density=heavy' has no number after '='");
  EXPECT_EQ(parseError("time-scale"), "time-scale S: missing argument 1");
  EXPECT_EQ(parseError("step"), "step N (1 or more ticks): missing argument 1");
  EXPECT_EQ(parseError("step 0"), "step N (1 or more ticks): tick count out of range");
  EXPECT_EQ(parseError("polygon 1 2 3"),
            "polygon X1 Y1 X2 Y2 X3 Y3 ... [MATERIAL] [static] [asleep] [nograv] [NAME=VALUE...]: vertex 2 "
            "has no y");
  EXPECT_EQ(parseError("query -1"), "query ID: body id -1 out of range");
  EXPECT_EQ(parseError("pause now"), "pause: unexpected 'now'");
  EXPECT_EQ(parseError("jump 3"), "unknown command 'jump'");
}

TEST(CliScript, LoadNamesItsFileAndReadsNothingYet) {
  // The file is read when the line runs (after an earlier save wrote it),
  // so a file that does not exist yet parses.
  const auto command = parseOk("load not-written-yet.json");
  EXPECT_EQ(command.file, "not-written-yet.json");
  EXPECT_TRUE(command.message.load_scene().data().empty());
  EXPECT_EQ(parseError("load"), "load FILE: FILE is missing");
}

TEST(CliVariables, AssignmentsSplitOffTheirName) {
  const auto assignment = splitAssignment("  $ball_2 =circle 1 2 3");
  ASSERT_TRUE(assignment.has_value());
  EXPECT_EQ(assignment->variable, "ball_2");
  EXPECT_EQ(assignment->command, "circle 1 2 3");
  EXPECT_FALSE(splitAssignment("circle $x 1 1").has_value());
  EXPECT_FALSE(splitAssignment("$ = circle 1 1 1").has_value());
  EXPECT_FALSE(splitAssignment("$x circle").has_value());
}

TEST(CliVariables, ValuesReplaceEveryReferenceBeforeTheComment) {
  Variables variables;
  variables.set("x", "2.5");
  variables.set("ball", "7");
  const auto done = variables.substitute("impulse $ball $x 0 density=$x  # not $here");
  EXPECT_TRUE(done.error.empty()) << done.error;
  EXPECT_EQ(done.text, "impulse 7 2.5 0 density=2.5  # not $here");
}

TEST(CliVariables, WaitingFailedAndUnknownVariablesAreTold) {
  Variables variables;
  variables.await("ball", 3);
  EXPECT_TRUE(variables.substitute("query $ball").waiting);
  variables.fail("ball", 3);
  EXPECT_EQ(variables.substitute("query $ball").error,
            "$ball has no value: line 3, which sets it, failed");
  EXPECT_EQ(variables.substitute("query $box").error,
            "$box has no value (set it with $box = COMMAND or $box = NUMBER)");
  EXPECT_EQ(variables.substitute("query $ 1").error, "'$' without a variable name after it");
}

TEST(CliScript, RepeatLinesOpenBlocksAndBracesCloseThem) {
  EXPECT_EQ(lineShape("repeat 3 {"), LineShape::OpensBlock);
  EXPECT_EQ(lineShape("  repeat $n $i {  # comment"), LineShape::OpensBlock);
  EXPECT_EQ(lineShape(" } "), LineShape::ClosesBlock);
  EXPECT_EQ(lineShape("repeat 3"), LineShape::Plain);
  const auto words = parseRepeat("repeat $n $i {");
  EXPECT_TRUE(words.error.empty()) << words.error;
  EXPECT_EQ(words.count, "$n");
  EXPECT_EQ(words.counter, "i");
  EXPECT_EQ(parseRepeat("repeat 3 i {").error,
            "repeat N [$I] {: 'i' is not a $name to count the passes in");
  std::string error;
  EXPECT_EQ(repeatCount("12", error), 12);
  EXPECT_FALSE(repeatCount("-1", error).has_value());
  EXPECT_EQ(error, "repeat N [$I] {: N must be a whole number, 0 or more, not '-1'");
}

}  // namespace
}  // namespace impulse::cli
