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
  ASSERT_EQ(controls.placedPoints().size(), 1u);

  press(Control::CancelOrQuit, sandbox);
  EXPECT_EQ(controls.mode(), DrawMode::None);
  EXPECT_TRUE(controls.placedPoints().empty());
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

TEST_F(ToolControls, DraggingMakesAMouseJoint_TheCursorMovesItsTarget_ReleaseRemovesIt) {
  const ControlSettings settings;
  controls.pointerPressed(Vec2(5, 5), BodyHit{3, false, Vec2(5, 5)}, now);
  ASSERT_EQ(controls.grabbedBody(), 3u);
  ControlContext context = sandbox;
  context.grabbed = GrabbedBody{Vec2(5, 5), 2.0};
  // A click that does not move is a selection, not a drag: nothing sent.
  controls.update(context, now);
  EXPECT_TRUE(sent().empty());

  controls.pointerMoved(Vec2(6, 5));
  controls.update(context, now);
  auto commands = sent();
  ASSERT_EQ(commands.size(), 2u) << "the joint and at once its first target";
  ASSERT_TRUE(commands[0].message.has_create_joint());
  EXPECT_EQ(commands[1].message.update_joint().target().x(), 6);
  const auto& create = commands[0].message.create_joint();
  EXPECT_EQ(create.body_a(), 3u);
  EXPECT_EQ(create.body_b(), 0u);
  EXPECT_EQ(create.anchor_a().x(), 5);
  ASSERT_TRUE(create.has_mouse());
  const std::uint32_t tag = create.tag();
  ASSERT_NE(tag, 0u) << "later commands name the joint by its tag";
  // Mass-scaled: the same brisk follow for any body.
  EXPECT_NEAR(create.mouse().max_force(), 2.0 * settings.grab.maxAcceleration, 1e-9);
  EXPECT_GT(create.mouse().stiffness(), 0);

  // Targets follow the cursor at once, naming the joint by its tag, at most at grabHz.
  for (int frame = 0; frame < 60; ++frame) {
    controls.pointerMoved(Vec2(6 + frame * 0.01f, 5));
    controls.update(context, now + frame / 60.0);
  }
  commands = sent();
  EXPECT_NEAR(double(commands.size()), settings.grabHz, 1.5);
  ASSERT_TRUE(commands[0].message.has_update_joint());
  EXPECT_EQ(commands[0].message.update_joint().joint_tag(), tag);
  EXPECT_TRUE(commands[0].message.update_joint().has_target());

  controls.pointerReleased(Vec2(6, 5));
  EXPECT_FALSE(controls.grabbedBody());
  commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].message.remove_joint().joint_tag(), tag);
}

TEST_F(ToolControls, AReleaseRightAfterThePressRemovesTheJointByItsTag_EachDragTagsAnew) {
  ControlContext context = sandbox;
  context.grabbed = GrabbedBody{Vec2(5, 5), 1.0};
  std::vector<std::uint32_t> tags;
  for (int drag = 0; drag < 2; ++drag) {
    controls.pointerPressed(Vec2(5, 5), BodyHit{3, false, Vec2(5, 5)}, now);
    controls.pointerMoved(Vec2(6, 5));
    controls.update(context, now);
    controls.pointerReleased(Vec2(6, 5));
    const auto commands = sent();
    ASSERT_EQ(commands.size(), 3u) << "the joint, its first target and its removal, without waiting for a reply";
    tags.push_back(commands[0].message.create_joint().tag());
    EXPECT_EQ(commands[1].message.update_joint().joint_tag(), tags.back());
    EXPECT_EQ(commands[2].message.remove_joint().joint_tag(), tags.back());
  }
  EXPECT_NE(tags[0], tags[1]);
}

TEST_F(ToolControls, JPinsTheSelectedBodyAtTheCursorOnIt) {
  press(Control::ToggleInspector, sandbox);
  controls.pointerPressed(Vec2(5, 6), BodyHit{3, false, Vec2(5, 5)}, now);
  controls.pointerReleased(Vec2(5, 6));
  sent();
  ControlContext context = sandbox;
  context.selectedPosition = Vec2(5, 5);
  context.bodyUnderPointer = 3;
  press(Control::PinSelected, context);
  auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  const auto& pin = commands[0].message.create_joint();
  EXPECT_TRUE(pin.has_revolute());
  EXPECT_EQ(pin.body_a(), 3u);
  EXPECT_EQ(pin.body_b(), 0u);
  EXPECT_EQ(pin.anchor_a().y(), 6);
  // Nothing selected: a hint, nothing sent.
  press(Control::CancelOrQuit, context);
  press(Control::PinSelected, context);
  EXPECT_TRUE(sent().empty());
  EXPECT_TRUE(controls.notice(now));
}

TEST_F(ToolControls, StaticBodiesAreNotGrabbed) {
  controls.pointerPressed(Vec2(5, 5), BodyHit{3, true, Vec2(5, 5)}, now);
  EXPECT_FALSE(controls.grabbedBody());
}

TEST_F(ToolControls, WheelZoomsAtTheCursor_FitKeyRestoresTheFittedView) {
  const PixelRect viewport{0, 0, 900, 720};
  const ViewTransform fitted(viewport, kPresetScene, controls.camera());
  const Vec2 anchor = fitted.toWorld(300, 200);
  controls.zoomAt(2, 300, 200, viewport);
  const ViewTransform zoomed(viewport, kPresetScene, controls.camera());
  EXPECT_FLOAT_EQ(zoomed.scale(), 2 * fitted.scale());
  EXPECT_NEAR(zoomed.toWorld(300, 200).x(), anchor.x(), 1e-4);
  EXPECT_NEAR(zoomed.toWorld(300, 200).y(), anchor.y(), 1e-4);
  controls.pan(40, -10);
  const ViewTransform panned(viewport, kPresetScene, controls.camera());
  EXPECT_FLOAT_EQ(panned.left(), zoomed.left() + 40);
  EXPECT_FLOAT_EQ(panned.top(), zoomed.top() - 10);
  press(Control::FitView, sandbox);
  EXPECT_FLOAT_EQ(controls.camera().zoom, 1);
  EXPECT_FLOAT_EQ(ViewTransform(viewport, kPresetScene, controls.camera()).left(), fitted.left());
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
