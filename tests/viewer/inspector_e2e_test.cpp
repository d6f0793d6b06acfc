// The editable inspector end to end: a box selected with M and a click,
// moved by typing in its position field, made kinematic by a click on the
// type buttons; an observer checks the server's world.
#include <gtest/gtest.h>

#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

TEST(EditableInspector, TypedPositionMovesTheBody_TypeButtonMakesItKinematic) {
  net_test::ServerProcess server({"--paused"});
  ViewerHarness viewer(server.port());
  client::Client observer(observerOptions(server.port()));
  const std::vector<client::Point> corners{{7, 7}, {9, 7}, {9, 9}, {7, 9}};
  const auto reply = observer.request(client::spawnPolygon(corners));
  ASSERT_TRUE(reply.command_result().ok()) << reply.command_result().error();
  const BodyId id{reply.command_result().body_id()};
  ASSERT_TRUE(observeUntil(viewer, observer, [&] { return viewer.app().world().find(id.value) != nullptr; }));

  viewer.tap(SDLK_m);
  viewer.click(Vec2(8, 8));
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().panelState().poseFields.has_value(); }));
  viewer.runFrames(3);
  auto shot = viewer.capture(screenshotPath("inspector_edit.bmp"));
  ASSERT_NE(shot, nullptr);

  // x is the first of the three fields: a click selects its text, typing replaces it.
  const viewer::PixelRect pose = *viewer.app().panelState().poseFields;
  viewer.clickPixel(pose.x + pose.w / 6, pose.y + pose.h / 2);
  viewer.typeText("4");
  viewer.tap(SDLK_RETURN);
  ASSERT_TRUE(observeUntil(viewer, observer, [&] {
    const auto* body = observer.mirror().find(id);
    return body != nullptr && std::abs(body->state.position.x() - 4) < 1e-4;
  }));
  EXPECT_NEAR(observer.mirror().find(id)->state.position.y(), 8, 1e-4);
  // Enter went to the field, not to the gravity key.
  EXPECT_EQ(observer.mirror().gravity(), Vec2(0, Real(-9.81)));

  ASSERT_TRUE(viewer.app().panelState().typeButtons[1].has_value());
  const viewer::PixelRect kinematic = *viewer.app().panelState().typeButtons[1];
  viewer.clickPixel(kinematic.x + kinematic.h / 2, kinematic.y + kinematic.h / 2);
  ASSERT_TRUE(observeUntil(viewer, observer, [&] {
    const auto* body = observer.mirror().find(id);
    return body != nullptr && body->isKinematic;
  }));
}

}  // namespace
}  // namespace impulse::viewer_test
