// Issue 15's viewer controls as state machines: the time-scale keys ask the
// server for half, double or 1x within 0.01x-16x; the standard-shape keys
// spawn regular polygons at the cursor, sized by the size keys.
#include <gtest/gtest.h>

#include <cmath>

#include "controls.h"
#include "impulse/shape.h"
#include "standard_shapes.h"

namespace impulse::viewer {
namespace {

class TimeAndShapesTest : public ::testing::Test {
 protected:
  void press(Control control, const ControlContext& context, int index = 0) {
    controls.keyPressed({control, index}, context, now);
  }
  std::vector<Outgoing> sent() { return controls.takeCommands(); }
  // The scale one time key asks for at `current` (a first press, by fresh
  // controls); nothing when none is sent.
  std::optional<double> askedScale(Control control, double current) {
    controls = Controls();
    press(control, {.timeScale = current});
    const auto commands = sent();
    if (commands.empty()) return std::nullopt;
    EXPECT_EQ(commands.size(), 1u);
    EXPECT_TRUE(commands[0].message.has_set_time_scale());
    return commands[0].message.set_time_scale().scale();
  }

  Controls controls;
  double now = 0;
};

TEST_F(TimeAndShapesTest, BracketsHalveAndDoubleTheServersScale_BackslashResets) {
  EXPECT_EQ(askedScale(Control::SlowerTime, 1), 0.5);
  EXPECT_EQ(askedScale(Control::FasterTime, 1), 2);
  EXPECT_EQ(askedScale(Control::FasterTime, 4), 8);
  EXPECT_EQ(askedScale(Control::NormalTime, 0.25), 1);
}

TEST_F(TimeAndShapesTest, TimeScaleStaysWithinTheServersRange) {
  EXPECT_EQ(askedScale(Control::SlowerTime, 0.015), 0.01) << "clamped to the slowest";
  EXPECT_EQ(askedScale(Control::FasterTime, 10), 16) << "clamped to the fastest";
  EXPECT_EQ(askedScale(Control::SlowerTime, 0.01), std::nullopt) << "already slowest";
  EXPECT_TRUE(controls.notice(now).has_value());
  EXPECT_EQ(askedScale(Control::FasterTime, 16), std::nullopt) << "already fastest";
  EXPECT_EQ(askedScale(Control::NormalTime, 1), std::nullopt);
}

TEST_F(TimeAndShapesTest, QuickPressesBuildOnEachOtherUntilTheServerAnswers) {
  const auto ask = [&](Control control, double server) {
    press(control, {.timeScale = server});
    const auto commands = sent();
    return commands.empty() ? 0.0 : commands.back().message.set_time_scale().scale();
  };
  EXPECT_EQ(ask(Control::FasterTime, 1), 2);
  EXPECT_EQ(ask(Control::FasterTime, 1), 4) << "the server has not answered the first yet";
  EXPECT_EQ(ask(Control::FasterTime, 2), 8) << "it answered the first only";
  EXPECT_EQ(ask(Control::SlowerTime, 8), 4) << "it answered all";
  now += 5;
  EXPECT_EQ(ask(Control::FasterTime, 0.5), 1)
      << "long after, another client's 0.5x: the server's scale counts";
}

TEST_F(TimeAndShapesTest, ShapeKeysSpawnRegularPolygonsAtTheCursor) {
  const Vec2 cursor(6, 4);
  controls.pointerMoved(cursor);
  press(Control::SelectMaterial, {}, int(Material::Glass));
  for (int sides = 3; sides <= 6; ++sides) {
    SCOPED_TRACE(sides);
    press(Control::StandardShape, {}, sides);
    const auto commands = sent();
    ASSERT_EQ(commands.size(), 1u);
    const auto& polygon = commands[0].message.spawn_polygon();
    ASSERT_EQ(polygon.vertices_size(), sides);
    EXPECT_EQ(polygon.options().material(), v1::GLASS);
    // Every corner at the size from the cursor, sides all equal, the first
    // side (last to first vertex) level at the bottom.
    std::vector<Vec2> points;
    for (const auto& v : polygon.vertices()) points.emplace_back(Real(v.x()), Real(v.y()));
    const Real side = (points[0] - points.back()).norm();
    for (int k = 0; k < sides; ++k) {
      EXPECT_NEAR((points[std::size_t(k)] - cursor).norm(), kDefaultShapeSize, 1e-5);
      const Vec2 next = points[std::size_t((k + 1) % sides)];
      EXPECT_NEAR((next - points[std::size_t(k)]).norm(), side, 1e-5);
    }
    EXPECT_NEAR(points[0].y(), points.back().y(), 1e-5);
    EXPECT_LT(points[0].y(), cursor.y());
    // The side of a regular n-gon: 2 R sin(pi / n).
    EXPECT_NEAR(side, 2 * kDefaultShapeSize * std::sin(M_PI / sides), 1e-5);
    EXPECT_EQ(checkPolygonInProgress(points), ShapeError::None) << "convex, a valid body";
  }
}

TEST_F(TimeAndShapesTest, SizeKeysScaleTheShapesWithinTheirRange) {
  controls.pointerMoved(Vec2(5, 5));
  press(Control::ShapeLarger, {});
  EXPECT_NEAR(controls.shapeSize(), kDefaultShapeSize * kShapeSizeFactor, 1e-6);
  press(Control::StandardShape, {}, 4);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  const auto& square = commands[0].message.spawn_polygon();
  // A square of circumradius R has side R sqrt(2).
  const double side = std::hypot(square.vertices(1).x() - square.vertices(0).x(),
                                 square.vertices(1).y() - square.vertices(0).y());
  EXPECT_NEAR(side, controls.shapeSize() * std::sqrt(2.0), 1e-5);
  for (int i = 0; i < 40; ++i) press(Control::ShapeSmaller, {});
  EXPECT_EQ(controls.shapeSize(), kMinShapeSize);
  for (int i = 0; i < 40; ++i) press(Control::ShapeLarger, {});
  EXPECT_EQ(controls.shapeSize(), kMaxShapeSize);
}

TEST(StandardShapes, NamesFollowTheSideCount) {
  EXPECT_EQ(standardShapeName(3), "triangle");
  EXPECT_EQ(standardShapeName(6), "hexagon");
}

}  // namespace
}  // namespace impulse::viewer
