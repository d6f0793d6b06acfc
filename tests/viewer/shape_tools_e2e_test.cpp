// The capsule, segment and chain tools end to end: synthetic mouse and key
// input draws in the real viewer, an observer checks what the real server
// made. And the kinematic look, checked pixel by pixel in a screenshot
// (kept in <build>/viewer-screenshots).
#include <gtest/gtest.h>

#include <numbers>

#include "palette.h"
#include "server_process.h"
#include "standard_shapes.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using std::chrono::milliseconds;

class ShapeTools : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(observe([&] {
      const auto* c = viewer.app().connection().client();
      return c != nullptr && c->mirror().preset().has_value();
    }));
    for (const auto& [id, body] : observer.mirror().bodies()) sceneIds.push_back(id);
  }
  bool observe(const std::function<bool()>& done, milliseconds timeout = milliseconds(5000)) {
    return observeUntil(viewer, observer, done, timeout);
  }
  /// The first body the scene did not have whose first shape is `type`.
  const client::MirrorBody* drawn(ShapeType type) {
    for (const auto& [id, body] : observer.mirror().bodies()) {
      if (body.shape.type() == type && std::find(sceneIds.begin(), sceneIds.end(), id) == sceneIds.end()) {
        return &body;
      }
    }
    return nullptr;
  }
  /// Left button pressed at `from`, moved to `to` over a few frames, released.
  void drag(const Vec2& from, const Vec2& to) {
    const auto a = viewer.pixel(from);
    viewer.mouseMove(a.x, a.y);
    viewer.mouseButton(a.x, a.y, true);
    viewer.app().frame();
    for (int i = 1; i <= 4; ++i) {
      const auto p = viewer.pixel(from + (to - from) * (Real(i) / 4));
      viewer.mouseMove(p.x, p.y);
      viewer.app().frame();
    }
    const auto b = viewer.pixel(to);
    viewer.mouseButton(b.x, b.y, false);
    viewer.app().frame();
  }
  std::string notice() { return viewer.app().controls().notice(viewer.app().now()).value_or(""); }

  net_test::ServerProcess server{{"--paused"}};  // the sandbox, still: shapes stay where drawn
  ViewerHarness viewer{server.port()};
  client::Client observer{observerOptions(server.port())};
  std::vector<std::uint32_t> sceneIds;
};

TEST_F(ShapeTools, CapsuleDraggedEndToEnd_IsMadeWithTheRadiusSetByTheSizeKeys) {
  viewer.tap(SDLK_r);
  ASSERT_EQ(viewer.app().controls().mode(), viewer::DrawMode::Capsule);
  viewer.tap(SDLK_EQUALS);  // radius 0.25 m -> 0.3125 m
  drag(Vec2(8, 9), Vec2(12, 10));
  // The preview: the capsule's outline in the preview colour around its axis.
  auto preview = viewer.capture(screenshotPath("capsule_preview.bmp"));
  ASSERT_NE(preview, nullptr);
  const auto low = viewer.pixel(Vec2(7.5f, 8.5f)), high = viewer.pixel(Vec2(12.5f, 10.5f));
  const SDL_Rect around{int(low.x), int(high.y), int(high.x - low.x), int(low.y - high.y)};
  const Real radius = viewer::kDefaultCapsuleRadius * viewer::kShapeSizeFactor;
  const Real outlinePixels = (2 * std::hypot(4, 1) + 2 * std::numbers::pi_v<Real> * radius) * viewer.app().view().scale();
  EXPECT_GT(countNear(preview.get(), around, viewer::palette::kPreview, 40), int(outlinePixels / 2));
  viewer.tap(SDLK_r);
  ASSERT_TRUE(observe([&] { return drawn(ShapeType::Capsule) != nullptr; }));
  const client::MirrorBody& body = *drawn(ShapeType::Capsule);
  EXPECT_FALSE(body.isStatic);
  const Capsule& capsule = body.shape.capsule();
  EXPECT_NEAR(capsule.radius, radius, 1e-5);
  // One pixel is about 3 cm at this window size.
  EXPECT_NEAR((capsule.center2 - capsule.center1).norm(), std::hypot(4, 1), 0.06);
  EXPECT_NEAR(body.state.position.x(), 10, 0.04);
  EXPECT_NEAR(body.state.position.y(), 9.5, 0.04);
}

TEST_F(ShapeTools, SegmentDraggedEndToEnd_IsStaticScenery) {
  viewer.tap(SDLK_l);
  drag(Vec2(5, 6), Vec2(14, 4));
  viewer.tap(SDLK_l);
  ASSERT_TRUE(observe([&] { return drawn(ShapeType::Segment) != nullptr; }));
  const client::MirrorBody& body = *drawn(ShapeType::Segment);
  EXPECT_TRUE(body.isStatic);
  const Transform xf{body.state.position, Rot::fromAngle(body.state.angle)};
  const Vec2 from = xf.apply(body.shape.segment().point1);
  const Vec2 to = xf.apply(body.shape.segment().point2);
  EXPECT_NEAR((from - Vec2(5, 6)).norm(), 0, 0.05);
  EXPECT_NEAR((to - Vec2(14, 4)).norm(), 0, 0.05);
}

