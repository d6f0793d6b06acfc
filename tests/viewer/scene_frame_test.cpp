// Where a room opens: on the preset scene when its bounds hold it, on its
// bounds when they are small enough to show, else on its bodies.
#include "scene_frame.h"

#include <gtest/gtest.h>

#include <vector>

#include "view_transform.h"

namespace impulse::viewer {
namespace {

void expectBox(const AABB& actual, const AABB& expected) {
  EXPECT_NEAR(actual.lower.x(), expected.lower.x(), 1e-3);
  EXPECT_NEAR(actual.lower.y(), expected.lower.y(), 1e-3);
  EXPECT_NEAR(actual.upper.x(), expected.upper.x(), 1e-3);
  EXPECT_NEAR(actual.upper.y(), expected.upper.y(), 1e-3);
}

TEST(SceneFrame, ARoomHoldingThePresetSceneOpensOnIt) {
  const AABB serverDefault{Vec2(-25, -25), Vec2(50, 45)};
  const std::vector<Vec2> farBodies{Vec2(40, 40)};
  EXPECT_FALSE(opensOnBodies(serverDefault));
  expectBox(openingFrame(serverDefault, farBodies), kPresetScene);
  const AABB huge{Vec2(-5000, -5000), Vec2(5000, 5000)};
  expectBox(openingFrame(huge, farBodies), kPresetScene);
}

TEST(SceneFrame, ASmallRoomAwayFromTheOriginOpensOnItsBounds) {
  // 83 000 to 83 100 m out, around an origin of 80 000 m.
  const AABB bounds{Vec2(3000, 0), Vec2(3100, 100)};
  EXPECT_FALSE(opensOnBodies(bounds));
  expectBox(openingFrame(bounds, {}), bounds);
  const AABB longest{Vec2(3000, 0), Vec2(3000 + kLargestFramedRoom, 10)};
  expectBox(openingFrame(longest, {}), longest);
}

TEST(SceneFrame, AHugeRoomOpensOnItsBodiesGrownByTheMargin_OrItsCentreWhenEmpty) {
  const AABB bounds{Vec2(30, -2000), Vec2(10030, 8000)};
  EXPECT_TRUE(opensOnBodies(bounds));
  const std::vector<Vec2> bodies{Vec2(4000, 100), Vec2(4060, 130), Vec2(4030, 110)};
  const Real m = kBodiesAreaMargin;
  expectBox(openingFrame(bounds, bodies), {Vec2(4000 - m, 100 - m), Vec2(4060 + m, 130 + m)});

  // One body: the preset scene's size around it.
  const std::vector<Vec2> one{Vec2(100, 200)};
  expectBox(openingFrame(bounds, one),
            {Vec2(100, 200) - kSceneSize / 2, Vec2(100, 200) + kSceneSize / 2});
  expectBox(openingFrame(bounds, {}),
            {Vec2(5030, 3000) - kSceneSize / 2, Vec2(5030, 3000) + kSceneSize / 2});
}

TEST(SceneFrame, TheViewMapsTheFramesCornersToTheFittedRectangle_AndBack) {
  const PixelRect viewport{100, 0, 800, 600};
  const AABB frame{Vec2(3000, 0), Vec2(3100, 100)};
  const ViewTransform view(viewport, frame);
  // 100 m square in 800 x 600: 6 px a metre, centred across.
  EXPECT_FLOAT_EQ(view.scale(), 6);
  const PixelPoint lowerLeft = view.toPixels(frame.lower);
  const PixelPoint upperRight = view.toPixels(frame.upper);
  EXPECT_FLOAT_EQ(lowerLeft.x, 100 + 100);
  EXPECT_FLOAT_EQ(lowerLeft.y, 600);
  EXPECT_FLOAT_EQ(upperRight.x, 100 + 700);
  EXPECT_FLOAT_EQ(upperRight.y, 0);
  const Vec2 back = view.toWorld(lowerLeft.x + 60, lowerLeft.y - 30);
  EXPECT_NEAR(back.x(), 3010, 1e-3);
  EXPECT_NEAR(back.y(), 5, 1e-3);

  // Zooming at a pixel keeps the world point under it there.
  const Camera zoomed = zoomAt({}, viewport, frame, 3, 500, 300);
  const ViewTransform after(viewport, frame, zoomed);
  EXPECT_NEAR(after.toWorld(500, 300).x(), view.toWorld(500, 300).x(), 1e-3);
  EXPECT_NEAR(after.toWorld(500, 300).y(), view.toWorld(500, 300).y(), 1e-3);
  EXPECT_FLOAT_EQ(after.scale(), 18);
}

}  // namespace
}  // namespace impulse::viewer
