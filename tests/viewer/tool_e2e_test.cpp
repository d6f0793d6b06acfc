// The viewer as a tool, end to end against the real server: panels beside
// the playfield, readable materials, time keys, hands (drag, throw, remove),
// Esc's order, C keeping the scenery, zoom and pan, debug overlays, live
// plots, an unreachable server named. Screenshots go to viewer-screenshots/.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "palette.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using std::chrono::milliseconds;
using Shot = std::unique_ptr<SDL_Surface, void (*)(SDL_Surface*)>;

// A viewer and an observer on one server started with `args`.
class Tool {
 public:
  explicit Tool(std::vector<std::string> args, int width = 1280, int height = 720)
      : server(std::move(args)), viewer(server.port(), width, height),
        observer(observerOptions(server.port())) {}

  /// Waits until the viewer draws every body the server has.
  bool showsEveryBody() {
    return observe([&] {
      const auto* c = viewer.app().connection().client();
      return c != nullptr && !observer.mirror().bodies().empty() &&
             viewer.app().world().bodies().size() == observer.mirror().bodies().size();
    });
  }
  bool observe(const std::function<bool()>& done, milliseconds timeout = milliseconds(5000)) {
    return observeUntil(viewer, observer, done, timeout);
  }
  std::uint32_t spawn(const v1::ClientMessage& message) {
    const auto reply = observer.request(message);
    EXPECT_TRUE(reply.command_result().ok()) << reply.command_result().error();
    const std::uint32_t id = reply.command_result().body_id();
    EXPECT_TRUE(observe([&] { return viewer.app().world().bodies().size() ==
                                     observer.mirror().bodies().size() &&
                                     observer.mirror().find(BodyId{id}) != nullptr; }));
    return id;
  }
  const client::MirrorBody* body(std::uint32_t id) { return observer.mirror().find(BodyId{id}); }
  std::size_t staticCount() {
    std::size_t count = 0;
    for (const auto& [id, b] : observer.mirror().bodies()) count += b.isStatic;
    return count;
  }
  /// Presses the left button at `from`, moves to `to` in `steps` frames, keeps holding.
  void dragTo(const Vec2& from, const Vec2& to, int steps) {
    const auto a = viewer.pixel(from);
    viewer.mouseMove(a.x, a.y);
    viewer.mouseButton(a.x, a.y, true);
    viewer.app().frame();
    for (int i = 1; i <= steps; ++i) {
      const auto p = viewer.pixel(from + (to - from) * (Real(i) / Real(steps)));
      viewer.mouseMove(p.x, p.y);
      observe([] { return false; }, milliseconds(16));
    }
  }

  net_test::ServerProcess server;
  ViewerHarness viewer;
  client::Client observer;
};

// Pixels of the scene viewport that differ between two shots.
int differingPixels(SDL_Surface* a, SDL_Surface* b, SDL_Rect area) {
  int count = 0;
  for (int y = area.y; y < area.y + area.h; ++y) {
    for (int x = area.x; x < area.x + area.w; ++x) {
      count += colourDistance(pixelAt(a, x, y), pixelAt(b, x, y)) > 0;
    }
  }
  return count;
}

SDL_Rect rect(const viewer::PixelRect& r) { return {int(r.x), int(r.y), int(r.w), int(r.h)}; }

// Half way to the rim, across from the rotation mark.
viewer::Colour fillPixel(SDL_Surface* shot, const viewer::ViewTransform& view,
                         const viewer::DrawnBody& body) {
  const float r = body.look->shape.circle().radius * view.scale();
  const auto c = view.toPixels(body.state.position);
  const float a = body.state.angle;
  return pixelAt(shot, int(std::lround(c.x + 0.5f * r * std::sin(a))),
                 int(std::lround(c.y + 0.5f * r * std::cos(a))));
}

