// The viewer against a real impulse-server, rendered offscreen: the pictures
// are checked pixel by pixel and kept in <build>/viewer-screenshots.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "palette.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using std::chrono::milliseconds;

// The ramp preset's ball as the server has it.
const client::MirrorBody* findBall(const client::Client& observer) {
  for (const auto& [id, body] : observer.mirror().bodies()) {
    if (!body.isStatic && body.shape.type() == ShapeType::Circle) return &body;
  }
  return nullptr;
}

class PausedRampScreenshot : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(PausedRampScreenshot, BallColourAppearsWhereItsBodyIs) {
  const auto [width, height] = GetParam();
  // Paused: the ball stays where the server put it, so the frame can be
  // compared with the server's state exactly.
  net_test::ServerProcess server({"--paused"});
  ViewerHarness viewer(server.port(), width, height);
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().connection().connected(); }));
  std::string title = SDL_GetWindowTitle(viewer.app().window());
  EXPECT_EQ(title.rfind("Impulse", 0), 0u) << title;
  EXPECT_TRUE(viewer.app().controls().panelVisible());

  viewer.tap(SDLK_1);  // the viewer loads preset 1, Ramp
  const client::Client* seen = nullptr;
  ASSERT_TRUE(viewer.runUntil([&] {
    seen = viewer.app().connection().client();
    return seen != nullptr && seen->mirror().preset() && seen->mirror().preset()->id == 1 &&
           findBall(*seen) != nullptr && viewer.app().world().bodies().size() ==
                                             seen->mirror().bodies().size();
  }));
  EXPECT_FALSE(viewer.app().controls().panelVisible());

  client::Client observer(observerOptions(server.port()));
  const client::MirrorBody* ball = findBall(observer);
  ASSERT_NE(ball, nullptr);
  viewer.runFrames(5);
  const std::string name = "ramp_paused_" + std::to_string(width) + "x" +
                           std::to_string(height) + ".bmp";
  auto shot = viewer.capture(screenshotPath(name));
  ASSERT_NE(shot, nullptr) << SDL_GetError();
  ASSERT_EQ(shot->w, width);
  ASSERT_EQ(shot->h, height);

  const auto view = viewer.app().view();
  const float r = ball->shape.circle().radius * view.scale();
  const auto centre = view.toPixels(ball->state.position);
  // Half way to the rim, across from the radius line (which has the outline colour).
  const float a = ball->state.angle;
  const int x = int(std::lround(centre.x + 0.5f * r * std::sin(a)));
  const int y = int(std::lround(centre.y + 0.5f * r * std::cos(a)));
  const viewer::Colour expected =
      viewer::bodyFill(ball->material, false);
  EXPECT_LE(colourDistance(pixelAt(shot.get(), x, y), expected), 8)
      << "pixel (" << x << ", " << y << ") of " << name;
  // Around the ball, well clear of it: the scene background.
  const int above = int(centre.y - 3 * r);
  EXPECT_LE(colourDistance(pixelAt(shot.get(), int(centre.x), above),
                           viewer::palette::kSceneBackground),
            8);
  // The ball's fill covers its area inside the outline (about 2 px wide with
  // its anti-aliased edge) except the rotation mark (about 3 px by r),
  // nowhere else.
  const SDL_Rect box{int(centre.x - 2 * r), int(centre.y - 2 * r), int(4 * r), int(4 * r)};
  const int filled = countNear(shot.get(), box, expected, 8);
  const float inner = 3.14159f * (r - 2) * (r - 2);
  EXPECT_GT(filled, 0.9f * inner - 3 * r);
  EXPECT_LT(filled, 1.1f * 3.14159f * r * r);
  // The preset title is written at the top of the side panel.
  const auto panel = viewer.app().layout().panel;
  EXPECT_GT(countNear(shot.get(), {int(panel.x), 0, int(panel.w), 40}, viewer::palette::kText, 40),
            30);
}

INSTANTIATE_TEST_SUITE_P(WindowSizes, PausedRampScreenshot,
                         ::testing::Values(std::make_pair(1280, 720),
                                           std::make_pair(800, 600)));

