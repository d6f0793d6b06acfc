// The viewer's area of interest: the view grown by the margin, and when a
// moved view asks for a new one.
#include "view_area.h"

#include <gtest/gtest.h>

#include "options.h"

namespace impulse::viewer {
namespace {

const PixelRect kViewport{100, 0, 800, 600};
const AABB kScene = kPresetScene;

TEST(ViewArea, IsTheViewportsWorldRectangleGrownByTheMargin) {
  const ViewTransform view(kViewport, kScene);
  const AABB area = viewArea(view, 2);
  const Vec2 lower = view.toWorld(kViewport.x, kViewport.y + kViewport.h);
  const Vec2 upper = view.toWorld(kViewport.x + kViewport.w, kViewport.y);
  EXPECT_NEAR(area.lower.x(), lower.x() - 2, 1e-4);
  EXPECT_NEAR(area.lower.y(), lower.y() - 2, 1e-4);
  EXPECT_NEAR(area.upper.x(), upper.x() + 2, 1e-4);
  EXPECT_NEAR(area.upper.y(), upper.y() + 2, 1e-4);
  EXPECT_TRUE(area.contains(kScene)) << "the fitted scene is in view";
}

TEST(ViewArea, AMoveWithinHalfTheMarginKeepsTheAreaSent_APanOrZoomPastItAsksAgain) {
  const ViewTransform fitted(kViewport, kScene);
  const AABB sent = viewArea(fitted, 2);
  const float metre = fitted.scale();
  const AABB nudged = viewArea(ViewTransform(kViewport, kScene, {1, 0.5f * metre, 0}), 2);
  EXPECT_FALSE(areaMoved(sent, nudged, 1)) << "half a metre: the margin still covers the view";
  const AABB panned = viewArea(ViewTransform(kViewport, kScene, {1, 3 * metre, 0}), 2);
  EXPECT_TRUE(areaMoved(sent, panned, 1));
  const AABB zoomed = viewArea(ViewTransform(kViewport, kScene, {2, 0, 0}), 2);
  EXPECT_TRUE(areaMoved(sent, zoomed, 1));
}

TEST(ViewerOptions, TheViewIsTheAreaByDefault_WholeRoomOrQuantizedTurnItOff_NoBudget_OutOfRangeRefused) {
  const auto parse = [](std::vector<std::string_view> args) { return parseViewerOptions(args); };
  const auto defaults = parse({});
  EXPECT_EQ(defaults.options->areaMargin, kDefaultAreaMargin);
  EXPECT_FALSE(defaults.options->budget);
  EXPECT_FALSE(parse({"--whole-room"}).options->areaMargin);
  EXPECT_FALSE(parse({"--quantized"}).options->areaMargin) << "areas need plain snapshots";
  EXPECT_EQ(parse({"--quantized", "--area-margin", "2"}).options->areaMargin, 2.0f);
  EXPECT_FALSE(parse({"--whole-room", "--area-margin", "2"}).options);
  const auto given = parse({"--area-margin", "3.5", "--budget", "32000"});
  ASSERT_TRUE(given.options) << given.error;
  EXPECT_EQ(given.options->areaMargin, 3.5f);
  EXPECT_EQ(given.options->budget, 32000);
  EXPECT_FALSE(parse({"--area-margin", "-1"}).options);
  EXPECT_FALSE(parse({"--budget", "0"}).options);
  EXPECT_FALSE(parse({"--budget", "200000000"}).options);
}

}  // namespace
}  // namespace impulse::viewer