class PanelsBesideThePlayfield : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(PanelsBesideThePlayfield, NothingOfThePanelsIsDrawnInsideTheScene) {
  const auto [width, height] = GetParam();
  // Preset 5, paused: its collision happened under the old stats line.
  Tool tool({"--paused", "--preset", "5"}, width, height);
  ASSERT_TRUE(tool.showsEveryBody());
  auto& viewer = tool.viewer;
  viewer.tap(SDLK_x);  // controls hidden: the quietest panel
  ASSERT_FALSE(viewer.app().controls().panelVisible());
  viewer.runFrames(3);
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  Shot quiet = viewer.capture(screenshotPath("panels_quiet_" + size + ".bmp"));
  // Everything the panel can show at once: controls, inspector, a notice.
  viewer.tap(SDLK_x);
  viewer.tap(SDLK_m);
  viewer.tap(SDLK_p);
  viewer.tap(SDLK_p);  // a polygon of no points: cancelled, with a notice
  ASSERT_TRUE(viewer.app().controls().notice(viewer.app().now()));
  viewer.runFrames(3);
  Shot busy = viewer.capture(screenshotPath("panels_busy_" + size + ".bmp"));
  ASSERT_NE(quiet, nullptr);
  ASSERT_NE(busy, nullptr);

  const auto layout = viewer.app().layout();
  EXPECT_EQ(differingPixels(quiet.get(), busy.get(), rect(layout.scene)), 0);
  // The panel did change, beside the scene.
  EXPECT_GT(differingPixels(quiet.get(), busy.get(), rect(layout.panel)), 2000);
  // The scene fits its viewport: the whole 25 m x 18.75 m inside it, touching two sides.
  const auto view = viewer.app().view();
  EXPECT_GE(view.left(), layout.scene.x - 0.5f);
  EXPECT_LE(view.left() + view.width(), layout.scene.x + layout.scene.w + 0.5f);
  EXPECT_GE(view.top(), -0.5f);
  EXPECT_LE(view.top() + view.height(), layout.scene.h + 0.5f);
}

INSTANTIATE_TEST_SUITE_P(WindowSizes, PanelsBesideThePlayfield,
                         ::testing::Values(std::make_pair(1280, 720), std::make_pair(800, 600)));

TEST(Materials, EachBallOfTheRestitutionPresetHasItsOwnDistinctColour) {
  Tool tool({"--paused", "--preset", "10"});
  ASSERT_TRUE(tool.showsEveryBody());
  tool.viewer.runFrames(3);
  Shot shot = tool.viewer.capture(screenshotPath("materials_preset10.bmp"));
  ASSERT_NE(shot, nullptr);
  const auto view = tool.viewer.app().view();
  std::vector<viewer::Colour> seen;
  std::set<Material> materials;
  for (const viewer::DrawnBody& body : tool.viewer.app().world().bodies()) {
    if (body.look->isStatic) continue;
    const viewer::Colour colour = fillPixel(shot.get(), view, body);
    EXPECT_LE(colourDistance(colour, viewer::bodyFill(body.look->material, false)), 8);
    seen.push_back(colour);
    materials.insert(body.look->material);
  }
  ASSERT_EQ(materials.size(), 5u);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    for (std::size_t j = i + 1; j < seen.size(); ++j) {
      EXPECT_GE(colourDistance(seen[i], seen[j]), 40) << i << " vs " << j;
    }
  }
}

TEST(Materials, SleepingBodiesKeepTheirFillAndGetTheSleepOutline) {
  // The crowd's weightless balls fall asleep where they float.
  Tool tool({"--preset", "8"});
  ASSERT_TRUE(tool.viewer.runUntil([&] {
    int asleep = 0;
    for (const auto& body : tool.viewer.app().world().bodies()) {
      asleep += !body.look->isStatic && !body.state.awake;
    }
    return asleep >= 3;
  }));
  Shot shot = tool.viewer.capture(screenshotPath("sleeping_crowd.bmp"));
  ASSERT_NE(shot, nullptr);
  const auto view = tool.viewer.app().view();
  int checked = 0;
  for (const viewer::DrawnBody& body : tool.viewer.app().world().bodies()) {
    if (body.look->isStatic || body.state.awake) continue;
    ++checked;
    // A sleeping SOLID ball is SOLID's white, never METAL's grey.
    EXPECT_LE(colourDistance(fillPixel(shot.get(), view, body),
                             viewer::bodyFill(body.look->material, false)),
              8);
    const float r = body.look->shape.circle().radius * view.scale();
    const auto c = view.toPixels(body.state.position);
    const SDL_Rect box{int(c.x - r - 2), int(c.y - r - 2), int(2 * r + 4), int(2 * r + 4)};
    EXPECT_GT(countNear(shot.get(), box, viewer::palette::kSleep, 40), int(3 * r)) << r;
  }
  EXPECT_GE(checked, 3);
}

