// --area-margin and --budget against the real server: the viewer receives
// only the bodies in its view plus the margin and asks for more as the view
// zooms out; a budget too small for the room's changes makes the server
// withhold states from it.
#include <gtest/gtest.h>

#include "server_process.h"
#include "view_area.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

bool holds(const client::Client& client, std::uint32_t id) {
  return client.mirror().find(BodyId{id}) != nullptr;
}

std::uint32_t spawnedBall(client::Client& maker, client::Point at, bool isStatic) {
  const v1::ServerMessage made =
      maker.request(client::spawnCircle(at, 0.5, {.isStatic = isStatic}));
  EXPECT_TRUE(made.command_result().ok()) << made.command_result().error();
  return made.command_result().body_id();
}

TEST(ViewArea, TheViewerReceivesTheBodiesInItsView_AndOneOutsideOnceTheViewZoomsOutToIt) {
  net_test::ServerProcess server({"--paused"});
  client::Client maker(observerOptions(server.port()));
  ASSERT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  const std::uint32_t inView = spawnedBall(maker, {12, 9}, true);
  const std::uint32_t farCorner = spawnedBall(maker, {45, 40}, true);

  ViewerHarness viewer(server.port(),
                       [](viewer::ViewerOptions& options) { options.areaMargin = 1; });
  ASSERT_TRUE(viewer.runUntil([&] {
    const client::Client* seen = viewer.app().connection().client();
    return seen != nullptr && holds(*seen, inView);
  }));
  viewer.runFrames(20);
  EXPECT_FALSE(holds(*viewer.app().connection().client(), farCorner))
      << "outside the view and its margin";

  // Zoomed out about the scene's bottom-left corner: the view reaches 100 m
  // by 75 m from it.
  const auto corner = viewer.pixel(Vec2(0, 0));
  viewer.mouseMove(corner.x, corner.y);
  viewer.wheel(-12);
  viewer.runFrames(2);
  ASSERT_TRUE(viewer::viewArea(viewer.app().view(), 0).contains(AABB{Vec2(45, 40), Vec2(45, 40)}));
  EXPECT_TRUE(
      viewer.runUntil([&] { return holds(*viewer.app().connection().client(), farCorner); }));
  EXPECT_TRUE(holds(*viewer.app().connection().client(), inView));
}

TEST(ViewArea, ABudgetTooSmallForTheRoomsChangesMakesTheServerWithholdStates) {
  net_test::ServerProcess server;
  client::Client maker(observerOptions(server.port()));
  ASSERT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  for (int i = 0; i < 60; ++i)
    spawnedBall(maker, {2.0 + (i % 20) * 1.1, 5.0 + (i / 20) * 1.1}, false);

  ViewerHarness viewer(server.port(),
                       [](viewer::ViewerOptions& options) { options.budget = 1000; });
  EXPECT_TRUE(viewer.runUntil([&] {
    const client::Client* seen = viewer.app().connection().client();
    return seen != nullptr && seen->lastSnapshot() && seen->lastSnapshot()->states_withheld() > 0;
  }));
}

}  // namespace
}  // namespace impulse::viewer_test
