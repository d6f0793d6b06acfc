// Field presets in the viewer (Shift+5-7), rendered offscreen against a
// paused server: the liquid is tinted where the pool is, a fan's cone shows
// faintly above it, and the screenshots are kept in <build>/viewer-screenshots.

#include <gtest/gtest.h>

#include <string>

#include "impulse/scenes/field_scenes.h"
#include "impulse/scenes/presets.h"
#include "palette.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

// Loads preset `id` with Shift+`key` and waits for its bodies and fields.
void loadWithShift(ViewerHarness& viewer, SDL_Keycode key, int id) {
  viewer.tap(key, KMOD_LSHIFT);
  ASSERT_TRUE(viewer.runUntil([&] {
    const client::Client* seen = viewer.app().connection().client();
    return seen != nullptr && seen->mirror().preset() && seen->mirror().preset()->id == id &&
           !seen->mirror().fields().empty() &&
           viewer.app().world().bodies().size() == seen->mirror().bodies().size();
  }));
  viewer.runFrames(5);
}

TEST(FieldScreenshots, ShiftFiveToSeven_LoadTheFieldPresets_AndDrawTheirFields) {
  net_test::ServerProcess server({"--paused"});
  ViewerHarness viewer(server.port(), 1280, 720);
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().connection().connected(); }));
  const viewer::Colour background = viewer::palette::kSceneBackground;

  loadWithShift(viewer, SDLK_5, 15);
  ASSERT_NE(viewer.capture(screenshotPath("preset15_orbits.bmp")), nullptr);

  loadWithShift(viewer, SDLK_6, 16);
  auto pool = viewer.capture(screenshotPath("preset16_floating.bmp"));
  ASSERT_NE(pool, nullptr);
  // Low in the pool, between the boxes (which float at the surface).
  const auto water = viewer.pixel(Vec2(Real(5.75), 2));
  const viewer::Colour tinted = pixelAt(pool.get(), int(water.x), int(water.y));
  EXPECT_GT(int(tinted.b), int(background.b) + 30) << "the liquid is tinted blue";
  const auto air = viewer.pixel(Vec2(Real(5.75), kWaterLevel + 5));
  EXPECT_LE(colourDistance(pixelAt(pool.get(), int(air.x), int(air.y)), background), 8) << "no tint above it";

  loadWithShift(viewer, SDLK_7, 17);
  auto fans = viewer.capture(screenshotPath("preset17_fans.bmp"));
  ASSERT_NE(fans, nullptr);
  // On a fan's axis high up (balls hover lower), and well outside both cones.
  const auto inCone = viewer.pixel(Vec2(kFanPositions[0], 12));
  const auto outside = viewer.pixel(Vec2(Real(12.5), 3));
  EXPECT_GT(colourDistance(pixelAt(fans.get(), int(inCone.x), int(inCone.y)), background), 4) << "the cone shows";
  EXPECT_LE(colourDistance(pixelAt(fans.get(), int(outside.x), int(outside.y)), background), 2);
}

}  // namespace
}  // namespace impulse::viewer_test