TEST(TimeKeys, SpacePausesAndResumes_DotStepsOneTick) {
  Tool tool({});
  ASSERT_TRUE(tool.showsEveryBody());
  tool.viewer.tap(SDLK_SPACE);
  ASSERT_TRUE(tool.observe([&] { return tool.observer.mirror().paused(); }));
  // The viewer shows the state it is in.
  ASSERT_TRUE(tool.observe([&] { return tool.viewer.app().connection().client()->mirror().paused(); }));
  const std::uint64_t tick = tool.observer.mirror().tick();
  tool.viewer.tap(SDLK_PERIOD);
  ASSERT_TRUE(tool.observe([&] { return tool.observer.mirror().tick() == tick + 1; }));
  tool.viewer.runFrames(10);
  EXPECT_EQ(tool.observer.mirror().tick(), tick + 1);
  tool.viewer.tap(SDLK_SPACE);
  ASSERT_TRUE(tool.observe([&] {
    return !tool.observer.mirror().paused() && tool.observer.mirror().tick() > tick + 10;
  }));
}

TEST(Hands, LeftDragCarriesABodyToTheCursor_ReleaseThrowsIt) {
  Tool tool({});
  ASSERT_TRUE(tool.showsEveryBody());
  const std::uint32_t id = tool.spawn(client::spawnCircle({8, 1.5}, 0.5));
  tool.viewer.runFrames(20);
  const Vec2 start = tool.body(id)->state.position;
  const Vec2 target(12, 7);
  tool.dragTo(start, target, 20);
  ASSERT_EQ(tool.viewer.app().controls().grabbedBody(), id);
  // Held there against gravity.
  ASSERT_TRUE(tool.observe([&] { return (tool.body(id)->state.position - target).norm() < 0.4f; }));
  tool.observe([] { return false; }, milliseconds(300));
  EXPECT_LT((tool.body(id)->state.position - target).norm(), 0.4f);
  Shot shot = tool.viewer.capture(screenshotPath("drag.bmp"));
  ASSERT_NE(shot, nullptr);
  // The grabbed body is outlined in the selection colour.
  const auto c = tool.viewer.pixel(tool.viewer.app().world().bodies().back().state.position);
  EXPECT_GT(countNear(shot.get(), {int(c.x) - 25, int(c.y) - 25, 50, 50},
                      viewer::palette::kSelection, 40), 20);

  // A quick flick to the right, then let go: the body flies on.
  const Vec2 flick = target + Vec2(3, 0);
  for (int i = 1; i <= 4; ++i) {
    const auto p = tool.viewer.pixel(target + (flick - target) * (Real(i) / 4));
    tool.viewer.mouseMove(p.x, p.y);
    tool.observe([] { return false; }, milliseconds(16));
  }
  const auto p = tool.viewer.pixel(flick);
  tool.viewer.mouseButton(p.x, p.y, false);
  tool.viewer.app().frame();
  EXPECT_FALSE(tool.viewer.app().controls().grabbedBody());
  ASSERT_TRUE(tool.observe([&] { return tool.body(id)->state.linearVelocity.x() > 2; },
                           milliseconds(1000)));
  // The drag's mouse joint went with the release.
  EXPECT_TRUE(tool.observe([&] { return tool.observer.mirror().joints().empty(); }));
  const Real releasedX = tool.body(id)->state.position.x();
  ASSERT_TRUE(tool.observe([&] { return tool.body(id)->state.position.x() > releasedX + 0.5f; }));
}

