// End to end: synthetic SDL input drives the viewer's window; a separate
// client watches the bodies and gravity arrive at the real server.
#include <gtest/gtest.h>

#include <cmath>

#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using std::chrono::milliseconds;

class InputEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(viewer.runUntil([&] {
      const auto* c = viewer.app().connection().client();
      return c != nullptr && c->mirror().preset().has_value();
    }));
  }

  // Lets the observer catch up with the server until `done` holds.
  bool observe(const std::function<bool()>& done, milliseconds timeout = milliseconds(5000)) {
    return observeUntil(viewer, observer, done, timeout);
  }

  const client::MirrorBody* find(ShapeType type, bool isStatic) {
    for (const auto& [id, body] : observer.mirror().bodies()) {
      if (body.shape.type() == type && body.isStatic == isStatic && id > sceneMaxId) return &body;
    }
    return nullptr;
  }

  net_test::ServerProcess server;  // the sandbox
  ViewerHarness viewer{server.port()};
  client::Client observer{observerOptions(server.port())};
  std::uint32_t sceneMaxId = observer.mirror().bodies().empty()
                                 ? 0
                                 : observer.mirror().bodies().rbegin()->first;
};

TEST_F(InputEndToEnd, DrawsAPolygonAndACircle_TheServerGetsBoth) {
  viewer.tap(SDLK_p);
  ASSERT_EQ(viewer.app().controls().mode(), viewer::DrawMode::Polygon);
  viewer.click(Vec2(8, 8));
  viewer.click(Vec2(10, 8));
  viewer.click(Vec2(9, 8));  // collinear: red, placed nothing
  viewer.click(Vec2(10, 10));
  viewer.click(Vec2(11, 9));  // the closing edge would cross an edge: red, placed nothing
  viewer.click(Vec2(8, 10));
  EXPECT_EQ(viewer.app().controls().placedPoints().size(), 4u);
  viewer.tap(SDLK_p);

  viewer.tap(SDLK_q);     // static
  viewer.tap(SDLK_KP_4);  // METAL
  viewer.tap(SDLK_o);
  const auto centre = viewer.pixel(Vec2(15, 10));
  const auto rim = viewer.pixel(Vec2(16.5f, 10));
  viewer.mouseMove(centre.x, centre.y);
  viewer.mouseButton(centre.x, centre.y, true);
  viewer.app().frame();
  viewer.mouseMove((centre.x + rim.x) / 2, centre.y);
  viewer.app().frame();
  viewer.mouseMove(rim.x, rim.y);
  viewer.mouseButton(rim.x, rim.y, false);
  viewer.app().frame();
  viewer.tap(SDLK_o);

  ASSERT_TRUE(observe([&] {
    return find(ShapeType::Polygon, false) != nullptr && find(ShapeType::Circle, true) != nullptr;
  }));
  const auto* polygon = find(ShapeType::Polygon, false);
  EXPECT_EQ(polygon->shape.polygon().count, 4);
  EXPECT_NEAR(polygon->state.position.x(), 9, 0.1);
  const auto* circle = find(ShapeType::Circle, true);
  EXPECT_NEAR(circle->shape.circle().radius, 1.5, 0.05);
  EXPECT_NEAR(circle->state.position.x(), 15, 0.05);
  EXPECT_NEAR(circle->state.position.y(), 10, 0.05);
  EXPECT_EQ(circle->material, Material::Metal);
  // Both reach the viewer's own picture too.
  ASSERT_TRUE(observe([&] {
    int seen = 0;
    for (const auto& body : viewer.app().world().bodies()) {
      seen += body.state.id == polygon->id.value || body.state.id == circle->id.value;
    }
    return seen == 2;
  }));
}

TEST_F(InputEndToEnd, RefusedShapeShowsTheServersErrorOnScreen) {
  viewer.tap(SDLK_p);
  // Three points a pixel (31 mm) apart: a valid outline, but below the
  // server's minimum area of 10 cm^2.
  const auto p = viewer.pixel(Vec2(12, 12));
  for (const auto& [dx, dy] : {std::pair{0, 0}, {1, 0}, {0, 1}}) {
    viewer.mouseMove(p.x + float(dx), p.y + float(dy));
    viewer.mouseButton(p.x + float(dx), p.y + float(dy), true);
    viewer.mouseButton(p.x + float(dx), p.y + float(dy), false);
    viewer.app().frame();
  }
  ASSERT_EQ(viewer.app().controls().placedPoints().size(), 3u);
  viewer.tap(SDLK_p);
  ASSERT_TRUE(observe([&] {
    const auto notice = viewer.app().controls().notice(viewer.app().now());
    return notice && notice->find("refused") != std::string::npos;
  }));
  EXPECT_EQ(find(ShapeType::Polygon, false), nullptr);
}

