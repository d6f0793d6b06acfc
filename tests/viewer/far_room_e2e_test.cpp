// The viewer in a room 80 km from (0, 0): it draws in its mirror's frame,
// around the room's origin, and converts at its link, so a body the server
// holds far out is drawn where the view puts that absolute point, and a
// circle drawn under the cursor lands at the absolute point under it. A
// room that does not hold the preset scene opens on its bounds, or on its
// bodies when the bounds are too large to show; a preset loaded there lands
// centred on its bounds, in view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "palette.h"
#include "scene_frame.h"
#include "server_process.h"
#include "view_area.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

/// Bounds centred 80 037.5 m out: the room computes around (80 000, 0).
constexpr client::Box kFarBounds{{79987.5, -10}, {80087.5, 90}};
const Vec2d kFarOrigin(80000, 0);

/// An admin making (or joining) the room `name` with `bounds`.
client::ConnectOptions roomMaker(std::uint16_t port, const std::string& name, const client::Box& bounds) {
  client::ConnectOptions options = observerOptions(port);
  options.room = name;
  options.roomBounds = bounds;
  return options;
}

client::ConnectOptions farRoomMaker(std::uint16_t port) { return roomMaker(port, "far", kFarBounds); }

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

/// Radius of the balls the framing tests look for on screen.
constexpr double kBallRadius = 2;

/// Makes the room `name` with `bounds` holding a static ball at each of
/// `places` (metres from (0, 0)); a viewer joining it must show every ball
/// within its scene viewport, in the ball's colour. Returns the view's frame.
AABB framedWithBallsOnScreen(const std::string& name, const client::Box& bounds,
                             const std::vector<Vec2d>& places, const std::string& screenshot) {
  net_test::ServerProcess server({"--paused"});
  client::Client maker(roomMaker(server.port(), name, bounds));
  EXPECT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  for (const Vec2d& place : places) {
    const v1::ServerMessage made =
        maker.request(client::spawnCircle({place.x(), place.y()}, kBallRadius, {.isStatic = true}));
    EXPECT_TRUE(made.command_result().ok()) << made.command_result().error();
  }
  ViewerHarness viewer(server.port(), 1280, 720, {}, name);
  const auto allSeen = [&] {
    return viewer.app().world().bodies().size() == places.size() &&
           viewer.app().view().frame().lower != kPresetScene.lower;
  };
  if (!viewer.runUntil(allSeen)) {
    const AABB frame = viewer.app().view().frame();
    ADD_FAILURE() << "the viewer did not show the room's " << places.size() << " balls, framed; it shows "
                  << viewer.app().world().bodies().size() << " bodies, framed at (" << frame.lower.x() << ", "
                  << frame.lower.y() << ") to (" << frame.upper.x() << ", " << frame.upper.y() << ")";
    return {};
  }
  viewer.runFrames(3);
  auto shot = viewer.capture(screenshotPath(screenshot));
  EXPECT_NE(shot, nullptr) << SDL_GetError();
  const client::WorldMirror& mirror = viewer.app().connection().client()->mirror();
  const viewer::PixelRect scene = viewer.app().layout().scene;
  const float radius = float(kBallRadius) * viewer.app().view().scale();
  for (const Vec2d& place : places) {
    const auto centre = viewer.pixel(mirror.toLocal(place));
    EXPECT_TRUE(scene.contains(centre.x, centre.y))
        << "the ball at (" << place.x() << ", " << place.y() << ") is drawn at pixel (" << centre.x
        << ", " << centre.y << "), off the scene";
    if (shot == nullptr || !scene.contains(centre.x, centre.y)) continue;
    // Below the centre: clear of the rotation mark, which points along +x.
    EXPECT_LE(colourDistance(pixelAt(shot.get(), int(centre.x), int(centre.y + radius / 2)),
                             viewer::bodyFill(Material::Solid, true)),
              8)
        << "the ball at (" << place.x() << ", " << place.y() << ")";
  }
  return viewer.app().view().frame();
}

TEST(FarRoom, ARoom83KmOutOpensFramedOnItsBounds_WithItsBodiesOnScreen) {
  const client::Box bounds{{83000, 0}, {83100, 100}};
  const std::vector<Vec2d> balls{{83012.5, 10}, {83050, 50}, {83088, 90}};
  const AABB frame = framedWithBallsOnScreen("level", bounds, balls, "far_room_framed.bmp");
  // The room's origin is (80 000, 0): its bounds are 3 000 to 3 100 m from it.
  EXPECT_EQ(frame.lower, Vec2(3000, 0));
  EXPECT_EQ(frame.upper, Vec2(3100, 100));
}

