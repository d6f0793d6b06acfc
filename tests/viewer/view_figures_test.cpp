// Pure parts of the viewer's picture: the window layout, the grab impulse,
// the contacts and energy shown, shape descriptions, number formatting.
#include <gtest/gtest.h>

#include "body_metrics.h"
#include "contact_finder.h"
#include "grab.h"
#include "impulse/client/number_format.h"
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
  const ViewTransform view(layout.scene, kSceneSize);
  const PixelPoint topRight = view.toPixels(kSceneSize);
  const PixelPoint bottomLeft = view.toPixels(Vec2(0, 0));
  EXPECT_LE(topRight.x, layout.scene.x + layout.scene.w + 1e-3f);
  EXPECT_GE(topRight.y, -1e-3f);
  EXPECT_GE(bottomLeft.x, layout.scene.x - 1e-3f);
  EXPECT_LE(bottomLeft.y, 720 + 1e-3f);
  // Fitted: one of the two dimensions fills the viewport.
  EXPECT_NEAR(std::max(view.width() / layout.scene.w, view.height() / layout.scene.h), 1, 1e-5);
}

TEST(GrabImpulse, HeadsForTheCursorWithinTheSpeedLimit_AndCancelsGravity) {
  const GrabSettings settings{10, 25};
  const GrabbedMotion body{Vec2(0, 0), Vec2(1, 0), 3};
  // The point 0.5 m right of the centre is to reach (1, 0): 0.5 m to go.
  const Vec2 near = grabImpulse(body, Vec2(0.5f, 0), Vec2(1, 0), Vec2(0, -9), 0.1, settings);
  EXPECT_NEAR(near.x(), 3 * (5 - 1), 1e-4);
  EXPECT_NEAR(near.y(), 3 * 0.9, 1e-4);
  const Vec2 far = grabImpulse(body, Vec2::Zero(), Vec2(100, 0), Vec2::Zero(), 0.1, settings);
  EXPECT_NEAR(far.x(), 3 * (25 - 1), 1e-3);
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
  const BodyLook ball{Shape::makeCircle(1), Material::Solid, false, false};
  const BodyLook floor{Shape::makePolygon(makeBox(10, 0.5f)), Material::Solid, true, false};
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
  const BodyLook ball{Shape::makeCircle(1), Material::Solid, false, false};
  const BodyLook wall{Shape::makeCircle(1), Material::Solid, true, false};
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
