// Pure parts of the viewer's picture: the window layout, the hand's mouse
// spring, joint figures, the contacts and energy shown, shape descriptions, number formatting.
#include <gtest/gtest.h>

#include <numbers>

#include "body_metrics.h"
#include "contact_finder.h"
#include "grab.h"
#include "impulse/client/number_format.h"
#include "joint_figure.h"
#include "layout.h"

namespace impulse::viewer {
namespace {

TEST(WindowLayout, PanelAndSceneNeverOverlapAndCoverTheWindow) {
  for (const auto& [w, h] : {std::pair{1280, 720}, {800, 600}, {480, 320}, {2560, 1440}}) {
    const WindowLayout layout = layoutWindow(w, h);
    EXPECT_FLOAT_EQ(layout.scene.x + layout.scene.w, layout.panel.x) << w;
    EXPECT_FLOAT_EQ(layout.panel.x + layout.panel.w, float(w)) << w;
    EXPECT_FLOAT_EQ(layout.scene.h, float(h));
    EXPECT_GE(layout.scene.w, float(w) / 2) << w;
    EXPECT_GE(layout.panel.w, 200) << w;
  }
}

TEST(ViewTransform, FitsTheSceneInsideTheViewportOnly) {
  const WindowLayout layout = layoutWindow(1280, 720);
  const ViewTransform view(layout.scene, kPresetScene);
  const PixelPoint topRight = view.toPixels(kSceneSize);
  const PixelPoint bottomLeft = view.toPixels(Vec2(0, 0));
  EXPECT_LE(topRight.x, layout.scene.x + layout.scene.w + 1e-3f);
  EXPECT_GE(topRight.y, -1e-3f);
  EXPECT_GE(bottomLeft.x, layout.scene.x - 1e-3f);
  EXPECT_LE(bottomLeft.y, 720 + 1e-3f);
  // Fitted: one of the two dimensions fills the viewport.
  EXPECT_NEAR(std::max(view.width() / layout.scene.w, view.height() / layout.scene.h), 1, 1e-5);
}

TEST(MouseSpring, FollowsAsBrisklyWhateverTheMass) {
  const GrabSettings settings{2, 1, 100};
  const auto light = mouseSpring(1, settings);
  const auto heavy = mouseSpring(50, settings);
  // w = 2*pi*f: k = m*w^2, c = 2*zeta*m*w, cap m*a.
  const double w = 2 * std::numbers::pi * 2;
  EXPECT_NEAR(light.stiffness(), w * w, 1e-9);
  EXPECT_NEAR(light.damping(), 2 * w, 1e-9);
  EXPECT_NEAR(heavy.stiffness() / light.stiffness(), 50, 1e-9);
  EXPECT_NEAR(heavy.max_force(), 5000, 1e-9);
}

TEST(JointFigure, AnchorsFollowTheDrawnBodies_SpringsZigZag) {
  JointDescription rod;
  rod.bodyA = BodyId{1};
  rod.bodyB = BodyId{2};
  rod.localAnchorA = Vec2(1, 0);
  rod.localAnchorB = Vec2(0, 0);
  BodySample a{1, Vec2(0, 0), Real(std::numbers::pi / 2)};
  BodySample b{2, Vec2(3, 4)};
  const auto figure = jointFigure(rod, &a, &b);
  ASSERT_TRUE(figure);
  EXPECT_EQ(figure->look, JointLook::Rod);
  // A turned a quarter: its local (1, 0) is world (0, 1).
  EXPECT_NEAR(figure->a.x(), 0, 1e-6);
  EXPECT_NEAR(figure->a.y(), 1, 1e-6);
  EXPECT_EQ(figure->b, Vec2(3, 4));
  EXPECT_FALSE(jointFigure(rod, &a, nullptr));

  rod.settings = DistanceJointSettings{0, 100, 1};
  EXPECT_EQ(jointLook(rod.settings), JointLook::Spring);
  EXPECT_EQ(jointLook(RevoluteJointSettings{}), JointLook::Pin);
  EXPECT_EQ(jointLook(RopeJointSettings{}), JointLook::Rope);
  std::vector<Vec2> points{Vec2(7, 7)};  // a reused buffer: its old content goes
  zigzag(Vec2(0, 0), Vec2(10, 0), 4, 0.5f, points);
  ASSERT_EQ(points.size(), 2u + 8u + 2u);
  EXPECT_EQ(points.front(), Vec2(0, 0));
  EXPECT_EQ(points.back(), Vec2(10, 0));
  for (std::size_t i = 2; i < points.size() - 2; ++i) EXPECT_NEAR(std::abs(points[i].y()), 0.5, 1e-6);
}

DrawnBody drawn(const BodyLook& look, std::uint32_t id, Vec2 position, Vec2 velocity = Vec2::Zero(),
                Real spin = 0) {
  DrawnBody body;
  body.look = &look;
  body.state.id = id;
  body.state.position = position;
  body.state.velocity = velocity;
  body.state.angularVelocity = spin;
  return body;
}

TEST(ContactFinder, FindsTouchingPairsWithTheirNormal_SkipsSeparatedAndStaticPairs) {
  const BodyLook ball{.shape = Shape::makeCircle(1)};
  const BodyLook floor{.shape = Shape::makePolygon(makeBox(10, 0.5f)), .isStatic = true};
  const std::vector<DrawnBody> bodies{
      drawn(ball, 1, Vec2(0, 1.5f)),     // resting on the floor
      drawn(floor, 2, Vec2(0, 0)),       // the floor
      drawn(floor, 3, Vec2(0, -0.9f)),   // static on static: not shown
      drawn(ball, 4, Vec2(1.99f, 1.5f)),  // touching ball 1
      drawn(ball, 5, Vec2(6, 4))};       // in the air
  std::vector<ShownContact> contacts;
  findContacts(bodies, contacts);
  int floorContacts = 0;
  int ballContacts = 0;
  for (const ShownContact& c : contacts) {
    EXPECT_NEAR(c.normal.norm(), 1, 1e-4);
    if (std::abs(c.point.y() - 0.5f) < 0.02f) ++floorContacts;
    if (std::abs(c.point.x() - 0.995f) < 0.02f && std::abs(c.point.y() - 1.5f) < 0.02f) {
      ++ballContacts;
      EXPECT_NEAR(std::abs(c.normal.x()), 1, 1e-3);
    }
  }
  EXPECT_EQ(floorContacts, 2);  // both balls on the floor
  EXPECT_EQ(ballContacts, 1);
  EXPECT_EQ(contacts.size(), 3u);
}

TEST(BodyMetrics, KineticEnergyCountsMovingAndSpinningDynamicBodiesOnly) {
  const BodyLook ball{.shape = Shape::makeCircle(1)};
  const BodyLook wall{.shape = Shape::makeCircle(1), .isStatic = true};
  const MassProperties mass = massOf(ball);
  EXPECT_NEAR(mass.mass, 500 * 3.14159265f, 0.5f);
  const std::vector<DrawnBody> bodies{drawn(ball, 1, Vec2::Zero(), Vec2(2, 0), 0),
                                      drawn(ball, 2, Vec2::Zero(), Vec2::Zero(), 3),
                                      drawn(wall, 3, Vec2::Zero(), Vec2(5, 5), 5)};
  const double expected = 0.5 * mass.mass * 4 + 0.5 * mass.inertia * 9;
  EXPECT_NEAR(kineticEnergy(bodies), expected, expected * 1e-5);
  EXPECT_EQ(massOf(wall).mass, 0);
}

TEST(BodyMetrics, DescribesShapesWithTheirSize) {
  EXPECT_EQ(describeShape(Shape::makeCircle(0.5f)), "circle, radius 0.5 m");
  EXPECT_EQ(describeShape(Shape::makePolygon(makeBox(1, 0.25f))), "polygon, 4 vertices, 2 x 0.5 m");
  EXPECT_EQ(describeShape(Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), 0.25f)), "capsule, 2 m long, radius 0.25 m");
}

