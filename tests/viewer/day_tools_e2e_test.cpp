// The viewer as a tool kept open all day (issue 31), end to end against the
// real server: the scene picker in the panel, the room in the title, time
// keys that follow the keyboard's repeat, the grab line to the cursor, the
// frame rate. Screenshots go to viewer-screenshots/.
#include <gtest/gtest.h>

#include <string>

#include "palette.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using std::chrono::milliseconds;

const viewer::PixelRect* presetEntry(viewer::App& app, int id) {
  for (const auto& [preset, rect] : app.panelState().presetEntries) {
    if (preset == id) return &rect;
  }
  return nullptr;
}

// Pixels of `rect` that are not the panel's background.
int markedPixels(SDL_Surface* shot, const viewer::PixelRect& rect) {
  const SDL_Rect area{int(rect.x), int(rect.y), int(rect.w), int(rect.h)};
  return area.w * area.h - countNear(shot, area, viewer::palette::kPanelBackground, 4);
}

TEST(ScenePicker, AClickOnAPresetLoadsIt_TheTitleAndHeaderNameTheRoom) {
  net_test::ServerProcess server({"--paused"});
  ViewerHarness viewer(server.port(), 1280, 720, {}, "studio");
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().connection().connected(); }));
  const std::string title = SDL_GetWindowTitle(viewer.app().window());
  EXPECT_NE(title.find("room studio"), std::string::npos) << title;
  ASSERT_TRUE(viewer.runUntil([&] { return presetEntry(viewer.app(), 7) != nullptr; }));
  // Every preset is offered by name, with the key that loads it.
  EXPECT_GE(viewer.app().panelState().presetEntries.size(), 10u);

  const viewer::PixelRect speed = *presetEntry(viewer.app(), 7);
  const float x = speed.x + speed.w / 2, y = speed.y + speed.h / 2;
  viewer.clickPixel(x, y);

  auto options = observerOptions(server.port());
  options.room = "studio";
  client::Client observer(options);
  ASSERT_TRUE(observeUntil(viewer, observer, [&] {
    return observer.mirror().preset() && observer.mirror().preset()->id == 7;
  }));
  ASSERT_TRUE(viewer.runUntil([&] {
    const auto* c = viewer.app().connection().client();
    return c->mirror().preset() && c->mirror().preset()->id == 7;
  }));
  // The pointer off the panel: no hover highlight, no tooltip.
  viewer.mouseMove(100, 100);
  viewer.runFrames(3);
  auto shot = viewer.capture(screenshotPath("picker_speed_loaded.bmp"));
  ASSERT_NE(shot, nullptr);
  // The loaded preset's entry is highlighted; the one above it is not.
  const viewer::PixelRect* loaded = presetEntry(viewer.app(), 7);
  const viewer::PixelRect* other = presetEntry(viewer.app(), 6);
  ASSERT_NE(loaded, nullptr);
  ASSERT_NE(other, nullptr);
  EXPECT_GT(markedPixels(shot.get(), *loaded), markedPixels(shot.get(), *other) * 3);
}

TEST(TimeKeys, AHeldBracketFollowsTheKeyboardsRepeat_QuickPressesEachCount) {
  // Running: the time scale reaches clients in snapshots.
  net_test::ServerProcess server;
  ViewerHarness viewer(server.port());
  client::Client observer(observerOptions(server.port()));
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().connection().connected(); }));
  // ] held: the press, then two of the keyboard's repeats.
  viewer.key(SDLK_RIGHTBRACKET, true);
  viewer.app().frame();
  for (int repeat = 0; repeat < 2; ++repeat) {
    viewer.key(SDLK_RIGHTBRACKET, true, KMOD_NONE, true);
    viewer.app().frame();
  }
  viewer.key(SDLK_RIGHTBRACKET, false);
  ASSERT_TRUE(observeUntil(viewer, observer, [&] {
    return observer.mirror().timeScale() == 8 &&
           viewer.app().connection().client()->mirror().timeScale() == 8;
  }));
  // Three quick taps of [, each before the server answers the one before.
  for (int tap = 0; tap < 3; ++tap) viewer.tap(SDLK_LEFTBRACKET);
  ASSERT_TRUE(observeUntil(viewer, observer, [&] { return observer.mirror().timeScale() == 1; }));
}

