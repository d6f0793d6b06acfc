// End to end: the viewer's Ctrl keys. A polygon drawn in the real viewer is
// kept in the shape library (Ctrl+D) and stamped at the cursor (Ctrl+1);
// Ctrl+S saves the server's world to the scene file, Ctrl+O brings it back
// after everything was cleared. A separate client watches the server.
#include <gtest/gtest.h>

#include <filesystem>

#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

class SceneKeysEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    // The viewer's default files, in the test's working directory.
    std::filesystem::remove(sceneFile);
    std::filesystem::remove(shapeFile);
    ASSERT_TRUE(viewer.runUntil([&] {
      const auto* c = viewer.app().connection().client();
      return c != nullptr && c->mirror().preset().has_value();
    }));
  }
  void TearDown() override {
    std::filesystem::remove(sceneFile);
    std::filesystem::remove(shapeFile);
  }
  bool observe(const std::function<bool()>& done) { return observeUntil(viewer, observer, done); }
  bool noticeSays(const std::string& part) {
    return observe([&] {
      const auto notice = viewer.app().controls().notice(viewer.app().now());
      return notice && notice->find(part) != std::string::npos;
    });
  }
  std::vector<const client::MirrorBody*> polygons() {
    std::vector<const client::MirrorBody*> found;
    for (const auto& [id, body] : observer.mirror().bodies()) {
      if (body.shape.type() == ShapeType::Polygon && !body.isStatic &&
          body.shape.polygon().count == 3) {
        found.push_back(&body);
      }
    }
    return found;
  }

  const std::string sceneFile = "impulse.scene";
  const std::string shapeFile = "impulse-shapes.txt";
  net_test::ServerProcess server{{"--paused"}};  // the sandbox, still
  ViewerHarness viewer{server.port()};
  client::Client observer{observerOptions(server.port())};
};

TEST_F(SceneKeysEndToEnd, DrawnShapeIsStampedAtTheCursor_SavedSceneComesBackAfterAClear) {
  viewer.tap(SDLK_p);
  viewer.click(Vec2(8, 8));
  viewer.click(Vec2(10, 8));
  viewer.click(Vec2(9, 10));
  viewer.tap(SDLK_d, KMOD_LCTRL);
  ASSERT_TRUE(noticeSays("Ctrl+1 stamps it"));
  EXPECT_EQ(viewer.app().controls().mode(), viewer::DrawMode::Polygon);  // Ctrl+D is not D
  viewer.tap(SDLK_ESCAPE);

  const auto at = viewer.pixel(Vec2(20, 6));
  viewer.mouseMove(at.x, at.y);
  viewer.tap(SDLK_1, KMOD_LCTRL);
  ASSERT_TRUE(observe([&] { return polygons().size() == 1; }));
  const Vec2 stamped = polygons()[0]->state.position;
  // The triangle's centroid lands on the cursor, within a pixel (about 3 cm).
  EXPECT_NEAR(stamped.x(), 20, 0.05);
  EXPECT_NEAR(stamped.y(), 6, 0.05);
  EXPECT_EQ(observer.mirror().preset()->id, 0);  // Ctrl+1 is not preset 1

  viewer.tap(SDLK_s, KMOD_LCTRL);
  ASSERT_TRUE(noticeSays("Scene saved to impulse.scene"));
  ASSERT_TRUE(std::filesystem::exists(sceneFile));
  const std::size_t bodies = observer.mirror().bodies().size();

  viewer.tap(SDLK_c, KMOD_LSHIFT);
  ASSERT_TRUE(observe([&] { return observer.mirror().bodies().empty(); }));
  viewer.tap(SDLK_o, KMOD_LCTRL);
  ASSERT_TRUE(noticeSays("Scene loaded from impulse.scene"));
  ASSERT_TRUE(observe([&] { return observer.mirror().bodies().size() == bodies; }));
  ASSERT_EQ(polygons().size(), 1u);
  EXPECT_EQ(polygons()[0]->state.position, stamped);  // paused: exactly where it was saved
}

}  // namespace
}  // namespace impulse::viewer_test
