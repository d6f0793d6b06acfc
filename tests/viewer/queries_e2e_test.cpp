// Queries, filters and events in the viewer, end to end against the real
// server: the ray tool's hit (through a sensor, which queries never see)
// with its normal arrow, a sensor drawn see-through, the flashes of a hit
// and of a sensor that fired, and the inspector's flag check boxes.
// Screenshots go to viewer-screenshots/.
#include <gtest/gtest.h>

#include <cmath>

#include "palette.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using Shot = std::unique_ptr<SDL_Surface, void (*)(SDL_Surface*)>;

// A box of half extents (hx, hy) centred on (x, y), as spawnPolygon takes it.
std::vector<client::Point> box(double x, double y, double hx, double hy) {
  return {{x - hx, y - hy}, {x + hx, y - hy}, {x + hx, y + hy}, {x - hx, y + hy}};
}

client::SpawnOptions staticSensor() {
  client::SpawnOptions options;
  options.isStatic = true;
  options.flags.isSensor = true;
  return options;
}

// A viewer and an observer on one server started with `args`.
class Scene {
 public:
  explicit Scene(std::vector<std::string> args, int height = 720)
      : server(std::move(args)),
        viewer(server.port(), 1280, height),
        observer(observerOptions(server.port())) {}

  /// Spawns with the observer and waits until the viewer draws the body.
  std::uint32_t spawn(const v1::ClientMessage& message) {
    const auto reply = observer.request(message);
    EXPECT_TRUE(reply.command_result().ok()) << reply.command_result().error();
    const std::uint32_t id = reply.command_result().body_id();
    EXPECT_TRUE(observe([&] { return viewer.app().world().findDrawn(id) != nullptr; }));
    return id;
  }
  bool observe(const std::function<bool()>& done,
               std::chrono::milliseconds timeout = std::chrono::milliseconds(5000)) {
    return observeUntil(viewer, observer, done, timeout);
  }
  /// Presses at `from`, moves to `to` over a few frames and releases there.
  void drag(const Vec2& from, const Vec2& to) {
    const auto a = viewer.pixel(from);
    viewer.mouseMove(a.x, a.y);
    viewer.mouseButton(a.x, a.y, true);
    constexpr int kSteps = 6;
    for (int i = 1; i <= kSteps; ++i) {
      const auto p = viewer.pixel(from + (to - from) * (Real(i) / Real(kSteps)));
      viewer.mouseMove(p.x, p.y);
      viewer.runFrames(1);
    }
    const auto b = viewer.pixel(to);
    viewer.mouseButton(b.x, b.y, false);
    viewer.runFrames(1);
  }
  /// Pixels within `tolerance` of `colour` in a square of `half` pixels about `world`.
  int near(SDL_Surface* shot, const Vec2& world, int half, viewer::Colour colour, int tolerance) {
    const auto p = viewer.pixel(world);
    return countNear(shot, {int(p.x) - half, int(p.y) - half, 2 * half, 2 * half}, colour,
                     tolerance);
  }

  net_test::ServerProcess server;
  ViewerHarness viewer;
  client::Client observer;
};

TEST(RayToolE2E, DraggedRayHitsTheBoxThroughASensor_NormalArrowAndSensorDrawn) {
  Scene scene({"--paused"});
  const std::uint32_t target =
      scene.spawn(client::spawnPolygon(box(6, 3, 1, 0.5), {.isStatic = true}));
  const std::uint32_t sensor = scene.spawn(client::spawnPolygon(box(6, 6, 1.5, 1), staticSensor()));
  ASSERT_TRUE(scene.viewer.app().world().findDrawn(sensor)->look->flags.isSensor);

  scene.viewer.tap(SDLK_e);
  ASSERT_EQ(scene.viewer.app().controls().mode(), viewer::DrawMode::Ray);
  scene.drag(Vec2(6, 9), Vec2(6, 1));
  const viewer::RayTool& ray = scene.viewer.app().controls().rayTool();
  ASSERT_TRUE(scene.viewer.runUntil([&] {
    return ray.answer() && ray.aimed() && ray.answer()->ray == *ray.aimed() && !ray.inFlight();
  }));
  ASSERT_TRUE(ray.answer()->hit) << "the ray missed";
  const viewer::RayHit hit = *ray.answer()->hit;
  EXPECT_EQ(hit.body, target);  // the sensor on the way is not seen
  // The drag's ends are whole pixels: the ray runs within a pixel of x = 6.
  const viewer::Ray& cast = ray.answer()->ray;
  EXPECT_NEAR(hit.point.y(), 3.5, 1e-3);
  EXPECT_NEAR(hit.point.x(), 6, 0.05);
  EXPECT_NEAR(hit.normal.y(), 1, 1e-6);
  EXPECT_NEAR(hit.fraction, (cast.origin.y() - 3.5) / (cast.origin.y() - cast.end.y()), 1e-4);

  const Shot shot = scene.viewer.capture(screenshotPath("ray_tool_hit.bmp"));
  ASSERT_NE(shot, nullptr);
  // The normal arrow stands on the hit point, in the hit colour; the hit
  // box's outline is in it too, at its far corner from the ray.
  const float metre = scene.viewer.app().view().scale();
  EXPECT_GT(
      scene.near(shot.get(), hit.point + Vec2(0, 20 / metre), 4, viewer::palette::kRayHit, 40), 8);
  EXPECT_GT(scene.near(shot.get(), Vec2(7, 2.5), 3, viewer::palette::kRayHit, 40), 3);
  // The sensor is see-through: neither its material's white nor the empty
  // scene, and its edge is dashed (white and background pixels alternate).
  const auto inside = scene.viewer.pixel(Vec2(5, 6.5));
  const viewer::Colour fill = pixelAt(shot.get(), int(inside.x), int(inside.y));
  EXPECT_GT(colourDistance(fill, viewer::palette::kSceneBackground), 20);
  EXPECT_GT(colourDistance(fill, viewer::materialColour(Material::Solid)), 100);
  const auto top = scene.viewer.pixel(Vec2(4.5, 7));
  int edgePixels = 0;
  const int span = int(2.5 * metre);
  for (int x = int(top.x) + 2; x < int(top.x) + span; ++x) {
    edgePixels += colourDistance(pixelAt(shot.get(), x, int(std::lround(top.y))),
                                 viewer::palette::kSceneBackground) > 90;
  }
  EXPECT_GT(edgePixels, span / 3);
  EXPECT_LT(edgePixels, span * 9 / 10);

  scene.viewer.tap(SDLK_e);
  EXPECT_FALSE(scene.viewer.app().controls().rayTool().answer());
}

