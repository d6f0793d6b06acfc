// The capsule, segment and chain tools of Controls, and the chain tool's
// geometry (chain_drawing.h): no window, no server.
#include <gtest/gtest.h>

#include "chain_drawing.h"
#include "controls.h"
#include "standard_shapes.h"

namespace impulse::viewer {
namespace {

const ControlContext kSandbox{};

class LineToolsTest : public ::testing::Test {
 protected:
  void press(Control control) { controls.keyPressed({control, 0}, kSandbox, now); }
  void click(float x, float y) {
    controls.pointerMoved(Vec2(x, y));
    controls.pointerPressed(Vec2(x, y), std::nullopt, now);
    controls.pointerReleased(Vec2(x, y));
  }
  void drag(const Vec2& from, const Vec2& to) {
    controls.pointerMoved(from);
    controls.pointerPressed(from, std::nullopt, now);
    controls.pointerMoved((from + to) / 2);
    controls.pointerReleased(to);
  }
  std::vector<Outgoing> sent() { return controls.takeCommands(); }
  std::string notice() const { return controls.notice(now).value_or(""); }

  Controls controls;
  double now = 0;
};

Vec2 fromWire(const v1::Vec2& v) { return Vec2(Real(v.x()), Real(v.y())); }

TEST_F(LineToolsTest, Capsule_DragSetsItsEnds_SizeKeysSetItsRadius_RSends) {
  press(Control::CapsuleMode);
  ASSERT_EQ(controls.mode(), DrawMode::Capsule);
  press(Control::ShapeLarger);
  const Real radius = kDefaultCapsuleRadius * kShapeSizeFactor;
  EXPECT_FLOAT_EQ(controls.capsuleRadius(), radius);
  EXPECT_FLOAT_EQ(controls.shapeSize(), kDefaultShapeSize);  // standard shapes keep theirs
  drag(Vec2(4, 5), Vec2(7, 5));
  EXPECT_EQ(controls.dragStart(), Vec2(4, 5));
  EXPECT_EQ(controls.dragEnd(), Vec2(7, 5));
  press(Control::CapsuleMode);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  ASSERT_TRUE(commands[0].message.has_spawn_capsule());
  const auto& capsule = commands[0].message.spawn_capsule();
  EXPECT_EQ(fromWire(capsule.center1()), Vec2(4, 5));
  EXPECT_EQ(fromWire(capsule.center2()), Vec2(7, 5));
  EXPECT_FLOAT_EQ(float(capsule.radius()), radius);
  EXPECT_EQ(controls.mode(), DrawMode::None);
}

TEST_F(LineToolsTest, CapsuleRadius_StaysInItsRange) {
  press(Control::CapsuleMode);
  for (int i = 0; i < 40; ++i) press(Control::ShapeSmaller);
  EXPECT_FLOAT_EQ(controls.capsuleRadius(), kMinCapsuleRadius);
  for (int i = 0; i < 40; ++i) press(Control::ShapeLarger);
  EXPECT_FLOAT_EQ(controls.capsuleRadius(), kMaxCapsuleRadius);
  EXPECT_NE(notice().find("Capsule radius: 2 m"), std::string::npos) << notice();
}

TEST_F(LineToolsTest, Segment_DragSetsItsEnds_LSends_AClickAloneCancels) {
  press(Control::SegmentMode);
  click(3, 3);
  press(Control::SegmentMode);
  EXPECT_TRUE(sent().empty());
  EXPECT_NE(notice().find("Segment cancelled"), std::string::npos);

  press(Control::SegmentMode);
  drag(Vec2(1, 2), Vec2(6, 3));
  press(Control::SegmentMode);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  ASSERT_TRUE(commands[0].message.has_spawn_segment());
  EXPECT_EQ(fromWire(commands[0].message.spawn_segment().point1()), Vec2(1, 2));
  EXPECT_EQ(fromWire(commands[0].message.spawn_segment().point2()), Vec2(6, 3));
}

TEST_F(LineToolsTest, Chain_DrawnLeftToRight_IsSentRightToLeftWithGuidesBeyondItsEnds) {
  press(Control::ChainMode);
  click(2, 3);
  click(5, 2);
  click(8, 3);
  ASSERT_EQ(controls.placedPoints().size(), 3u);
  press(Control::ChainMode);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  ASSERT_TRUE(commands[0].message.has_spawn_chain());
  const auto& chain = commands[0].message.spawn_chain();
  EXPECT_FALSE(chain.loop());
  ASSERT_EQ(chain.points_size(), 5);
  // Right to left: solid from above. The guides continue the end segments.
  EXPECT_EQ(fromWire(chain.points(1)), Vec2(8, 3));
  EXPECT_EQ(fromWire(chain.points(2)), Vec2(5, 2));
  EXPECT_EQ(fromWire(chain.points(3)), Vec2(2, 3));
  const Vec2 firstGuide = fromWire(chain.points(0));
  const Vec2 lastGuide = fromWire(chain.points(4));
  EXPECT_NEAR((firstGuide - Vec2(8, 3)).norm(), kChainGuideLength, 1e-5);
  EXPECT_NEAR(cross(firstGuide - Vec2(8, 3), Vec2(8, 3) - Vec2(5, 2)), 0, 1e-5);
  EXPECT_NEAR((lastGuide - Vec2(2, 3)).norm(), kChainGuideLength, 1e-5);
  EXPECT_LT(lastGuide.x(), 2);
}

TEST_F(LineToolsTest, Chain_APointThatWouldCrossIsRefused) {
  press(Control::ChainMode);
  click(2, 2);
  click(6, 2);
  click(6, 5);
  controls.pointerMoved(Vec2(4, 0));  // back across the first segment
  EXPECT_FALSE(controls.pointerValid());
  click(4, 0);
  EXPECT_EQ(controls.placedPoints().size(), 3u);
  controls.pointerMoved(Vec2(3, 6));
  EXPECT_TRUE(controls.pointerValid());
  EXPECT_EQ(checkChainInProgress(std::vector<Vec2>{Vec2(2, 2), Vec2(6, 2), Vec2(6, 5), Vec2(4, 0)}),
            ShapeError::ChainCrossing);
}

TEST_F(LineToolsTest, ClosingACrossingChain_ShowsTheEnginesMessage_AndKeepsTheDrawing) {
  press(Control::ChainMode);
  // A Z whose closing segment (last point to first) crosses its diagonal.
  click(0, 0);
  click(4, 0);
  click(0, 4);
  click(4, 4);
  press(Control::CloseChain);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(notice(), "Chain not closed: " + std::string(describe(ShapeError::ChainCrossing)));
  EXPECT_EQ(controls.mode(), DrawMode::Chain);
  EXPECT_EQ(controls.placedPoints().size(), 4u);
  // Finished open instead, it is accepted.
  press(Control::ChainMode);
  ASSERT_EQ(sent().size(), 1u);
}

TEST_F(LineToolsTest, ClosedChain_IsSentAnticlockwise) {
  press(Control::ChainMode);
  for (const Vec2& p : {Vec2(0, 0), Vec2(0, 4), Vec2(4, 4), Vec2(4, 0)}) click(p.x(), p.y());  // clockwise
  press(Control::CloseChain);
  const auto commands = sent();
  ASSERT_EQ(commands.size(), 1u);
  const auto& chain = commands[0].message.spawn_chain();
  EXPECT_TRUE(chain.loop());
  ASSERT_EQ(chain.points_size(), 4);
  Real twiceArea = 0;
  for (int i = 0; i < 4; ++i) twiceArea += cross(fromWire(chain.points(i)), fromWire(chain.points((i + 1) % 4)));
  EXPECT_FLOAT_EQ(twiceArea, 32);
}

TEST_F(LineToolsTest, ChainOfOnePoint_IsCancelled_ShiftHOutsideChainModeExplains) {
  press(Control::CloseChain);
  EXPECT_NE(notice().find("H starts one"), std::string::npos);
  press(Control::ChainMode);
  click(1, 1);
  press(Control::ChainMode);
  EXPECT_TRUE(sent().empty());
  EXPECT_EQ(notice(), "Chain cancelled: click at least 2 points");
  EXPECT_EQ(controls.mode(), DrawMode::None);
}

}  // namespace
}  // namespace impulse::viewer
