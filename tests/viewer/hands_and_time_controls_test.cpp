// The controls added for a working tool: time, hands (grab, throw, remove),
// Esc's order, C versus Shift+C, the view's zoom and pan, debug toggles.
#include <gtest/gtest.h>

#include "controls.h"
#include "impulse/scenes/presets.h"

namespace impulse::viewer {
namespace {

class ToolControls : public ::testing::Test {
 protected:
  void press(Control control, const ControlContext& context) {
    controls.keyPressed({control}, context, now);
  }
  std::vector<Outgoing> sent() { return controls.takeCommands(); }

  Controls controls;
  ControlContext sandbox;
  double now = 0;
};

TEST_F(ToolControls, SpacePausesAndResumes_DotStepsOnlyWhilePaused) {
  press(Control::TogglePause, sandbox);
  ControlContext paused = sandbox;
  paused.serverPaused = true;
  press(Control::StepOnce, paused);
  press(Control::TogglePause, paused);
  auto commands = sent();
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_TRUE(commands[0].message.set_paused().paused());
  EXPECT_EQ(commands[1].message.step().ticks(), 1u);
  EXPECT_FALSE(commands[2].message.set_paused().paused());
  // Running: '.' sends nothing and says why.
  press(Control::StepOnce, sandbox);
  EXPECT_TRUE(sent().empty());
  ASSERT_TRUE(controls.notice(now));
  EXPECT_NE(controls.notice(now)->find("paused"), std::string::npos);
}

TEST_F(ToolControls, EscCancelsDrawingThenSelectionAndQuitsOnlyWhenIdle) {
  press(Control::ToggleInspector, sandbox);
  controls.pointerPressed(Vec2(1, 1), BodyHit{5, true}, now);
  controls.pointerReleased(Vec2(1, 1));
  press(Control::PolygonMode, sandbox);
  controls.pointerPressed(Vec2(4, 4), std::nullopt, now);
  ASSERT_EQ(controls.polygonPoints().size(), 1u);

  press(Control::CancelOrQuit, sandbox);
  EXPECT_EQ(controls.mode(), DrawMode::None);
  EXPECT_TRUE(controls.polygonPoints().empty());
  EXPECT_EQ(controls.selectedBody(), 5u);
  EXPECT_FALSE(controls.quitRequested());
  press(Control::CancelOrQuit, sandbox);
  EXPECT_FALSE(controls.selectedBody());
  EXPECT_FALSE(controls.quitRequested());
  press(Control::CancelOrQuit, sandbox);
  EXPECT_TRUE(controls.quitRequested());
  EXPECT_TRUE(sent().empty());
}

TEST_F(ToolControls, ClearRemovesTheUsersBodies_ShiftClearClearsEverything) {
  ControlContext context = sandbox;
  context.userBodies = {7, 9};
  press(Control::ClearUserBodies, context);
  auto commands = sent();
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].message.remove_body().body_id(), 7u);
  EXPECT_EQ(commands[1].message.remove_body().body_id(), 9u);
  // Only scenery left: nothing to send, a notice says why.
  press(Control::ClearUserBodies, sandbox);
  EXPECT_TRUE(sent().empty());
  EXPECT_TRUE(controls.notice(now));
  press(Control::ClearAll, sandbox);
  commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_TRUE(commands[0].message.has_clear());
}

TEST_F(ToolControls, DeleteRemovesTheSelectedBodyElseTheOneUnderTheCursor_RightClickToo) {
  ControlContext context = sandbox;
  context.bodyUnderPointer = 11;
  press(Control::RemoveBody, context);
  press(Control::ToggleInspector, sandbox);
  controls.pointerPressed(Vec2(1, 1), BodyHit{12}, now);
  controls.pointerReleased(Vec2(1, 1));
  press(Control::RemoveBody, context);
  EXPECT_FALSE(controls.selectedBody());
  controls.removeClicked(13u, now);
  auto commands = sent();
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0].message.remove_body().body_id(), 11u);
  EXPECT_EQ(commands[1].message.remove_body().body_id(), 12u);
  EXPECT_EQ(commands[2].message.remove_body().body_id(), 13u);
  controls.removeClicked(std::nullopt, now);
  EXPECT_TRUE(sent().empty());
  EXPECT_TRUE(controls.notice(now));
}

