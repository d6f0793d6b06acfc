#include "controls.h"

#include <gtest/gtest.h>

#include "impulse/constants.h"

namespace impulse::viewer {
namespace {

const ControlContext kSandbox{};

ControlKey key(Control control, int index = 0) { return {control, index}; }

class ControlsTest : public ::testing::Test {
 protected:
  void press(Control control, const ControlContext& context = kSandbox, int index = 0) {
    controls.keyPressed(key(control, index), context, now);
  }
  void click(float x, float y) {
    controls.pointerMoved(Vec2(x, y));
    controls.pointerPressed(Vec2(x, y), std::nullopt, now);
    controls.pointerReleased(Vec2(x, y));
  }
  std::vector<Outgoing> sent() { return controls.takeCommands(); }

  Controls controls;
  double now = 0;
};

TEST_F(ControlsTest, StartsWithPanelOn_AndPresetKeyLoadsAndHidesIt) {
  EXPECT_TRUE(controls.panelVisible());
  press(Control::SelectMaterial, kSandbox, 2);  // WOOD, used by preset 9
  press(Control::LoadPreset, kSandbox, 9);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  ASSERT_TRUE(commands[0].message.has_load_preset());
  EXPECT_EQ(commands[0].message.load_preset().preset(), 9);
  EXPECT_EQ(commands[0].message.load_preset().material(), v1::WOOD);
  EXPECT_FALSE(controls.panelVisible());
  press(Control::TogglePanel);
  EXPECT_TRUE(controls.panelVisible());
}

TEST_F(ControlsTest, Polygon_ClickedPointsAreSentOnSecondP) {
  press(Control::PolygonMode);
  EXPECT_EQ(controls.mode(), DrawMode::Polygon);
  click(5, 5);
  click(7, 5);
  click(6, 7);
  press(Control::PolygonMode);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  const auto& polygon = commands[0].message.spawn_polygon();
  ASSERT_EQ(polygon.vertices_size(), 3);
  EXPECT_DOUBLE_EQ(polygon.vertices(1).x(), 7);
  EXPECT_EQ(controls.mode(), DrawMode::None);
  EXPECT_TRUE(controls.placedPoints().empty());
}

TEST_F(ControlsTest, Polygon_FewerThanThreePointsCancels) {
  press(Control::PolygonMode);
  click(5, 5);
  click(7, 5);
  press(Control::PolygonMode);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(controls.mode(), DrawMode::None);
  EXPECT_TRUE(controls.notice(now).has_value());
}

TEST_F(ControlsTest, Polygon_CursorIsRedWhereTheOutlineWouldCross_AndRedClicksPlaceNothing) {
  press(Control::PolygonMode);
  click(0, 0);
  click(4, 0);
  click(4, 4);
  // Clockwise or anticlockwise both work: (0,4) closes a square.
  controls.pointerMoved(Vec2(0, 4));
  EXPECT_TRUE(controls.pointerValid());
  // (3, 1) lies inside the triangle: a concave outline, which the server
  // splits into convex pieces of one body.
  controls.pointerMoved(Vec2(3, 1));
  EXPECT_TRUE(controls.pointerValid());
  // (6, 2) would make the closing edge cross the first one.
  controls.pointerMoved(Vec2(6, 2));
  EXPECT_FALSE(controls.pointerValid());
  click(6, 2);
  EXPECT_EQ(controls.placedPoints().size(), 3u);
  // A duplicate point is red too.
  controls.pointerMoved(Vec2(4, 4));
  EXPECT_FALSE(controls.pointerValid());
}

TEST_F(ControlsTest, Polygon_ClockwiseWindingIsAccepted) {
  press(Control::PolygonMode);
  click(0, 0);
  click(0, 4);
  click(4, 4);
  controls.pointerMoved(Vec2(4, 0));
  EXPECT_TRUE(controls.pointerValid());
  controls.pointerMoved(Vec2(1, 3));
  EXPECT_TRUE(controls.pointerValid()) << "concave: split by the server";
  controls.pointerMoved(Vec2(-2, 2));
  EXPECT_FALSE(controls.pointerValid()) << "the edge from (4, 4) would cross the first";
}

TEST_F(ControlsTest, Polygon_AtMostSixteenPoints) {
  press(Control::PolygonMode);
  for (int i = 0; i < kMaxPolygonVertices + 2; ++i) {
    const float a = float(i) * 0.35f;
    click(10 + 3 * std::cos(a), 10 + 3 * std::sin(a));
  }
  EXPECT_EQ(controls.placedPoints().size(), std::size_t(kMaxPolygonVertices));
}

TEST_F(ControlsTest, Circle_PressSetsCentre_DragSetsRadius_OSends) {
  press(Control::ToggleStatic);
  press(Control::ToggleGravity);
  press(Control::SelectMaterial, kSandbox, 4);
  press(Control::CircleMode);
  controls.pointerPressed(Vec2(10, 8), std::nullopt, now);
  controls.pointerMoved(Vec2(11, 8));
  EXPECT_FLOAT_EQ(controls.circleRadius(), 1);
  controls.pointerReleased(Vec2(13, 12));
  EXPECT_FLOAT_EQ(controls.circleRadius(), 5);
  controls.pointerMoved(Vec2(20, 12));  // not dragging any more
  EXPECT_FLOAT_EQ(controls.circleRadius(), 5);
  press(Control::CircleMode);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  const auto& circle = commands[0].message.spawn_circle();
  EXPECT_DOUBLE_EQ(circle.center().x(), 10);
  EXPECT_DOUBLE_EQ(circle.radius(), 5);
  EXPECT_TRUE(circle.options().is_static());
  EXPECT_TRUE(circle.options().ignore_gravity());
  EXPECT_EQ(circle.options().material(), v1::RUBBER);
}

TEST_F(ControlsTest, Circle_WithoutDragCancels) {
  press(Control::CircleMode);
  click(3, 3);
  press(Control::CircleMode);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(controls.mode(), DrawMode::None);
}

TEST_F(ControlsTest, NoticesShowForAFewSeconds) {
  press(Control::PolygonMode);
  press(Control::PolygonMode);  // fewer than 3 points: cancelled, and told
  EXPECT_TRUE(controls.notice(now).has_value());
  EXPECT_FALSE(controls.notice(now + 10).has_value());
}

TEST_F(ControlsTest, GravityKeys_RepeatAtASteadyRateWhileHeld) {
  ControlSettings settings;
  Controls c(settings);
  c.keyPressed(key(Control::GravityLeft), kSandbox, 0);
  // 1 s of frames at an uneven rate: one nudge at the press, then repeatHz.
  for (double t = 0.003; t <= 1.0; t += 0.007 + 0.01 * (int(t * 1000) % 3)) c.update(kSandbox, t);
  c.keyReleased(key(Control::GravityLeft));
  for (double t = 1.0; t <= 2.0; t += 0.01) c.update(kSandbox, t);
  const auto commands = c.takeCommands();
  EXPECT_NEAR(double(commands.size()), 1 + settings.repeatHz, 1.5);
  ASSERT_TRUE(commands[0].message.has_nudge_gravity());
  EXPECT_DOUBLE_EQ(commands[0].message.nudge_gravity().delta().x(), -settings.gravityStep);
  EXPECT_DOUBLE_EQ(commands[0].message.nudge_gravity().delta().y(), 0);
}

TEST_F(ControlsTest, SimpleKeys_SendTheirCommands) {
  press(Control::ClearAll);
  press(Control::ResetGravity);
  press(Control::GravityUp);
  controls.keyReleased(key(Control::GravityUp));
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_TRUE(commands[0].message.has_clear());
  EXPECT_TRUE(commands[1].message.has_reset_gravity());
  EXPECT_DOUBLE_EQ(commands[2].message.nudge_gravity().delta().y(), 0.25);
}

TEST_F(ControlsTest, ToggleKeys_FlipNextShapeFlagsAndQuit) {
  EXPECT_FALSE(controls.nextStatic());
  EXPECT_TRUE(controls.nextFeelsGravity());
  press(Control::ToggleStatic);
  press(Control::ToggleGravity);
  EXPECT_TRUE(controls.nextStatic());
  EXPECT_FALSE(controls.nextFeelsGravity());
  press(Control::SelectMaterial, kSandbox, 1);
  EXPECT_EQ(controls.material(), Material::Ice);
  EXPECT_EQ(materialLabel(controls.material()), "ICE");
  EXPECT_FALSE(controls.quitRequested());
  press(Control::CancelOrQuit);
  EXPECT_TRUE(controls.quitRequested());
}

TEST_F(ControlsTest, Inspector_ClickSelects_ArrowsPushWithMassScaledImpulse) {
  press(Control::ToggleInspector);
  controls.pointerPressed(Vec2(1, 1), BodyHit{42}, now);
  EXPECT_EQ(controls.selectedBody(), 42u);
  // Before the body's mass is known nothing is sent.
  press(Control::PushRight);
  controls.keyReleased(key(Control::PushRight));
  EXPECT_TRUE(sent().empty());
  const ControlContext known{.selectedMass = 8.0};
  press(Control::PushUp, known);
  controls.keyReleased(key(Control::PushUp));
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  const auto& impulse = commands[0].message.apply_impulse();
  EXPECT_EQ(impulse.body_id(), 42u);
  EXPECT_DOUBLE_EQ(impulse.impulse().y(), 8.0 * 0.25);
  // Static bodies (mass 0) are not pushed.
  press(Control::PushUp, ControlContext{.selectedMass = 0.0});
  EXPECT_TRUE(sent().empty());
  // A click on empty space deselects; M off deselects too.
  controls.pointerPressed(Vec2(1, 1), std::nullopt, now);
  EXPECT_FALSE(controls.selectedBody());
  controls.pointerPressed(Vec2(1, 1), BodyHit{7}, now);
  press(Control::ToggleInspector);
  EXPECT_FALSE(controls.selectedBody());
}

TEST_F(ControlsTest, ClicksOutsideModesWithoutInspectorDoNothing) {
  click(3, 3);
  EXPECT_TRUE(sent().empty());
  EXPECT_FALSE(controls.selectedBody());
}

}  // namespace
}  // namespace impulse::viewer
