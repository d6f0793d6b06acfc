// The viewer's use of queries, filters and events without a window or a
// server: the ray tool's casts (one in flight, the newest ray next) and its
// figure, the flashes of the event stream and their fade, the sensor look
// and its dashes.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "controls.h"
#include "dashes.h"
#include "event_flashes.h"
#include "palette.h"
#include "ray_tool.h"

namespace impulse::viewer {
namespace {

Vec2 fromWire(const v1::Vec2& v) { return Vec2(Real(v.x()), Real(v.y())); }

void setWire(v1::Vec2* out, double x, double y) {
  out->set_x(x);
  out->set_y(y);
}

v1::ServerMessage queryResult(std::optional<RayHit> hit) {
  v1::ServerMessage reply;
  v1::QueryResult* result = reply.mutable_query_result();
  if (hit) {
    v1::QueryHit* out = result->add_hits();
    out->set_body_id(hit->body);
    out->set_shape_id(hit->shape);
    setWire(out->mutable_point(), hit->point.x(), hit->point.y());
    setWire(out->mutable_normal(), hit->normal.x(), hit->normal.y());
    out->set_fraction(hit->fraction);
  }
  return reply;
}

const RayHit kFloorHit{3, 7, Vec2(2, 0), Vec2(0, 1), 0.5};

TEST(RayTool, OneCastInFlight_TheNewestRayIsAskedNext) {
  RayTool tool;
  const Ray first{Vec2(0, 4), Vec2(1, 0)};
  const Ray dragged{Vec2(0, 4), Vec2(2, 0)};
  const Ray newest{Vec2(0, 4), Vec2(3, 0)};
  tool.aim(first);
  EXPECT_EQ(tool.request(0), first);
  tool.aim(dragged);
  EXPECT_FALSE(tool.request(0.01));
  tool.aim(newest);
  EXPECT_FALSE(tool.request(0.02));

  EXPECT_FALSE(tool.answered(queryResult(kFloorHit)));
  ASSERT_TRUE(tool.answer());
  EXPECT_EQ(tool.answer()->ray, first);  // the answer is to the ray asked
  EXPECT_EQ(tool.answer()->hit->shape, 7u);
  EXPECT_EQ(tool.request(0.03), newest);
}

TEST(RayTool, APressNotYetDraggedIsNoRay) {
  RayTool tool;
  tool.aim({Vec2(1, 1), Vec2(1, 1)});
  EXPECT_FALSE(tool.request(0));
  EXPECT_FALSE(tool.inFlight());
}

TEST(RayTool, ARayLeftInPlaceIsCastAgainAfterTheInterval) {
  RayTool tool;
  tool.aim({Vec2(0, 1), Vec2(5, 1)});
  ASSERT_TRUE(tool.request(1));
  tool.answered(queryResult(std::nullopt));
  EXPECT_FALSE(tool.request(1 + RayTool::kRecastInterval / 2));
  EXPECT_TRUE(tool.request(1 + RayTool::kRecastInterval));
}

TEST(RayTool, AMissIsAnAnswerWithoutAHit) {
  RayTool tool;
  tool.aim({Vec2(0, 1), Vec2(5, 1)});
  ASSERT_TRUE(tool.request(0));
  tool.answered(queryResult(std::nullopt));
  ASSERT_TRUE(tool.answer());
  EXPECT_FALSE(tool.answer()->hit);
  EXPECT_EQ(describeRay(*tool.answer()), "miss");
}

TEST(RayTool, AReplyToACastFromBeforeClearIsIgnored) {
  RayTool tool;
  tool.aim({Vec2(0, 1), Vec2(5, 1)});
  ASSERT_TRUE(tool.request(0));
  tool.clear();
  const Ray again{Vec2(0, 2), Vec2(5, 2)};
  tool.aim(again);
  EXPECT_FALSE(tool.request(0.01));  // the old cast is still in flight
  tool.answered(queryResult(kFloorHit));
  EXPECT_FALSE(tool.answer());
  EXPECT_EQ(tool.request(0.02), again);
}

TEST(RayTool, ARefusalIsReturned_TheRayIsNotAskedAgainUntilAimed) {
  RayTool tool;
  tool.aim({Vec2(0, 1), Vec2(5, 1)});
  ASSERT_TRUE(tool.request(0));
  v1::ServerMessage refusal;
  refusal.mutable_command_result()->set_ok(false);
  refusal.mutable_command_result()->set_error("ray_cast.origin: not finite");
  EXPECT_EQ(tool.answered(refusal), "ray_cast.origin: not finite");
  EXPECT_FALSE(tool.request(1));
  tool.aim({Vec2(0, 1), Vec2(4, 1)});
  EXPECT_TRUE(tool.request(1));
}

TEST(RayFigure, SolidToTheHit_NormalArrowFromIt) {
  const RayFigure figure = rayFigure({{Vec2(2, 4), Vec2(2, -4)}, kFloorHit}, Real(0.6));
  EXPECT_TRUE(figure.hit);
  EXPECT_EQ(figure.reach, Vec2(2, 0));
  EXPECT_EQ(figure.end, Vec2(2, -4));
  EXPECT_NEAR((figure.normalTip - Vec2(2, Real(0.6))).norm(), 0, 1e-6);
  // Both barbs behind the tip, one either side of the normal, alike.
  for (const Vec2& barb : figure.barbs) EXPECT_LT(barb.y(), figure.normalTip.y());
  EXPECT_NEAR(figure.barbs[0].x() - 2, -(figure.barbs[1].x() - 2), 1e-6);
  EXPECT_NE(figure.barbs[0].x(), figure.barbs[1].x());
  EXPECT_EQ(describeRay({{}, kFloorHit}), "body 3, shape 7 at 0.5 of the ray");
}

TEST(RayFigure, AMissIsTheWholeRayPlain) {
  const RayFigure figure = rayFigure({{Vec2(1, 1), Vec2(6, 3)}, std::nullopt}, 1);
  EXPECT_FALSE(figure.hit);
  EXPECT_EQ(figure.origin, Vec2(1, 1));
  EXPECT_EQ(figure.reach, Vec2(6, 3));
}

class RayControlsTest : public ::testing::Test {
 protected:
  void press(Control control) { controls.keyPressed({control, 0}, {}, now); }
  std::vector<Outgoing> sentAfterFrame() {
    controls.update({}, now);
    return controls.takeCommands();
  }
  Controls controls;
  double now = 0;
};

TEST_F(RayControlsTest, E_DragSendsClosestHitRayCastsOneAtATime_EAgainLeaves) {
  press(Control::RayMode);
  ASSERT_EQ(controls.mode(), DrawMode::Ray);
  controls.pointerPressed(Vec2(1, 5), std::nullopt, now);
  EXPECT_TRUE(sentAfterFrame().empty());
  controls.pointerMoved(Vec2(4, 5));
  auto sent = sentAfterFrame();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0].what, "ray");
  ASSERT_TRUE(sent[0].message.has_ray_cast());
  EXPECT_EQ(fromWire(sent[0].message.ray_cast().origin()), Vec2(1, 5));
  EXPECT_EQ(fromWire(sent[0].message.ray_cast().translation()), Vec2(3, 0));
  EXPECT_FALSE(sent[0].message.ray_cast().all_hits());  // the closest hit
  // Many pointer events while the cast is out: nothing more is sent.
  for (int x = 5; x < 15; ++x) controls.pointerMoved(Vec2(Real(x), 5));
  EXPECT_TRUE(sentAfterFrame().empty());
  controls.rayAnswered(queryResult(std::nullopt), now);
  sent = sentAfterFrame();
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(fromWire(sent[0].message.ray_cast().translation()), Vec2(13, 0));
  controls.pointerReleased(Vec2(14, 5));