TEST(FarRoom, ARoomTooLargeToShowOpensOnItsBodies) {
  const client::Box bounds{{83000, 0}, {93000, 10000}};
  const std::vector<Vec2d> balls{{83012.5, 10}, {83050, 50}, {83088, 90}};
  const AABB frame = framedWithBallsOnScreen("region", bounds, balls, "large_room_framed.bmp");
  // Origin (90 000, 10 000): the balls' centres, grown by the margin.
  const Real margin = viewer::kBodiesAreaMargin;
  EXPECT_NEAR(frame.lower.x(), -6987.5 - margin, 1e-2);
  EXPECT_NEAR(frame.lower.y(), -9990 - margin, 1e-2);
  EXPECT_NEAR(frame.upper.x(), -6912 + margin, 1e-2);
  EXPECT_NEAR(frame.upper.y(), -9910 + margin, 1e-2);
}

/// A room too large to show, whose origin is (90 000, 10 000).
constexpr client::Box kRegionBounds{{83000, 0}, {93000, 10000}};

bool knowsBodies(ViewerHarness& viewer, std::size_t count) {
  return viewer.app().world().bodies().size() == count;
}

TEST(FarRoom, FFramesTheBodiesTheViewerKnowsNow) {
  net_test::ServerProcess server({"--paused"});
  client::Client maker(roomMaker(server.port(), "region", kRegionBounds));
  ASSERT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  const std::vector<Vec2d> balls{{83012.5, 10}, {83050, 50}, {83088, 90}};
  for (const Vec2d& place : balls)
    ASSERT_TRUE(
        maker.request(client::spawnCircle({place.x(), place.y()}, kBallRadius, {.isStatic = true}))
            .command_result()
            .ok());
  ViewerHarness viewer(server.port(), [](viewer::ViewerOptions& options) {
    options.connect.room = "region";
    options.areaMargin.reset();  // --whole-room: the viewer hears of the ball made off the view
  });
  ASSERT_TRUE(viewer.runUntil([&] { return knowsBodies(viewer, 3); }));
  viewer.runFrames(3);
  const client::WorldMirror& mirror = viewer.app().connection().client()->mirror();
  const viewer::PixelRect scene = viewer.app().layout().scene;
  const Vec2d late(84000, 1000);
  ASSERT_TRUE(
      maker.request(client::spawnCircle({late.x(), late.y()}, kBallRadius, {.isStatic = true}))
          .command_result()
          .ok());
  ASSERT_TRUE(viewer.runUntil([&] { return knowsBodies(viewer, 4); }));
  const auto lateAt = [&] { return viewer.pixel(mirror.toLocal(late)); };
  EXPECT_FALSE(scene.contains(lateAt().x, lateAt().y)) << "the ball made later starts off the view";

  viewer.tap(SDLK_f);
  viewer.runFrames(2);
  // The four centres, grown by the margin (origin (90 000, 10 000)).
  const AABB frame = viewer.app().view().frame();
  const Real margin = viewer::kBodiesAreaMargin;
  EXPECT_NEAR(frame.lower.x(), -6987.5 - margin, 1e-2);
  EXPECT_NEAR(frame.lower.y(), -9990 - margin, 1e-2);
  EXPECT_NEAR(frame.upper.x(), -6000 + margin, 1e-2);
  EXPECT_NEAR(frame.upper.y(), -9000 + margin, 1e-2);
  for (const Vec2d& place : {balls[0], balls[1], balls[2], late}) {
    const auto at = viewer.pixel(mirror.toLocal(place));
    EXPECT_TRUE(scene.contains(at.x, at.y))
        << "(" << place.x() << ", " << place.y() << ") off the view";
  }
}