TEST_F(ShapeTools, ChainClickedLeftToRight_HoldsABallDroppedOnIt) {
  viewer.tap(SDLK_h);
  const std::vector<Vec2> clicks{Vec2(5, 7), Vec2(9, 5), Vec2(12, 5), Vec2(16, 7)};
  for (const Vec2& p : clicks) viewer.click(p);
  ASSERT_EQ(viewer.app().controls().placedPoints().size(), clicks.size());
  viewer.tap(SDLK_h);
  ASSERT_TRUE(observe([&] { return drawn(ShapeType::ChainSegment) != nullptr; }));
  const client::MirrorBody& chain = *drawn(ShapeType::ChainSegment);
  ASSERT_TRUE(observe([&] { return viewer.app().world().bodies().size() == observer.mirror().bodies().size(); }));
  viewer.runFrames(3);
  // A click on its line selects it for the inspector (a chain has no inside).
  viewer.tap(SDLK_m);
  viewer.click(Vec2(10.5f, 5.05f));
  EXPECT_EQ(viewer.app().controls().selectedBody(), chain.id.value);
  viewer.runFrames(20);
  ASSERT_NE(viewer.capture(screenshotPath("chain_drawn.bmp")), nullptr);
  EXPECT_TRUE(chain.isStatic);
  EXPECT_EQ(chain.extraShapes.size() + 1, clicks.size() - 1);  // a segment between each two clicks

  // Solid from above: a ball dropped into the dip comes to rest on it.
  const auto ball = observer.request(client::spawnCircle({10.5, 8}, 0.4, {.restitution = 0}));
  ASSERT_TRUE(ball.command_result().ok()) << ball.command_result().error();
  const BodyId ballId{ball.command_result().body_id()};
  ASSERT_TRUE(observer.request(client::setPaused(false)).command_result().ok());
  ASSERT_TRUE(observe([&] {
    const auto* b = observer.mirror().find(ballId);
    return b != nullptr && observer.mirror().simTime() > 2;
  }, milliseconds(8000)));
  EXPECT_NEAR(observer.mirror().find(ballId)->state.position.y(), 5.4, 0.05);
}

TEST_F(ShapeTools, ClosingAChainThatWouldCross_ShowsTheEnginesMessage_AndMakesNothing) {
  viewer.tap(SDLK_h);
  // A Z: its closing segment would cross the diagonal.
  for (const Vec2& p : {Vec2(6, 6), Vec2(10, 6), Vec2(6, 10), Vec2(10, 10)}) viewer.click(p);
  viewer.tap(SDLK_h, KMOD_SHIFT);
  EXPECT_EQ(notice(), "Chain not closed: " + std::string(describe(ShapeError::ChainCrossing)));
  EXPECT_EQ(viewer.app().controls().mode(), viewer::DrawMode::Chain);
  // A point that would cross the chain drawn so far is not placed.
  viewer.click(Vec2(8, 4));
  EXPECT_EQ(viewer.app().controls().placedPoints().size(), 4u);
  viewer.runFrames(20);
  observer.poll(milliseconds(50));
  EXPECT_EQ(drawn(ShapeType::ChainSegment), nullptr);
}

// Pixels of `area` near `colour`, as a fraction of the area.
double share(SDL_Surface* shot, SDL_Rect area, viewer::Colour colour) {
  return double(countNear(shot, area, colour, 24)) / double(area.w * area.h);
}

TEST_F(ShapeTools, KinematicBodiesAreStriped_UnlikeMovingAndStaticOnes) {
  // Three SOLID boxes side by side: dynamic, kinematic, static.
  const auto spawnBox = [&](double x, client::SpawnOptions options) {
    const std::vector<client::Point> corners{{x - 1, 8}, {x + 1, 8}, {x + 1, 10}, {x - 1, 10}};
    const auto reply = observer.request(client::spawnPolygon(corners, options));
    EXPECT_TRUE(reply.command_result().ok()) << reply.command_result().error();
  };
  spawnBox(7, {});
  spawnBox(12, {.isKinematic = true});
  spawnBox(17, {.isStatic = true});
  ASSERT_TRUE(observe([&] { return viewer.app().world().bodies().size() == observer.mirror().bodies().size() &&
                                   observer.mirror().bodies().size() == sceneIds.size() + 3; }));
  viewer.runFrames(3);
  auto shot = viewer.capture(screenshotPath("kinematic_look.bmp"));
  ASSERT_NE(shot, nullptr);
  // The inside of each box, clear of its outline.
  const auto inside = [&](double x) {
    const auto low = viewer.pixel(Vec2(Real(x - 0.8), Real(8.2)));
    const auto high = viewer.pixel(Vec2(Real(x + 0.8), Real(9.8)));
    return SDL_Rect{int(low.x), int(high.y), int(high.x - low.x), int(low.y - high.y)};
  };
  const viewer::Colour fill = viewer::bodyFill(Material::Solid, false);
  const viewer::Colour stripe = viewer::bodyOutline(Material::Solid, false, false);
  const viewer::Colour scenery = viewer::bodyFill(Material::Solid, true);
  // Kinematic: the material's own fill, crossed by stripes in the outline colour.
  EXPECT_GT(share(shot.get(), inside(12), fill), 0.4);
  EXPECT_GT(share(shot.get(), inside(12), stripe), 0.15);
  // Moving: the same fill, no stripes (its rotation mark is one thin line).
  EXPECT_GT(share(shot.get(), inside(7), fill), 0.85);
  EXPECT_LT(share(shot.get(), inside(7), stripe), 0.06);
  // Static: dark scenery, neither the fill nor the stripes.
  EXPECT_GT(share(shot.get(), inside(17), scenery), 0.95);
  EXPECT_EQ(share(shot.get(), inside(17), fill), 0);
}

}  // namespace
}  // namespace impulse::viewer_test