  press(Control::RayMode);
  EXPECT_EQ(controls.mode(), DrawMode::None);
  EXPECT_FALSE(controls.rayTool().aimed());
  EXPECT_TRUE(sentAfterFrame().empty());
}

TEST_F(RayControlsTest, ARefusedRayBecomesANotice) {
  press(Control::RayMode);
  controls.pointerPressed(Vec2(1, 5), std::nullopt, now);
  controls.pointerMoved(Vec2(4, 5));
  ASSERT_EQ(sentAfterFrame().size(), 1u);
  v1::ServerMessage refusal;
  refusal.mutable_command_result()->set_error("rate limited");
  controls.rayAnswered(refusal, now);
  EXPECT_EQ(controls.notice(now).value_or(""), "Server refused the ray: rate limited");
}

v1::Events hitAt(double x, double y, double speed) {
  v1::Events events;
  v1::HitEvent* hit = events.add_hits();
  setWire(hit->mutable_point(), x, y);
  setWire(hit->mutable_normal(), 0, 1);
  hit->set_approach_speed(speed);
  return events;
}

TEST(EventFlashes, WaitForTheDrawnWorld_ThenFadeOverHalfASecond) {
  EventFlashes flashes;
  flashes.add(hitAt(3, 1, 4), /*time=*/2.0, /*now=*/10.0);
  ASSERT_EQ(flashes.flashes().size(), 1u);
  flashes.update(1.9, 10.05);  // drawn world still before the hit
  EXPECT_EQ(EventFlashes::intensity(flashes.flashes()[0], 10.05), 0);
  flashes.update(2.0, 10.1);
  const Flash& flash = flashes.flashes()[0];
  EXPECT_EQ(flash.point, Vec2(3, 1));
  EXPECT_FLOAT_EQ(EventFlashes::intensity(flash, 10.1), 1);
  EXPECT_FLOAT_EQ(EventFlashes::intensity(flash, 10.1 + EventFlashes::kFadeSeconds / 2), 0.5f);
  flashes.update(2.4, 10.1 + EventFlashes::kFadeSeconds - 0.01);
  EXPECT_EQ(flashes.flashes().size(), 1u);
  flashes.update(2.5, 10.1 + EventFlashes::kFadeSeconds);
  EXPECT_TRUE(flashes.flashes().empty());
}