TEST_F(InputEndToEnd, GravityKeysNudgeWhileHeld_EnterResets) {
  viewer.key(SDLK_d, true);
  viewer.runFrames(30);  // about half a second
  viewer.key(SDLK_d, false);
  viewer.app().frame();
  ASSERT_TRUE(observe([&] { return observer.mirror().gravity().x() > 1.0f; }));
  const float nudged = observer.mirror().gravity().x();
  // Released: no more nudges.
  viewer.runFrames(20);
  observe([] { return false; }, milliseconds(200));
  EXPECT_NEAR(observer.mirror().gravity().x(), nudged, 0.3);
  viewer.tap(SDLK_RETURN);
  ASSERT_TRUE(observe([&] {
    return observer.mirror().gravity().x() == 0.0f &&
           std::abs(observer.mirror().gravity().y() + 9.81f) < 1e-4f;
  }));
}

TEST_F(InputEndToEnd, PresetKeysLoadScenes_ShiftClearEmptiesTheWorld_DrawingWorksEverywhere) {
  viewer.tap(SDLK_3);
  ASSERT_TRUE(observe([&] { return observer.mirror().preset()->id == 3; }));
  EXPECT_FALSE(viewer.app().controls().panelVisible());
  viewer.tap(SDLK_x);
  EXPECT_TRUE(viewer.app().controls().panelVisible());
  viewer.tap(SDLK_F1);
  ASSERT_TRUE(observe([&] { return observer.mirror().preset()->id == 10; }));
  // The viewer sees preset 10 too, whose text says nothing of drawing:
  // drawing works there as in every scene.
  ASSERT_TRUE(observe([&] {
    const auto* c = viewer.app().connection().client();
    return c->mirror().preset()->id == 10;
  }));
  const std::size_t before = observer.mirror().bodies().size();
  viewer.tap(SDLK_p);
  EXPECT_EQ(viewer.app().controls().mode(), viewer::DrawMode::Polygon);
  for (const Vec2& corner : {Vec2(20, 12), Vec2(22, 12), Vec2(21, 14)}) viewer.click(corner);
  viewer.tap(SDLK_p);
  ASSERT_TRUE(observe([&] { return observer.mirror().bodies().size() == before + 1; }));
  viewer.tap(SDLK_c, KMOD_LSHIFT);
  ASSERT_TRUE(observe([&] { return observer.mirror().bodies().empty(); }));
  viewer.tap(SDLK_0);
  ASSERT_TRUE(observe([&] { return observer.mirror().preset()->id == 0; }));
}

TEST_F(InputEndToEnd, InspectorSelectsABody_ArrowsPushIt) {
  // A ball resting on the sandbox floor.
  client::Client driver(observerOptions(server.port()));
  const auto result = driver.request(client::spawnCircle({12.5, 1.5}, 0.5));
  ASSERT_TRUE(result.command_result().ok()) << result.command_result().error();
  const std::uint32_t id = result.command_result().body_id();
  ASSERT_TRUE(observe([&] {
    for (const auto& body : viewer.app().world().bodies()) {
      if (body.state.id == id) return true;
    }
    return false;
  }));
  viewer.runFrames(30);
  viewer.tap(SDLK_m);
  ASSERT_TRUE(viewer.app().controls().inspectorVisible());
  const auto* ball = observer.mirror().find(BodyId{id});
  ASSERT_NE(ball, nullptr);
  viewer.click(ball->state.position);
  ASSERT_EQ(viewer.app().controls().selectedBody(), id);
  viewer.runFrames(20);  // the body's details (mass) arrive
  const float startX = ball->state.position.x();
  viewer.key(SDLK_RIGHT, true);
  viewer.runFrames(10);
  viewer.key(SDLK_RIGHT, false);
  viewer.app().frame();
  ASSERT_TRUE(observe([&] {
    const auto* b = observer.mirror().find(BodyId{id});
    return b != nullptr && b->state.position.x() > startX + 0.2f;
  }));
}

}  // namespace
}  // namespace impulse::viewer_test