TEST(BodyMetrics, ABodyIsTouchedInAnyOfItsShapes_AndNearItsLines) {
  // A compound body: a box with a wheel 3 m to its right, moved to (10, 0).
  const BodyLook cart{.shape = Shape::makePolygon(makeBox(1, 0.25f)),
                      .extraShapes = {Shape::makeCircle(0.5f, Vec2(3, 0))}};
  const Transform xf{Vec2(10, 0), Rot::fromAngle(0)};
  EXPECT_TRUE(bodyTouches(cart, xf, Vec2(10.5f, 0.1f), 0.1f));
  EXPECT_TRUE(bodyTouches(cart, xf, Vec2(13.2f, 0.2f), 0.1f));
  EXPECT_FALSE(bodyTouches(cart, xf, Vec2(12, 0), 0.1f));
  const BodyLook wall{.shape = Shape::makeSegment(Vec2(0, 0), Vec2(0, 4)), .isStatic = true};
  EXPECT_TRUE(bodyTouches(wall, xf, Vec2(10.08f, 2), 0.1f));
  EXPECT_FALSE(bodyTouches(wall, xf, Vec2(10.15f, 2), 0.1f));
  EXPECT_FALSE(bodyTouches(wall, xf, Vec2(10, 4.2f), 0.1f));
}

TEST(BodyMetrics, DescribesABodysShapesTogether) {
  const Shape box = Shape::makePolygon(makeBox(1, 0.25f));
  const Shape wheel = Shape::makeCircle(0.5f);
  const std::vector<Shape> one{box};
  EXPECT_EQ(describeShapes(one), describeShape(box));
  const std::vector<Shape> compound{box, wheel, box};
  EXPECT_EQ(describeShapes(compound), "3 shapes: 2 polygons, 1 circle");
  const ChainBuild chain = buildChain(std::vector<Vec2>{Vec2(0, 0), Vec2(1, 0), Vec2(3, 0), Vec2(4, 0), Vec2(5, 0)}, false);
  ASSERT_EQ(chain.error, ShapeError::None);
  std::vector<Shape> segments;
  for (const ChainSegment& segment : chain.segments) segments.push_back(Shape{segment});
  EXPECT_EQ(describeShapes(segments), "chain of 2 segments, 3 m");
}

TEST(NumberFormat, WritesNumbersAsPeopleDo) {
  using client::formatNumber;
  EXPECT_EQ(formatNumber(-25.0), "-25");
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(9.81f, 3), "9.81");
  EXPECT_EQ(formatNumber(-0.0001, 2), "0");
  EXPECT_EQ(formatNumber(2.5e6), "2500000");
  EXPECT_EQ(formatNumber(1.0 / 3, 3), "0.333");
  EXPECT_EQ(client::formatExact(0.1), "0.1");
  EXPECT_EQ(client::formatExact(-25.0), "-25");
}

}  // namespace
}  // namespace impulse::viewer