TEST(RunningScreenshot, EveryDynamicBodyIsDrawnInItsColourWhereTheViewerShowsIt) {
  net_test::ServerProcess server({"--preset", "8"});
  ViewerHarness viewer(server.port());
  ASSERT_TRUE(viewer.runUntil([&] {
    return viewer.app().connection().connected() && viewer.app().world().bodies().size() > 10;
  }));
  viewer.runFrames(40);
  // Rendered time trails the newest snapshot by about the playout delay.
  const auto& world = viewer.app().world();
  const double behind = world.buffer().newestTime() - world.renderTime();
  EXPECT_GT(behind, -1.0 / 30);
  EXPECT_LT(behind, world.clock().delay() + 0.1);

  auto shot = viewer.capture(screenshotPath("crowd_running.bmp"));
  ASSERT_NE(shot, nullptr);
  // What the captured frame drew.
  const std::vector<viewer::DrawnBody>& drawn = world.bodies();
  const auto view = viewer.app().view();
  int checked = 0;
  int matched = 0;
  for (const viewer::DrawnBody& body : drawn) {
    if (body.look->isStatic || body.look->shape.type() != ShapeType::Circle) continue;
    const float r = body.look->shape.circle().radius * view.scale();
    if (r < 6) continue;
    const auto c = view.toPixels(body.state.position);
    const float a = body.state.angle;
    const viewer::Colour expected =
        viewer::bodyFill(body.look->material, false);
    const viewer::Colour seen = pixelAt(shot.get(), int(c.x + 0.5f * r * std::sin(a)),
                                        int(c.y + 0.5f * r * std::cos(a)));
    // Balls in contact may overlap by a pixel where the probe lands.
    if (colourDistance(seen, expected) <= 8) ++matched;
    ++checked;
  }
  EXPECT_GT(checked, 10);
  EXPECT_GE(matched, checked * 9 / 10) << matched << " of " << checked;
}

TEST(ViewerBinary, ConnectsLoadsAPresetAndSavesAScreenshot) {
  net_test::ServerProcess server;
  const std::string path = screenshotPath("binary_preset4.bmp");
  std::remove(path.c_str());
  const std::string command =
      "SDL_VIDEODRIVER=offscreen SDL_RENDER_DRIVER=software SDL_FRAMEBUFFER_ACCELERATION=0 " +
                              std::string(IMPULSE_VIEWER_BINARY) + " --connect 127.0.0.1:" +
                              std::to_string(server.port()) + " --preset 4 --frames 45" +
                              " --screenshot " + path;
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  SDL_Surface* shot = SDL_LoadBMP(path.c_str());
  ASSERT_NE(shot, nullptr) << path;
  SDL_Surface* argb = SDL_ConvertSurfaceFormat(shot, SDL_PIXELFORMAT_ARGB8888, 0);
  // The circle tutorial's yellow markers are drawn.
  EXPECT_GT(countNear(argb, {0, 0, argb->w, argb->h}, viewer::palette::kMarker, 10), 20);
  SDL_FreeSurface(argb);
  SDL_FreeSurface(shot);
  client::Client observer(observerOptions(server.port()));
  ASSERT_TRUE(observer.mirror().preset());
  EXPECT_EQ(observer.mirror().preset()->id, 4);
}

TEST(Reconnect, LostServerIsShown_AndTheViewerReconnectsToANewOne) {
  std::uint16_t port = 0;
  {
    net_test::ServerProcess first;
    port = first.port();
    ViewerHarness viewer(port);
    ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().connection().connected(); }));
    first.stop();
    ASSERT_TRUE(viewer.runUntil(
        [&] { return viewer.app().connection().state() == viewer::LinkState::Lost; }));
    // Frames keep coming while the link is down.
    const auto before = viewer.app().frames();
    viewer.runFrames(5);
    EXPECT_EQ(viewer.app().frames(), before + 5);
    net_test::ServerProcess second({"--port", std::to_string(port), "--preset", "2"});
    ASSERT_EQ(second.port(), port);
    ASSERT_TRUE(viewer.runUntil([&] {
      const auto* c = viewer.app().connection().client();
      return c != nullptr && c->mirror().preset() && c->mirror().preset()->id == 2 &&
             !viewer.app().world().bodies().empty();
    }));
    EXPECT_EQ(viewer.app().connection().connections(), 2);
  }
}

}  // namespace
}  // namespace impulse::viewer_test
