// The viewer's prediction end to end over a round trip made 150 ms long:
// a push (an arrow key on the selected box) shows on the next frame, and
// after the "Predict my actions" box is cleared, only when the snapshots
// bring it. Frames are counted; the time they took is printed, not checked.
#include <gtest/gtest.h>

#include <iostream>

#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using Clock = std::chrono::steady_clock;

/// A box has moved on screen when it is drawn this far (m) from where it was.
constexpr double kVisibleMove = 0.001;

struct PushFigure {
  int frames = 0;
  double milliseconds = 0;
};

/// Presses the up arrow (a push of the selected body) and runs frames until
/// the body is drawn elsewhere.
PushFigure pushUntilDrawnMoving(ViewerHarness& viewer, std::uint32_t body) {
  const Vec2 before = viewer.app().world().find(body)->position;
  const auto start = Clock::now();
  viewer.key(SDLK_UP, true);
  PushFigure figure;
  const auto moved = [&] { return (viewer.app().world().find(body)->position - before).norm() > kVisibleMove; };
  while (!moved() && figure.frames < 600) {
    viewer.runFrames(1);
    if (++figure.frames == 1) viewer.key(SDLK_UP, false);
  }
  figure.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return figure;
}

TEST(ViewerPrediction, PushShowsOnTheNextFrame_ClearingTheBoxWaitsForSnapshots) {
  net_test::ServerProcess server(std::vector<std::string>{});
  client::Client observer(observerOptions(server.port()));
  ASSERT_TRUE(observer.request(client::clearWorld()).command_result().ok());
  const std::vector<client::Point> floor{{-20, -1}, {40, -1}, {40, 0}, {-20, 0}};
  ASSERT_TRUE(observer.request(client::spawnPolygon(floor, {.isStatic = true})).command_result().ok());
  const std::vector<client::Point> box{{7, 0}, {9, 0}, {9, 2}, {7, 2}};
  const auto made = observer.request(client::spawnPolygon(box, {.material = Material::Wood}));
  ASSERT_TRUE(made.command_result().ok()) << made.command_result().error();
  const std::uint32_t id = made.command_result().body_id();

  ViewerHarness viewer(server.port(), std::chrono::milliseconds(150), true);
  ASSERT_TRUE(viewer.runUntil([&] {
    return viewer.app().connection().predictor() != nullptr && viewer.app().world().find(id) != nullptr;
  })) << "prediction starts once a round trip is measured";
  viewer.tap(SDLK_m);
  viewer.click(Vec2(8, 1));
  // The push needs the box's mass, which the inspector's details bring.
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().panelState().poseFields.has_value(); }));
  viewer.runFrames(30);

  const PushFigure predicted = pushUntilDrawnMoving(viewer, id);
  EXPECT_TRUE(viewer.app().connection().predictor()->owns(id));
  viewer.runFrames(120);  // the box lands again

  ASSERT_TRUE(viewer.app().panelState().predictBox.has_value());
  const viewer::PixelRect toggle = *viewer.app().panelState().predictBox;
  viewer.clickPixel(toggle.x + toggle.h / 2, toggle.y + toggle.h / 2);
  ASSERT_FALSE(viewer.app().connection().predicting()) << "the box turned prediction off";
  EXPECT_EQ(viewer.app().connection().predictor(), nullptr);
  viewer.runFrames(30);
  const PushFigure unpredicted = pushUntilDrawnMoving(viewer, id);

  std::cout << "[ figures  ] viewer push at 150 ms round trip: predicted " << predicted.frames << " frame(s), "
            << predicted.milliseconds << " ms; unpredicted " << unpredicted.frames << " frames, "
            << unpredicted.milliseconds << " ms\n";
  EXPECT_EQ(predicted.frames, 1) << "the push is stepped by the copy in the frame after the key";
  EXPECT_GT(unpredicted.frames, predicted.frames);
  EXPECT_GE(unpredicted.milliseconds, 150) << "a snapshot cannot bring the push before the round trip";
}

}  // namespace
}  // namespace impulse::viewer_test