TEST(Joints, SpringsRodsAndPinsAreDrawnInTheJointColour) {
  Tool tool({"--paused"});
  ASSERT_TRUE(tool.showsEveryBody());
  const std::uint32_t anchor = tool.spawn(client::spawnCircle({6, 9}, 0.3, {.isStatic = true}));
  const std::uint32_t bob = tool.spawn(client::spawnCircle({6, 4}, 0.5));
  const std::uint32_t swing = tool.spawn(client::spawnCircle({14, 4}, 0.5));
  v1::DistanceJoint spring;
  spring.set_stiffness(200);
  ASSERT_TRUE(tool.observer.request(client::distanceJoint({anchor, bob, {6, 9}, {6, 4}, false},
                                                          spring)).command_result().ok());
  ASSERT_TRUE(tool.observer.request(client::revoluteJoint({swing, 0, {14, 9}, {14, 9}, false},
                                                          {})).command_result().ok());
  ASSERT_TRUE(tool.observe([&] {
    const auto* c = tool.viewer.app().connection().client();
    return c != nullptr && c->mirror().joints().size() == 2;
  }));
  tool.viewer.runFrames(5);
  Shot shot = tool.viewer.capture(screenshotPath("joints_spring_and_pin.bmp"));
  ASSERT_NE(shot, nullptr);
  // The spring's zig-zag between the anchor and the bob, and the pin's ring.
  const auto top = tool.viewer.pixel(Vec2(6, 8.5f));
  const auto bottom = tool.viewer.pixel(Vec2(6, 4.5f));
  const SDL_Rect springArea{int(top.x) - 12, int(top.y), 24, int(bottom.y - top.y)};
  EXPECT_GT(countNear(shot.get(), springArea, viewer::palette::kJoint, 40), 40);
  const auto pin = tool.viewer.pixel(Vec2(14, 9));
  EXPECT_GT(countNear(shot.get(), {int(pin.x) - 6, int(pin.y) - 6, 12, 12},
                      viewer::palette::kJoint, 40), 8);
}

// The joint presets as the viewer shows them: each draws its joints.
TEST(Joints, EachJointPresetIsDrawnWithItsJoints) {
  for (const int preset : {11, 12, 13, 14}) {
    SCOPED_TRACE(preset);
    Tool tool({"--paused", "--preset", std::to_string(preset)});
    ASSERT_TRUE(tool.showsEveryBody());
    ASSERT_TRUE(tool.observe([&] {
      const auto* c = tool.viewer.app().connection().client();
      return c != nullptr && !c->mirror().joints().empty();
    }));
    tool.viewer.runFrames(5);
    Shot shot = tool.viewer.capture(screenshotPath("preset" + std::to_string(preset) + ".bmp"));
    ASSERT_NE(shot, nullptr);
    const auto scene = tool.viewer.app().layout().scene;
    EXPECT_GT(countNear(shot.get(), {int(scene.x), int(scene.y), int(scene.w), int(scene.h)},
                        viewer::palette::kJoint, 30),
              40);
  }
}

TEST(Hands, RightClickAndDeleteRemoveTheBodyUnderTheCursor) {
  Tool tool({});
  ASSERT_TRUE(tool.showsEveryBody());
  const std::size_t scenery = tool.staticCount();
  const std::uint32_t first = tool.spawn(client::spawnCircle({6, 1.5}, 0.5));
  const std::uint32_t second = tool.spawn(client::spawnCircle({14, 1.5}, 0.5));
  tool.viewer.runFrames(10);
  const auto a = tool.viewer.pixel(tool.body(first)->state.position);
  tool.viewer.mouseMove(a.x, a.y);
  tool.viewer.mouseButton(a.x, a.y, true, SDL_BUTTON_RIGHT);
  tool.viewer.app().frame();
  tool.viewer.mouseButton(a.x, a.y, false, SDL_BUTTON_RIGHT);
  ASSERT_TRUE(tool.observe([&] { return tool.body(first) == nullptr; }));
  const auto b = tool.viewer.pixel(tool.body(second)->state.position);
  tool.viewer.mouseMove(b.x, b.y);
  tool.viewer.app().frame();
  tool.viewer.tap(SDLK_DELETE);
  ASSERT_TRUE(tool.observe([&] { return tool.body(second) == nullptr; }));
  EXPECT_EQ(tool.staticCount(), scenery);
}

TEST(Keys, EscCancelsTheDrawingFirst_QuitsOnlyWhenNothingIsInProgress) {
  Tool tool({});
  ASSERT_TRUE(tool.showsEveryBody());
  tool.viewer.tap(SDLK_p);
  tool.viewer.click(Vec2(8, 8));
  ASSERT_EQ(tool.viewer.app().controls().placedPoints().size(), 1u);
  tool.viewer.key(SDLK_ESCAPE, true);
  EXPECT_TRUE(tool.viewer.app().frame());
  tool.viewer.key(SDLK_ESCAPE, false);
  EXPECT_TRUE(tool.viewer.app().frame());
  EXPECT_EQ(tool.viewer.app().controls().mode(), viewer::DrawMode::None);
  tool.viewer.key(SDLK_ESCAPE, true);
  EXPECT_FALSE(tool.viewer.app().frame());
}