TEST(FarRoom, AfterAZoomFFramesTheBodiesLeftInTheArea_AndTheAreaFollowsTheNewView) {
  net_test::ServerProcess server({"--paused"});
  client::Client maker(roomMaker(server.port(), "region", kRegionBounds));
  ASSERT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  // `near` is 11.5 m from `zoomed`: outside a view 4 m wide plus the 5 m
  // margin (and the half margin the area lags a shrinking view by), inside
  // the preset scene's size around `zoomed`.
  const Vec2d zoomed(83012.5, 10), near(83024, 10), far(83088, 90);
  for (const Vec2d& place : {zoomed, near, far})
    ASSERT_TRUE(maker.request(client::spawnCircle({place.x(), place.y()}, 0.5, {.isStatic = true}))
                    .command_result()
                    .ok());
  ViewerHarness viewer(server.port(), 1280, 720, {}, "region");
  ASSERT_TRUE(viewer.runUntil([&] { return knowsBodies(viewer, 3); }));
  viewer.runFrames(3);
  const client::WorldMirror& mirror = viewer.app().connection().client()->mirror();
  const Vec2 zoomedLocal = mirror.toLocal(zoomed);
  const auto pointer = viewer.pixel(zoomedLocal);
  viewer.mouseMove(pointer.x, pointer.y);
  viewer.runFrames(1);
  for (int notch = 0; notch < 30; ++notch) {
    viewer.wheel(1);
    viewer.runFrames(1);
  }
  const AABB shown = viewer::viewArea(viewer.app().view(), 0);
  ASSERT_LT(shown.upper.x() - shown.lower.x(), 4.f)
      << "the view is not zoomed in enough for the test";
  ASSERT_TRUE(viewer.runUntil([&] { return knowsBodies(viewer, 1); }))
      << "the area did not shrink to the zoomed view; the viewer knows "
      << viewer.app().world().bodies().size();

  viewer.tap(SDLK_f);
  viewer.runFrames(2);
  // The one body known, grown to the preset scene's size around it.
  const AABB frame = viewer.app().view().frame();
  const Vec2 centre = (frame.lower + frame.upper) / 2;
  EXPECT_NEAR(centre.x(), zoomedLocal.x(), 1e-2);
  EXPECT_NEAR(centre.y(), zoomedLocal.y(), 1e-2);
  EXPECT_NEAR(frame.upper.x() - frame.lower.x(), kSceneSize.x(), 1e-2);
  EXPECT_NEAR(frame.upper.y() - frame.lower.y(), kSceneSize.y(), 1e-2);
  // The area sent follows the new view: the near ball comes back, the far one stays out.
  EXPECT_TRUE(viewer.runUntil([&] { return knowsBodies(viewer, 2); }))
      << "the viewer knows " << viewer.app().world().bodies().size() << " bodies after F";
  const auto nearAt = viewer.pixel(mirror.toLocal(near));
  EXPECT_TRUE(viewer.app().layout().scene.contains(nearAt.x, nearAt.y));
}

TEST(FarRoom, TheInspectorShowsAndTakesPositionsFromZero_InDouble) {
  net_test::ServerProcess server({"--paused"});
  client::Client maker(roomMaker(server.port(), "level", {{83000, 0}, {83100, 100}}));
  ASSERT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  const v1::ServerMessage made =
      maker.request(client::spawnCircle({83012.5, 10.25}, kBallRadius, {.isStatic = true}));
  ASSERT_TRUE(made.command_result().ok()) << made.command_result().error();
  const std::uint32_t ball = made.command_result().body_id();

  ViewerHarness viewer(server.port(), 1280, 720, {}, "level");
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().world().find(ball) != nullptr; }));
  const client::WorldMirror& mirror = viewer.app().connection().client()->mirror();
  viewer.tap(SDLK_m);
  viewer.click(mirror.toLocal({83012.5, 10.25}));
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().panelState().poseFields.has_value(); }));
  viewer.runFrames(3);
  const viewer::FieldsEdit& shown = viewer.app().panelState().poseEdit;
  EXPECT_EQ(shown.body, ball);
  EXPECT_EQ(shown.values[0], 83012.5) << "x from (0, 0), not from the room's origin";
  EXPECT_EQ(shown.values[1], 10.25);

  // x is the first of the three fields: a click selects its text, typing replaces it.
  const viewer::PixelRect pose = *viewer.app().panelState().poseFields;
  viewer.clickPixel(pose.x + pose.w / 6, pose.y + pose.h / 2);
  viewer.typeText("83020.125");
  viewer.tap(SDLK_RETURN);
  const auto queried = [&] { return maker.request(client::queryBody(ball)).body_info().state().position(); };
  ASSERT_TRUE(observeUntil(viewer, maker, [&] { return std::abs(queried().x() - 83020.125) < 1e-3; }))
      << "the ball is at x = " << queried().x();
  EXPECT_NEAR(queried().y(), 10.25, 1e-3);
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().panelState().poseEdit.values[0] == 83020.125; }));
}