TEST(EventFlashes, SensorBeginsFlashTheSensor_ContactBeginsBothBodies) {
  v1::Events events;
  v1::SensorEvent* visit = events.add_sensor_begins();
  visit->set_sensor_body(5);
  visit->set_visitor_body(9);
  v1::ContactEvent* contact = events.add_contact_begins();
  contact->set_body_a(2);
  contact->set_body_b(9);
  events.add_sensor_ends()->set_sensor_body(6);  // leaving is not flashed
  EventFlashes flashes;
  flashes.add(events, 0, 0);
  std::vector<std::pair<Flash::Kind, std::uint32_t>> flashed;
  for (const Flash& flash : flashes.flashes()) flashed.emplace_back(flash.kind, flash.body);
  const std::vector<std::pair<Flash::Kind, std::uint32_t>> expected{{Flash::Kind::ContactBegin, 2},
                                                                    {Flash::Kind::ContactBegin, 9},
                                                                    {Flash::Kind::SensorBegin, 5}};
  EXPECT_EQ(flashed, expected);
}

TEST(EventFlashes, KeepAtMostTheNewestFew) {
  EventFlashes flashes;
  for (std::size_t i = 0; i < EventFlashes::kMaxFlashes + 10; ++i)
    flashes.add(hitAt(double(i), 0, 1), 0, 0);
  ASSERT_EQ(flashes.flashes().size(), EventFlashes::kMaxFlashes);
  EXPECT_EQ(flashes.flashes().front().point, Vec2(10, 0));
}

