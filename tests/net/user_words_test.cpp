// Refusals in the user's words (impulse/server/user_words.h): the CLI's
// word for each command and its usage's names for the arguments, never a
// protocol field path.
#include <gtest/gtest.h>

#include <vector>

#include "impulse/client/commands.h"
#include "impulse/server/user_words.h"

namespace impulse::server {
namespace {

TEST(UserWords, EachCommandIsNamedByItsCliWord) {
  EXPECT_EQ(commandWord(client::spawnCircle({1, 2}, 0.5, {})), "circle");
  EXPECT_EQ(commandWord(client::setPaused(true)), "pause");
  EXPECT_EQ(commandWord(client::setPaused(false)), "resume");
  EXPECT_EQ(commandWord(client::setTimeScale(2)), "time-scale");
  EXPECT_EQ(commandWord(client::setJointTarget(1, {0, 0})), "target");
  EXPECT_EQ(commandWord(client::setJointMotor(1, 2)), "motor");
  EXPECT_EQ(commandWord(client::ropeJoint({1, 2, {0, 0}, {1, 0}, false}, {})), "rope");
  EXPECT_EQ(commandWord(client::gravitationField(1)), "gravitation");
}

TEST(UserWords, FieldPathsBecomeTheUsagesNames_NumbersArePlain) {
  const auto circle = client::spawnCircle({1, 2}, 0.5, {});
  EXPECT_EQ(inUserWords(circle, "spawn_circle.center.x is not a finite number"),
            "circle X is not a finite number");
  EXPECT_EQ(inUserWords(circle, "spawn_circle: position (-25.000000, 3.500000) is outside"),
            "circle: position (-25, 3.5) is outside");
  const std::vector<client::Point> triangle{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(inUserWords(circle, "spawn_circle.options.velocity.x is not a finite number"),
            "circle velocity x is not a finite number");
  const auto polygon = client::spawnPolygon(triangle);
  EXPECT_EQ(inUserWords(polygon, "spawn_polygon.vertices[2].y is not a finite number"),
            "polygon Y3 is not a finite number");
  const auto distance = client::distanceJoint({1, 2, {0, 0}, {1, 0}, false}, {});
  EXPECT_EQ(inUserWords(distance, "create_joint.distance.stiffness is not a finite number"),
            "distance stiffness is not a finite number");
  EXPECT_EQ(inUserWords(distance, "create_joint: bodyA must be a body; only bodyB may be the world (null)"),
            "distance: A must be a body; only B may be the world (0)");
  EXPECT_EQ(inUserWords(client::setTimeScale(100), "set_time_scale: time scale 100 is outside"),
            "time-scale: time scale 100 is outside");
  EXPECT_EQ(inUserWords(client::fanField({}), "add_field.fan.max_speed is not a finite number."),
            "fan max speed is not a finite number.");
  EXPECT_EQ(inUserWords(client::setPaused(true), "set_paused: refused for the player role"),
            "pause: refused for the player role");
}

TEST(UserWords, AMessageNoWordMakesKeepsItsWireName) {
  auto noKind = client::ropeJoint({1, 2, {0, 0}, {1, 0}, false}, {});
  noKind.mutable_create_joint()->clear_kind();
  EXPECT_EQ(commandWord(noKind), "create_joint");
  EXPECT_EQ(inUserWords(noKind, "create_joint.kind: none of distance, rope"),
            "create_joint kind: none of distance, rope");
}

}  // namespace
}  // namespace impulse::server