TEST(FarRoom, APresetLoadedInALevel83KmOutLandsInItsBoundsAndOnScreen) {
  net_test::ServerProcess server({"--paused"});
  const client::Box bounds{{83000, 0}, {83100, 100}};
  client::Client maker(roomMaker(server.port(), "level", bounds));
  ViewerHarness viewer(server.port(), 1280, 720, {}, "level");
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().connection().connected(); }));
  viewer.tap(SDLK_3);  // the polygon tutorial
  const client::WorldMirror& mirror = viewer.app().connection().client()->mirror();
  ASSERT_TRUE(viewer.runUntil([&] {
    return mirror.preset() && mirror.preset()->id == 3 && !viewer.app().world().bodies().empty();
  }));
  viewer.runFrames(3);
  const viewer::PixelRect scene = viewer.app().layout().scene;
  for (const auto& [id, body] : mirror.bodies()) {
    const Vec2d place = mirror.toGlobal(body.state.position);
    EXPECT_TRUE(place.x() >= bounds.min.x && place.x() <= bounds.max.x && place.y() >= bounds.min.y &&
                place.y() <= bounds.max.y)
        << "body " << id << " at (" << place.x() << ", " << place.y() << ")";
    const auto at = viewer.pixel(body.state.position);
    EXPECT_TRUE(scene.contains(at.x, at.y)) << "body " << id << " is drawn at pixel (" << at.x << ", " << at.y
                                            << "), off the scene";
  }
  for (const Marker& marker : mirror.preset()->markers) {
    const auto at = viewer.pixel(marker.center);
    EXPECT_TRUE(scene.contains(at.x, at.y)) << "a marker is drawn at pixel (" << at.x << ", " << at.y << ")";
  }
  EXPECT_NE(viewer.capture(screenshotPath("far_room_preset.bmp")), nullptr) << SDL_GetError();
}

TEST(FarRoom, APresetLoadedInARoomTooLargeToShowIsFramedWhereItLands) {
  net_test::ServerProcess server({"--paused"});
  client::Client maker(roomMaker(server.port(), "region", kRegionBounds));
  ASSERT_TRUE(maker.request(client::clearWorld()).command_result().ok());
  // The room opens on a ball in its corner, 5 km from where a preset lands.
  ASSERT_TRUE(maker.request(client::spawnCircle({83012.5, 10}, kBallRadius, {.isStatic = true}))
                  .command_result()
                  .ok());
  ViewerHarness viewer(server.port(), 1280, 720, {}, "region");
  ASSERT_TRUE(viewer.runUntil([&] { return knowsBodies(viewer, 1); }));
  viewer.tap(SDLK_3);  // the polygon tutorial
  const client::WorldMirror& mirror = viewer.app().connection().client()->mirror();
  // Centred on the bounds' centre (88 000, 5 000), the scene 25 x 18.75 m.
  const auto landed = [&](const client::MirrorBody& body) {
    const Vec2d place = mirror.toGlobal(body.state.position);
    return std::abs(place.x() - 88000) <= 12.5 && std::abs(place.y() - 5000) <= 9.375;
  };
  // Only the area of interest's bodies arrive: the view must have gone there.
  ASSERT_TRUE(viewer.runUntil([&] {
    return mirror.preset() && mirror.preset()->id == 3 && !mirror.bodies().empty() &&
           std::all_of(mirror.bodies().begin(), mirror.bodies().end(), [&](const auto& b) { return landed(b.second); });
  })) << "the viewer holds " << mirror.bodies().size() << " bodies";
  viewer.runFrames(3);
  const viewer::PixelRect scene = viewer.app().layout().scene;
  for (const auto& [id, body] : mirror.bodies()) {
    const auto at = viewer.pixel(body.state.position);
    EXPECT_TRUE(scene.contains(at.x, at.y)) << "body " << id << " is drawn at pixel (" << at.x << ", " << at.y
                                            << "), off the scene";
  }
}

}  // namespace
}  // namespace impulse::viewer_test