TEST(EventFlashes, AFlashTheDrawnWorldNeverReachesIsDropped) {
  EventFlashes flashes;
  flashes.add(hitAt(0, 0, 1), /*time=*/100, /*now=*/0);
  flashes.update(1, EventFlashes::kMaxWaitSeconds - 0.1);
  EXPECT_EQ(flashes.flashes().size(), 1u);
  flashes.update(1, EventFlashes::kMaxWaitSeconds + 0.1);
  EXPECT_TRUE(flashes.flashes().empty());
}

TEST(HitMark, FasterHitsAreLargerAndBrighter_WithinLimits) {
  const HitMark gentle = hitMark(1), hard = hitMark(8), fastest = hitMark(16);
  EXPECT_LT(gentle.radius, hard.radius);
  EXPECT_LT(gentle.brightness, hard.brightness);
  EXPECT_LT(hard.radius, fastest.radius);
  EXPECT_EQ(hitMark(100).radius, fastest.radius);
  EXPECT_FLOAT_EQ(fastest.brightness, 1);
  EXPECT_GT(hitMark(0).brightness, 0.3f);  // a slow hit still shows
}

TEST(SensorLook, SeeThroughAndDashed_SolidBodiesUnchanged) {
  for (int i = 0; i < kMaterialCount; ++i) {
    const Material material = *materialFromIndex(i);
    for (const bool isStatic : {false, true}) {
      const SurfaceLook solid = surfaceLook(material, isStatic, false, false);
      EXPECT_EQ(solid.fill, bodyFill(material, isStatic));
      EXPECT_EQ(solid.outline, bodyOutline(material, isStatic, false));
      EXPECT_FALSE(solid.dashed);
      const SurfaceLook sensor = surfaceLook(material, isStatic, false, true);
      EXPECT_TRUE(sensor.dashed);
      EXPECT_LE(sensor.fill.a, 64);
      EXPECT_GT(sensor.outline.a, sensor.fill.a);
      // The material's own colour, static or not: a trigger is not scenery.
      Colour opaque = sensor.fill;
      opaque.a = 255;
      EXPECT_EQ(opaque, materialColour(material));
    }
  }
}

float length(PixelPoint a, PixelPoint b) { return std::hypot(b.x - a.x, b.y - a.y); }

TEST(Dashes, AlongALine_DashThenGap) {
  const std::vector<PixelPoint> line{{0, 0}, {25, 0}};
  std::vector<PixelPoint> dashes;
  dashesAlong(line, false, 6, 4, dashes);
  const std::vector<float> starts{0, 10, 20};
  ASSERT_EQ(dashes.size(), 2 * starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i) {
    EXPECT_FLOAT_EQ(dashes[2 * i].x, starts[i]);
    EXPECT_FLOAT_EQ(dashes[2 * i + 1].x, std::min(starts[i] + 6, 25.0f));
  }
}

TEST(Dashes, RoundAClosedSquare_ThePatternCarriesOverCorners) {
  // 4 x 15 px = 60 px: six periods of 10, a dash across every corner but one.
  const std::vector<PixelPoint> square{{0, 0}, {15, 0}, {15, 15}, {0, 15}};
  std::vector<PixelPoint> dashes;
  dashesAlong(square, true, 6, 4, dashes);
  float drawn = 0;
  for (std::size_t i = 0; i < dashes.size(); i += 2) drawn += length(dashes[i], dashes[i + 1]);
  EXPECT_NEAR(drawn, 36, 1e-3);
  // The dash from 10 px runs 5 px to the corner and 1 px past it.
  EXPECT_FLOAT_EQ(dashes[2].x, 10);
  EXPECT_FLOAT_EQ(dashes[3].x, 15);
  EXPECT_FLOAT_EQ(dashes[4].x, 15);
  EXPECT_FLOAT_EQ(dashes[4].y, 0);
  EXPECT_FLOAT_EQ(dashes[5].y, 1);
}

}  // namespace
}  // namespace impulse::viewer