TEST(Keys, ClearRemovesWhatTheUserMadeAndKeepsTheScenery_ShiftClearEverything) {
  Tool tool({});
  ASSERT_TRUE(tool.showsEveryBody());
  const std::size_t scenery = tool.staticCount();
  ASSERT_GT(scenery, 0u);
  // A static polygon drawn in the viewer, and a ball from another client.
  auto& viewer = tool.viewer;
  viewer.tap(SDLK_q);
  viewer.tap(SDLK_KP_3);  // WOOD
  viewer.tap(SDLK_p);
  for (const Vec2& p : {Vec2(9, 5), Vec2(13, 5), Vec2(13, 7), Vec2(10, 8)}) viewer.click(p);
  viewer.mouseMove(viewer.pixel(Vec2(9, 7.5f)).x, viewer.pixel(Vec2(9, 7.5f)).y);
  viewer.runFrames(2);
  Shot drawing = viewer.capture(screenshotPath("sandbox_polygon_drawing.bmp"));
  ASSERT_NE(drawing, nullptr);
  // The cursor dot is green: one more point there keeps the polygon convex.
  const auto cursor = viewer.pixel(Vec2(9, 7.5f));
  EXPECT_GT(countNear(drawing.get(), {int(cursor.x) - 3, int(cursor.y) - 3, 7, 7},
                      viewer::palette::kValid, 30), 15);
  viewer.tap(SDLK_p);
  tool.spawn(client::spawnCircle({4, 1.5}, 0.5));
  ASSERT_TRUE(tool.observe([&] { return tool.staticCount() == scenery + 1; }));
  viewer.tap(SDLK_q);
  viewer.runFrames(10);
  Shot made = viewer.capture(screenshotPath("sandbox_polygon.bmp"));
  ASSERT_NE(made, nullptr);
  const auto inside = viewer.pixel(Vec2(11.5f, 6));
  EXPECT_LE(colourDistance(pixelAt(made.get(), int(inside.x), int(inside.y)),
                           viewer::bodyFill(Material::Wood, true)), 8);

  viewer.tap(SDLK_c);
  ASSERT_TRUE(tool.observe([&] {
    return tool.observer.mirror().bodies().size() == scenery && tool.staticCount() == scenery;
  }));
  viewer.tap(SDLK_c, KMOD_LSHIFT);
  ASSERT_TRUE(tool.observe([&] { return tool.observer.mirror().bodies().empty(); }));
}

TEST(View, WheelZoomsAtTheCursor_RightDragPans_FRefits) {
  Tool tool({"--paused"});
  ASSERT_TRUE(tool.showsEveryBody());
  auto& viewer = tool.viewer;
  const float fitted = viewer.app().view().scale();
  const auto p = viewer.pixel(Vec2(5, 3));
  viewer.mouseMove(p.x, p.y);
  viewer.wheel(3);
  viewer.runFrames(2);
  const auto zoomed = viewer.app().view();
  EXPECT_NEAR(zoomed.scale(), fitted * std::pow(1.15f, 3), 1e-3);
  const Vec2 under = zoomed.toWorld(p.x, p.y);
  EXPECT_NEAR(under.x(), 5, 0.05);
  EXPECT_NEAR(under.y(), 3, 0.05);

  const std::size_t bodies = tool.observer.mirror().bodies().size();
  viewer.mouseButton(p.x, p.y, true, SDL_BUTTON_RIGHT);
  for (int i = 1; i <= 5; ++i) {
    viewer.mouseMove(p.x + float(i * 20), p.y);
    viewer.app().frame();
  }
  viewer.mouseButton(p.x + 100, p.y, false, SDL_BUTTON_RIGHT);
  viewer.runFrames(2);
  EXPECT_NEAR(viewer.app().view().left(), zoomed.left() + 100, 1);
  viewer.runFrames(10);
  EXPECT_EQ(tool.observer.mirror().bodies().size(), bodies);  // a pan removes nothing

  viewer.tap(SDLK_f);
  EXPECT_FLOAT_EQ(viewer.app().view().scale(), fitted);
}

