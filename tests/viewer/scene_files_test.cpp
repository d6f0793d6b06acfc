#include "scene_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "impulse/client/scene_file.h"

namespace impulse::viewer {
namespace {

class SceneFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() / ("impulse-viewer-" + std::string(test->name()));
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string path(const char* name) const { return (dir / name).string(); }

  std::filesystem::path dir;
};

const std::vector<Vec2> kTriangle = {Vec2(10, 10), Vec2(13, 10),
                                     Vec2(10, 13)};  // centroid (11, 11)

TEST_F(SceneFilesTest, SaveAsksForTheScene_AndTheReplyIsWrittenToTheFileNamedOnScreen) {
  SceneFiles files(path("world.scene"), path("shapes.txt"));
  const std::string asked = files.save();
  EXPECT_NE(asked.find(path("world.scene")), std::string::npos) << asked;
  const auto commands = files.takeCommands();
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_TRUE(commands[0].message.has_save_scene());

  const std::string data("\x08\x01\x12\x00scene bytes", 15);
  const std::string shown = files.sceneArrived(data);
  EXPECT_NE(shown.find(path("world.scene")), std::string::npos) << shown;
  EXPECT_NE(shown.find("15 bytes"), std::string::npos) << shown;
  std::string error;
  EXPECT_EQ(client::readSceneFile(path("world.scene"), error), data) << error;
}

TEST_F(SceneFilesTest, LoadSendsTheFileBytes_OrSaysWhyNot) {
  SceneFiles files(path("world.scene"), path("shapes.txt"));
  EXPECT_NE(files.load().find("not loaded"), std::string::npos);
  EXPECT_TRUE(files.takeCommands().empty());
  const std::string data("exact\0bytes", 11);
  ASSERT_EQ(client::writeSceneFile(path("world.scene"), data), "");
  files.load();
  const auto commands = files.takeCommands();
  ASSERT_EQ(commands.size(), 1u);
  ASSERT_TRUE(commands[0].message.has_load_scene());
  EXPECT_EQ(commands[0].message.load_scene().data(), data);
}

TEST_F(SceneFilesTest, KeptShapeIsStampedCentredAtTheCursor_AndSurvivesARestart) {
  {
    SceneFiles files(path("world.scene"), path("shapes.txt"));
    const std::string kept = files.saveShape(kTriangle);
    EXPECT_NE(kept.find("Ctrl+1"), std::string::npos) << kept;
  }
  SceneFiles files(path("world.scene"), path("shapes.txt"));  // read back from the file
  ASSERT_EQ(files.shapes().size(), 1u);
  files.stamp(0, Vec2(-2, 5), {.material = Material::Ice, .isStatic = true});
  const auto commands = files.takeCommands();
  ASSERT_EQ(commands.size(), 1u);
  const auto& polygon = commands[0].message.spawn_polygon();
  ASSERT_EQ(polygon.vertices_size(), 3);
  double cx = 0;
  double cy = 0;
  for (const auto& v : polygon.vertices()) {
    cx += v.x() / 3;
    cy += v.y() / 3;
  }
  // The triangle's centroid lands on the cursor; its shape is unchanged
  // (legs of 3 m), to float precision (1e-5 m).
  EXPECT_NEAR(cx, -2, 1e-5);
  EXPECT_NEAR(cy, 5, 1e-5);
  double longest = 0;
  for (int i = 0; i < 3; ++i) {
    const auto& p = polygon.vertices(i);
    const auto& q = polygon.vertices((i + 1) % 3);
    longest = std::max(longest, std::hypot(p.x() - q.x(), p.y() - q.y()));
  }
  EXPECT_NEAR(longest, 3 * std::sqrt(2.0), 1e-5);
  EXPECT_EQ(polygon.options().material(), v1::ICE);
  EXPECT_TRUE(polygon.options().is_static());
}

TEST_F(SceneFilesTest, WithoutADrawingTheLastPolygonSentIsKept_AndBadOnesAreRefused) {
  SceneFiles files(path("world.scene"), path("shapes.txt"));
  EXPECT_NE(files.saveShape({}).find("No polygon"), std::string::npos);
  std::vector<client::Point> sent;
  for (const Vec2& p : kTriangle) sent.push_back({p.x(), p.y()});
  files.sent(client::spawnPolygon(sent));
  files.saveShape({});
  EXPECT_EQ(files.shapes().size(), 1u);
  const std::vector<Vec2> collinear = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)};
  EXPECT_NE(files.saveShape(collinear).find("not kept"), std::string::npos);
  EXPECT_EQ(files.shapes().size(), 1u);
  EXPECT_NE(files.stamp(4, Vec2(0, 0), {}).find("No shape 5"), std::string::npos);
  EXPECT_TRUE(files.takeCommands().empty());
}

TEST_F(SceneFilesTest, LibraryKeepsTheNewestNine) {
  SceneFiles files(path("world.scene"), path("shapes.txt"));
  for (int i = 0; i < 11; ++i) {
    const Real size = Real(1 + i);
    files.saveShape(std::vector<Vec2>{Vec2(0, 0), Vec2(size, 0), Vec2(0, size)});
  }
  ASSERT_EQ(files.shapes().size(), ShapeLibrary::kMaxShapes);
  // Shape 1 is now the third one drawn (legs of 3 m): its leftmost vertex
  // is a third of a leg left of its centroid.
  const auto placed = files.shapes().placed(0, Vec2(0, 0));
  ASSERT_EQ(placed.size(), 3u);
  Real minX = placed[0].x();
  for (const Vec2& p : placed) minX = std::min(minX, p.x());
  EXPECT_NEAR(minX, -1.0, 1e-5);
}

}  // namespace
}  // namespace impulse::viewer