TEST_F(ToolControls, DraggingADynamicBodySteersItAtTheGrabRate_ReleaseStops) {
  const ControlSettings settings;
  controls.pointerPressed(Vec2(5, 5), BodyHit{3, false, Vec2(5, 5)}, now);
  ASSERT_EQ(controls.grabbedBody(), 3u);
  ControlContext context = sandbox;
  context.gravity = Vec2(0, -10);
  context.grabbed = GrabbedMotion{Vec2(5, 5), Vec2(0, 0), 2.0};
  // A click that does not move is a selection, not a drag: nothing sent.
  controls.update(context, now);
  EXPECT_TRUE(sent().empty());

  controls.pointerMoved(Vec2(6, 5));
  for (int frame = 0; frame < 60; ++frame) controls.update(context, now + frame / 60.0);
  const auto commands = sent();
  // One second of frames: grabHz impulses.
  EXPECT_NEAR(double(commands.size()), settings.grabHz, 1.5);
  ASSERT_TRUE(commands[0].message.has_apply_impulse());
  const auto& impulse = commands[0].message.apply_impulse();
  EXPECT_EQ(impulse.body_id(), 3u);
  // 1 m to go at gain 10/s: 10 m/s for 2 kg, plus the gravity of one interval.
  EXPECT_NEAR(impulse.impulse().x(), 2.0 * settings.grab.gain, 1e-4);
  EXPECT_NEAR(impulse.impulse().y(), 2.0 * 10 / settings.grabHz, 1e-4);

  controls.pointerReleased(Vec2(6, 5));
  EXPECT_FALSE(controls.grabbedBody());
  controls.update(context, now + 2);
  EXPECT_TRUE(sent().empty());
}

TEST_F(ToolControls, StaticBodiesAreNotGrabbed) {
  controls.pointerPressed(Vec2(5, 5), BodyHit{3, true, Vec2(5, 5)}, now);
  EXPECT_FALSE(controls.grabbedBody());
}

TEST_F(ToolControls, WheelZoomsAtTheCursor_FitKeyRestoresTheFittedView) {
  const PixelRect viewport{0, 0, 900, 720};
  const ViewTransform fitted(viewport, kSceneSize, controls.camera());
  const Vec2 anchor = fitted.toWorld(300, 200);
  controls.zoomAt(2, 300, 200, viewport);
  const ViewTransform zoomed(viewport, kSceneSize, controls.camera());
  EXPECT_FLOAT_EQ(zoomed.scale(), 2 * fitted.scale());
  EXPECT_NEAR(zoomed.toWorld(300, 200).x(), anchor.x(), 1e-4);
  EXPECT_NEAR(zoomed.toWorld(300, 200).y(), anchor.y(), 1e-4);
  controls.pan(40, -10);
  const ViewTransform panned(viewport, kSceneSize, controls.camera());
  EXPECT_FLOAT_EQ(panned.left(), zoomed.left() + 40);
  EXPECT_FLOAT_EQ(panned.top(), zoomed.top() - 10);
  press(Control::FitView, sandbox);
  EXPECT_FLOAT_EQ(controls.camera().zoom, 1);
  EXPECT_FLOAT_EQ(ViewTransform(viewport, kSceneSize, controls.camera()).left(), fitted.left());
}

TEST_F(ToolControls, OverlayKeysToggleEachOverlay) {
  press(Control::ToggleContacts, sandbox);
  press(Control::ToggleBounds, sandbox);
  press(Control::ToggleVelocities, sandbox);
  EXPECT_TRUE(controls.overlays().contacts);
  EXPECT_TRUE(controls.overlays().bounds);
  EXPECT_TRUE(controls.overlays().velocities);
  press(Control::ToggleBounds, sandbox);
  EXPECT_FALSE(controls.overlays().bounds);
}

}  // namespace
}  // namespace impulse::viewer