TEST(Hands, TheGrabLineRunsFromTheHeldPointToTheCursor) {
  net_test::ServerProcess server;
  ViewerHarness viewer(server.port());
  client::Client observer(observerOptions(server.port()));
  const auto reply = observer.request(client::spawnCircle({6, 2}, 0.5));
  ASSERT_TRUE(reply.command_result().ok());
  const std::uint32_t id = reply.command_result().body_id();
  const auto drawn = [&]() -> const viewer::DrawnBody* {
    for (const auto& body : viewer.app().world().bodies()) {
      if (body.state.id == id) return &body;
    }
    return nullptr;
  };
  ASSERT_TRUE(observeUntil(viewer, observer, [&] { return drawn() != nullptr; }));
  viewer.runFrames(20);
  const Vec2 pressed = drawn()->state.position;
  const Vec2 cursor(20, 14);
  // Press on the ball's centre and move far away while holding.
  const auto from = viewer.pixel(pressed);
  viewer.mouseMove(from.x, from.y);
  viewer.mouseButton(from.x, from.y, true);
  viewer.app().frame();
  const auto to = viewer.pixel(cursor);
  for (int i = 1; i <= 5; ++i) {
    viewer.mouseMove(from.x + (to.x - from.x) * float(i) / 5, from.y + (to.y - from.y) * float(i) / 5);
    viewer.app().frame();
  }
  ASSERT_EQ(viewer.app().controls().grabbedBody(), id);
  // On its way: well off the press point, still short of the cursor.
  ASSERT_TRUE(observeUntil(viewer, observer, [&] {
    const Vec2 at = drawn()->state.position;
    return (at - pressed).norm() > 2 && (cursor - at).norm() > 4;
  }));
  auto shot = viewer.capture(screenshotPath("grab_line.bmp"));
  ASSERT_NE(shot, nullptr);
  const Vec2 held = drawn()->state.position;
  auto linePixels = [&](const Vec2& a, const Vec2& b, float t) {
    const auto p = viewer.pixel(a + (b - a) * t);
    return countNear(shot.get(), {int(p.x) - 3, int(p.y) - 3, 7, 7}, viewer::palette::kSelection, 40);
  };
  // The line reaches out to the cursor...
  for (const float t : {0.4f, 0.7f, 0.9f}) EXPECT_GT(linePixels(held, cursor, t), 0) << t;
  // ...and nothing is drawn back to where the press was.
  EXPECT_EQ(linePixels(held, pressed, 0.7f), 0);
  viewer.mouseButton(to.x, to.y, false);
  viewer.app().frame();
}

TEST(Inspector, TheSelectedBodysVelocityIsEditable_StopSetsItToZero) {
  net_test::ServerProcess server({"--paused"});
  ViewerHarness viewer(server.port());
  client::Client observer(observerOptions(server.port()));
  const auto spawned = observer.request(client::spawnCircle({8, 8}, 0.6));
  ASSERT_TRUE(spawned.command_result().ok());
  const std::uint32_t id = spawned.command_result().body_id();
  ASSERT_TRUE(observer.request(client::setVelocity(id, {2, 1}, 3)).command_result().ok());
  ASSERT_TRUE(viewer.runUntil([&] {
    for (const auto& body : viewer.app().world().bodies()) {
      if (body.state.id == id) return true;
    }
    return false;
  }));
  viewer.tap(SDLK_m);
  viewer.click(Vec2(8, 8));
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().panelState().stopButton.has_value(); }));
  viewer.runFrames(3);
  auto shot = viewer.capture(screenshotPath("inspector_editable.bmp"));
  ASSERT_NE(shot, nullptr);
  // The Stop button is drawn under the velocity fields (its face is not
  // the panel's background).
  const viewer::PixelRect stop = *viewer.app().panelState().stopButton;
  EXPECT_GT(markedPixels(shot.get(), stop), int(stop.w * stop.h / 2));

  const float x = stop.x + stop.w / 2, y = stop.y + stop.h / 2;
  viewer.mouseMove(x, y);
  viewer.runFrames(2);
  viewer.mouseButton(x, y, true);
  viewer.runFrames(2);
  viewer.mouseButton(x, y, false);
  viewer.runFrames(2);
  ASSERT_TRUE(viewer.runUntil([&] {
    const auto info = observer.request(client::queryBody(id)).body_info();
    return info.state().velocity().x() == 0 && info.state().velocity().y() == 0 &&
           info.state().angular_velocity() == 0;
  }));
}

TEST(FrameRate, ThePanelsFigureCountsTheFramesOfTheLastSecond) {
  net_test::ServerProcess server({"--paused"});
  ViewerHarness viewer(server.port());
  const auto start = std::chrono::steady_clock::now();
  viewer.runUntil([] { return false; }, milliseconds(1300));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double expected = double(viewer.app().frames()) / seconds;
  EXPECT_GT(viewer.app().framesPerSecond(), 0.5 * expected);
  EXPECT_LT(viewer.app().framesPerSecond(), 2 * expected);
}

}  // namespace
}  // namespace impulse::viewer_test