TEST(DebugOverlays, ContactsBoundsAndVelocitiesAreDrawnWhereTheBodiesAre) {
  Tool tool({});
  ASSERT_TRUE(tool.showsEveryBody());
  const std::uint32_t resting = tool.spawn(client::spawnCircle({8, 1.5}, 0.5));
  ASSERT_TRUE(tool.observe([&] { return !tool.body(resting)->state.awake; }, milliseconds(8000)));
  ASSERT_TRUE(tool.observer.request(client::setPaused(true)).command_result().ok());
  client::SpawnOptions moving;
  moving.ignoreGravity = true;
  moving.velocityX = 4;
  const std::uint32_t flying = tool.spawn(client::spawnCircle({16, 9}, 0.5, moving));
  auto& viewer = tool.viewer;
  viewer.tap(SDLK_k);
  viewer.tap(SDLK_b);
  viewer.tap(SDLK_v);
  viewer.runFrames(10);
  Shot shot = viewer.capture(screenshotPath("debug_overlays.bmp"));
  ASSERT_NE(shot, nullptr);

  // The resting ball touches the floor under its centre.
  const Vec2 ball = tool.body(resting)->state.position;
  const auto& contacts = viewer.app().shownContacts();
  ASSERT_FALSE(contacts.empty());
  bool underBall = false;
  for (const auto& c : contacts) underBall |= std::abs(c.point.x() - ball.x()) < 0.05f &&
                                              std::abs(c.point.y() - (ball.y() - 0.5f)) < 0.05f;
  EXPECT_TRUE(underBall);
  const auto foot = viewer.pixel(ball - Vec2(0, 0.5f));
  EXPECT_GT(countNear(shot.get(), {int(foot.x) - 4, int(foot.y) - 4, 9, 9},
                      viewer::palette::kContact, 40), 10);
  // Its bounding box: a green square around the ball.
  const auto topLeft = viewer.pixel(ball + Vec2(-0.5f, 0.5f));
  const auto bottomRight = viewer.pixel(ball + Vec2(0.5f, -0.5f));
  const int side = int(bottomRight.x - topLeft.x);
  EXPECT_GT(countNear(shot.get(), {int(topLeft.x) - 2, int(topLeft.y) - 2, side + 4, side + 4},
                      viewer::palette::kBounds, 60),
            2 * side);
  // The flying ball's velocity arrow points right of it: 4 m/s x 0.25 s = 1 m.
  const auto arrowTip = viewer.pixel(tool.body(flying)->state.position + Vec2(0.8f, 0));
  EXPECT_GT(countNear(shot.get(), {int(arrowTip.x) - 4, int(arrowTip.y) - 4, 9, 9},
                      viewer::palette::kVelocity, 40), 4);
}

TEST(LivePlots, StepTimeAndKineticEnergyAreRecordedFromTheRunningServer) {
  Tool tool({"--preset", "10"});
  ASSERT_TRUE(tool.showsEveryBody());
  ASSERT_TRUE(tool.viewer.runUntil([&] { return tool.viewer.app().stepTimeHistory().values().size() >= 6; }));
  const auto& step = tool.viewer.app().stepTimeHistory().values();
  for (float ms : step) {
    EXPECT_GE(ms, 0);
    EXPECT_LT(ms, 100);
  }
  EXPECT_GT(tool.viewer.app().stepTimeHistory().max(), 0);
  // Falling and bouncing balls: energy changes over time.
  EXPECT_GT(tool.viewer.app().energyHistory().max(), 1);
  Shot shot = tool.viewer.capture(screenshotPath("live_plots.bmp"));
  ASSERT_NE(shot, nullptr);
}

TEST(Connection, AServerNeverReachedIsNamedWithTheReason) {
  std::uint16_t port = 0;
  {
    net_test::ServerProcess probe;  // a free port, closed again
    port = probe.port();
  }
  ViewerHarness viewer(port);
  ASSERT_TRUE(viewer.runUntil(
      [&] { return viewer.app().connection().state() == viewer::LinkState::Lost; }));
  const std::string text = viewer.app().connection().describe();
  const std::string expected = "cannot connect to 127.0.0.1:" + std::to_string(port) + " (";
  EXPECT_EQ(text.rfind(expected, 0), 0u) << text;
  EXPECT_NE(text.find("refused"), std::string::npos) << text;
  EXPECT_NE(text.find("retrying in"), std::string::npos) << text;
  EXPECT_EQ(text.find("lost"), std::string::npos) << text;
  viewer.capture(screenshotPath("cannot_connect.bmp"));
}

}  // namespace
}  // namespace impulse::viewer_test