TEST(EventFlashesE2E, AHardLandingInASensorFlashesTheHitAndTheSensor) {
  Scene scene({});
  const std::uint32_t sensor =
      scene.spawn(client::spawnPolygon(box(12, 1.6, 1.5, 0.8), staticSensor()));
  scene.viewer.tap(SDLK_n);
  ASSERT_TRUE(scene.viewer.app().controls().overlays().eventFlashes);
  client::SpawnOptions ball;
  ball.flags.enableHitEvents = true;
  scene.spawn(client::spawnCircle({12, 6}, 0.4, ball));

  const viewer::EventFlashes& flashes = scene.viewer.app().flashes();
  const auto showing = [&](viewer::Flash::Kind kind) {
    for (const viewer::Flash& flash : flashes.flashes()) {
      if (flash.kind == kind &&
          viewer::EventFlashes::intensity(flash, scene.viewer.app().now()) > 0.8f)
        return &flash;
    }
    return static_cast<const viewer::Flash*>(nullptr);
  };
  ASSERT_TRUE(scene.observe([&] { return showing(viewer::Flash::Kind::Hit) != nullptr; }));
  const viewer::Flash hit = *showing(viewer::Flash::Kind::Hit);
  const Shot shot = scene.viewer.capture(screenshotPath("event_flashes.bmp"));
  ASSERT_NE(shot, nullptr);
  // The ball lands on the floor (its top at 0.78 m) at about 9 m/s.
  EXPECT_NEAR(hit.point.x(), 12, 0.05);
  EXPECT_NEAR(hit.point.y(), 0.78, 0.1);
  EXPECT_GT(hit.speed, 6);
  EXPECT_GT(scene.near(shot.get(), hit.point, 24, viewer::palette::kHitFlash, 60), 10);
  // The sensor fired as the ball came in, a moment earlier.
  bool sensorFlashed = false;
  for (const viewer::Flash& flash : flashes.flashes()) {
    sensorFlashed |= flash.kind == viewer::Flash::Kind::SensorBegin && flash.body == sensor;
  }
  EXPECT_TRUE(sensorFlashed);

  // Off: the flashes go, and a second landing makes none.
  scene.viewer.tap(SDLK_n);
  EXPECT_TRUE(flashes.flashes().empty());
  scene.spawn(client::spawnCircle({8, 5}, 0.4, ball));
  scene.observe([] { return false; }, std::chrono::milliseconds(1500));
  EXPECT_TRUE(flashes.flashes().empty());
}

TEST(InspectorFlags, AClickOnHitEventsSetsThem_TheOthersStay) {
  // Tall enough for the whole inspector: its check boxes come last.
  Scene scene({"--paused"}, 1100);
  const std::uint32_t id = scene.spawn(client::spawnPolygon(box(8, 8, 1, 1)));
  scene.viewer.tap(SDLK_m);
  scene.viewer.click(Vec2(8, 8));
  const auto& boxes = scene.viewer.app().panelState().flagBoxes;
  ASSERT_TRUE(scene.viewer.runUntil([&] { return boxes[3].has_value(); }));
  scene.viewer.runFrames(2);
  const Shot shot = scene.viewer.capture(screenshotPath("inspector_flags.bmp"));
  ASSERT_NE(shot, nullptr);
  EXPECT_FALSE(scene.observer.mirror().find(BodyId{id})->flags.enableHitEvents);
  const viewer::PixelRect hitEvents = *boxes[3];
  scene.viewer.clickPixel(hitEvents.x + hitEvents.h / 2, hitEvents.y + hitEvents.h / 2);
  ASSERT_TRUE(scene.observe([&] {
    const auto* body = scene.observer.mirror().find(BodyId{id});
    return body != nullptr && body->flags.enableHitEvents;
  }));
  const ShapeInteraction flags = scene.observer.mirror().find(BodyId{id})->flags;
  EXPECT_FALSE(flags.isSensor);
  EXPECT_FALSE(flags.enableContactEvents);
  EXPECT_TRUE(flags.enableSensorEvents);
}

}  // namespace
}  // namespace impulse::viewer_test
