// Filters, sensors and events over the wire: spawn options and descriptors
// carry the flags, SetShapeFlags changes them, and a client that asks for
// events receives each tick's, in order, while others receive none.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

// A ground box, a ball above it that reports contacts and hits, and a coin
// (a static sensor) the ball falls through on its way down.
struct Course {
  std::uint32_t ground = 0;
  std::uint32_t ball = 0;
  std::uint32_t coin = 0;
};

Course buildCourse(Client& client) {
  EXPECT_TRUE(result(client.request(client::clearWorld())).ok());
  Course course;
  client::SpawnOptions ground;
  ground.isStatic = true;
  ground.restitution = 0;
  const std::vector<client::Point> slab = {{0, 0}, {20, 0}, {20, 1}, {0, 1}};
  course.ground = result(client.request(client::spawnPolygon(slab, ground))).body_id();
  client::SpawnOptions coin;
  coin.isStatic = true;
  coin.flags.isSensor = true;
  course.coin = result(client.request(client::spawnCircle({10, 4}, 0.5, coin))).body_id();
  client::SpawnOptions ball;
  ball.restitution = 0;
  ball.flags.enableContactEvents = true;
  ball.flags.enableHitEvents = true;
  course.ball = result(client.request(client::spawnCircle({10, 6}, 0.25, ball))).body_id();
  return course;
}

TEST(EventsOverTheWire, ASubscriberHearsTheCoinTheLandingAndTheHitInTickOrder) {
  ServerProcess server({"--paused"});
  Client listener(localClient(server.port()));
  Client quiet(localClient(server.port()));
  const Course course = buildCourse(listener);
  ASSERT_NE(course.ball, 0u);
  const auto subscribed = listener.request(client::subscribeEvents(true));
  ASSERT_TRUE(result(subscribed).ok()) << errorOf(subscribed);

  ASSERT_TRUE(result(listener.request(client::step(90))).ok());
  listener.ping();
  quiet.ping();
  const std::vector<v1::Events> events = listener.takeEvents();
  EXPECT_TRUE(quiet.takeEvents().empty()) << "only subscribers receive events";

  int sensorBegins = 0, sensorEnds = 0, contactBegins = 0, hits = 0;
  std::uint64_t lastTick = 0, lastSequence = 0;
  for (const v1::Events& tick : events) {
    EXPECT_GT(tick.tick(), lastTick);
    EXPECT_EQ(tick.sequence(), lastSequence + 1) << "no gap for a client that reads";
    lastTick = tick.tick();
    lastSequence = tick.sequence();
    for (const auto& visit : tick.sensor_begins()) {
      EXPECT_EQ(visit.sensor_body(), course.coin);
      EXPECT_EQ(visit.visitor_body(), course.ball);
      ++sensorBegins;
    }
    sensorEnds += tick.sensor_ends_size();
    for (const auto& begin : tick.contact_begins()) {
      EXPECT_EQ(begin.body_a() == course.ball ? begin.body_b() : begin.body_a(), course.ground);
      EXPECT_LT(begin.shape_a(), begin.shape_b());
      ++contactBegins;
    }
    for (const auto& hit : tick.hits()) {
      // Fallen 4.75 m onto the slab: sqrt(2 g h) = 9.65 m/s, less a step of gravity.
      EXPECT_NEAR(hit.approach_speed(), std::sqrt(2 * 9.81 * 4.75), 0.25);
      EXPECT_NEAR(hit.point().y(), 1, 0.1);
      ++hits;
    }
  }
  EXPECT_EQ(sensorBegins, 1);
  EXPECT_EQ(sensorEnds, 1);
  EXPECT_EQ(contactBegins, 1);
  EXPECT_GE(hits, 1);

  // The descriptor shows the flags and the shape ids events name.
  const auto info = listener.request(client::queryBody(course.coin)).body_info();
  EXPECT_TRUE(info.descriptor().shape_flags().is_sensor());
  ASSERT_EQ(info.descriptor().shape_ids_size(), 1);
  EXPECT_EQ(server.stop(), 0);
}

TEST(EventsOverTheWire, FlagsChangedAtRunTimeLetTheBallFallThrough) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const Course course = buildCourse(client);
  ASSERT_TRUE(result(client.request(client::step(90))).ok());
  const double resting = client.request(client::queryBody(course.ball)).body_info().state().position().y();
  EXPECT_NEAR(resting, 1.25, 0.02);

  ShapeInteraction ghost;
  ghost.filter.maskBits = 0;
  const auto changed = client.request(client::setShapeFlags(course.ball, ghost));
  ASSERT_TRUE(result(changed).ok()) << errorOf(changed);
  ASSERT_TRUE(result(client.request(client::step(60))).ok());
  EXPECT_LT(client.request(client::queryBody(course.ball)).body_info().state().position().y(), -2);
  client.ping();
  const auto* mirrored = client.mirror().find(BodyId{course.ball});
  ASSERT_NE(mirrored, nullptr);
  EXPECT_EQ(mirrored->flags.filter.maskBits, 0u) << "the descriptor was sent again";

  const auto unknown = client.request(client::setShapeFlags(987654, ghost));
  EXPECT_FALSE(result(unknown).ok());
  EXPECT_NE(errorOf(unknown).find("unknown body"), std::string::npos) << errorOf(unknown);
  EXPECT_EQ(server.stop(), 0);
}

TEST(EventsOverTheWire, UnsubscribingStopsTheStream) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  buildCourse(client);
  ASSERT_TRUE(result(client.request(client::subscribeEvents(true))).ok());
  ASSERT_TRUE(result(client.request(client::subscribeEvents(false))).ok());
  ASSERT_TRUE(result(client.request(client::step(90))).ok());
  client.ping();
  EXPECT_TRUE(client.takeEvents().empty()) << "unsubscribed";
  EXPECT_EQ(server.stop(), 0);
}

}  // namespace
}  // namespace impulse::net_test
