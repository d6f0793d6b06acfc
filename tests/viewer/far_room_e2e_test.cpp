// The viewer in a room 80 km from (0, 0): it draws in its mirror's frame,
// around the room's origin, and converts at its link, so a body the server
// holds far out is drawn where the view puts that absolute point, and a
// circle drawn under the cursor lands at the absolute point under it.
#include <gtest/gtest.h>

#include "palette.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

/// Bounds centred 80 037.5 m out: the room computes around (80 000, 0).
constexpr client::Box kFarBounds{{79987.5, -10}, {80087.5, 90}};
const Vec2d kFarOrigin(80000, 0);

/// An admin making (or joining) the far room.
client::ConnectOptions farRoomMaker(std::uint16_t port) {
  client::ConnectOptions options = observerOptions(port);
  options.room = "far";
  options.roomBounds = kFarBounds;
  return options;
}

const client::MirrorBody* bodyAt(const client::Client& client, const Vec2d& place, double within) {
  for (const auto& [id, body] : client.mirror().bodies()) {
    if ((client.mirror().toGlobal(body.state.position) - place).norm() < within) return &body;
  }
  return nullptr;
}

TEST(FarRoom, ABodyFarOutIsDrawnWhereItIs_AndACircleDrawnThereLandsAtItsAbsolutePlace) {
  net_test::ServerProcess server({"--paused"});
  client::Client maker(farRoomMaker(server.port()));
  ASSERT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  const Vec2d ballPlace(80012.5, 9);
  const v1::ServerMessage made =
      maker.request(client::spawnCircle({ballPlace.x(), ballPlace.y()}, 1, {.isStatic = true}));
  ASSERT_TRUE(made.command_result().ok()) << made.command_result().error();
  const std::uint32_t ball = made.command_result().body_id();

  ViewerHarness viewer(server.port(), 1280, 720, {}, "far");
  ASSERT_TRUE(viewer.runUntil([&] {
    for (const auto& body : viewer.app().world().bodies()) {
      if (body.state.id == ball) return true;
    }
    return false;
  }));
  const client::Client& seen = *viewer.app().connection().client();
  EXPECT_EQ(seen.mirror().origin(), kFarOrigin);

  // The ball's colour under the pixel the view gives its absolute place, and
  // the scene's background a diameter away.
  const Vec2 ballInView = seen.mirror().toLocal(ballPlace);
  EXPECT_EQ(ballInView, Vec2(12.5f, 9)) << "the viewer draws around the room's origin";
  auto shot = viewer.capture(screenshotPath("far_room_ball.bmp"));
  ASSERT_NE(shot, nullptr) << SDL_GetError();
  const auto centre = viewer.pixel(ballInView);
  const float radius = viewer.app().view().scale();
  const viewer::Colour fill = viewer::bodyFill(Material::Solid, true);
  EXPECT_LE(colourDistance(pixelAt(shot.get(), int(centre.x + radius / 2), int(centre.y)), fill),
            8);
  EXPECT_LE(colourDistance(pixelAt(shot.get(), int(centre.x), int(centre.y - 2 * radius)),
                           viewer::palette::kSceneBackground),
            8);

  // A circle dragged out at the view's (18, 6) is made at the absolute point
  // the room's origin puts there, as the other client sees it.
  viewer.tap(SDLK_o);
  const Vec2 drawn(18, 6);
  const auto press = viewer.pixel(drawn);
  const auto rim = viewer.pixel(drawn + Vec2(1, 0));
  viewer.mouseMove(press.x, press.y);
  viewer.mouseButton(press.x, press.y, true);
  viewer.app().frame();
  viewer.mouseMove(rim.x, rim.y);
  viewer.mouseButton(rim.x, rim.y, false);
  viewer.app().frame();
  viewer.tap(SDLK_o);
  const Vec2d expected = kFarOrigin + drawn.cast<double>();
  ASSERT_TRUE(observeUntil(viewer, maker, [&] { return bodyAt(maker, expected, 0.05) != nullptr; }))
      << "no body near (" << expected.x() << ", " << expected.y() << ")";
  EXPECT_NEAR(bodyAt(maker, expected, 0.05)->shape.circle().radius, 1, 0.05);
}

}  // namespace
}  // namespace impulse::viewer_test
