// Collision filters, sensors and contact events: who collides with whom,
// what sensors see, and the events a step reports, in a fixed order across
// runs and across a save and load.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "world_test_support.h"

namespace impulse::test {
namespace {

constexpr std::uint64_t kPlayers = 1u << 1;
constexpr std::uint64_t kBullets = 1u << 2;

struct Dropped {
  BodyId body;
  ShapeId shape;
};

// Ground that does not bounce (restitution mixes to the larger of two).
BodyId addGround(World& world, ShapeInteraction interaction = {}) {
  BodyOptions options;
  options.properties.isStatic = true;
  options.materialOverride.restitution = 0;
  options.interaction = interaction;
  const Vec2 corners[] = {Vec2(-20, -1), Vec2(20, -1), Vec2(20, 0), Vec2(-20, 0)};
  CreateResult ground = world.createPolygon(corners, options);
  EXPECT_TRUE(ground.ok()) << ground.error;
  return ground.id;
}

ShapeId firstShape(const World& world, BodyId body) {
  std::optional<BodyDescription> description = world.bodyDescription(body);
  EXPECT_TRUE(description.has_value());
  return description ? description->shapes.front().id : ShapeId{};
}

// A ball that does not bounce, so it lands once.
Dropped dropBall(World& world, Vec2 center, ShapeInteraction interaction = {}) {
  BodyOptions options;
  options.interaction = interaction;
  options.materialOverride.restitution = 0;
  CreateResult ball = world.createCircle(center, Real(0.25), options);
  EXPECT_TRUE(ball.ok()) << ball.error;
  return {ball.id, firstShape(world, ball.id)};
}

ShapeInteraction withEvents() {
  ShapeInteraction interaction;
  interaction.enableContactEvents = true;
  interaction.enableHitEvents = true;
  return interaction;
}

ShapeInteraction inCategory(std::uint64_t category, std::uint64_t mask) {
  ShapeInteraction interaction;
  interaction.filter.categoryBits = category;
  interaction.filter.maskBits = mask;
  return interaction;
}

// Options of a sensor body: static, or kinematic.
BodyOptions sensorBody(bool kinematic = false) {
  BodyOptions options;
  options.properties.isStatic = !kinematic;
  options.properties.isKinematic = kinematic;
  options.interaction.isSensor = true;
  return options;
}

TEST(CollisionFilter, FollowsCategoriesMasksAndGroups) {
  CollisionFilter player{kPlayers, ~kBullets, 0};
  CollisionFilter bullet{kBullets, ~std::uint64_t{0}, 0};
  CollisionFilter wall{};
  EXPECT_FALSE(shouldCollide(player, bullet));
  EXPECT_TRUE(shouldCollide(bullet, wall));
  EXPECT_TRUE(shouldCollide(player, wall));
  // A shared negative group never collides, a shared positive one always does.
  EXPECT_FALSE(shouldCollide({1, ~0ull, -3}, {1, ~0ull, -3}));
  EXPECT_TRUE(shouldCollide({kPlayers, 0, 4}, {kBullets, 0, 4}));
  // Different groups fall back to the bits.
  EXPECT_FALSE(shouldCollide({kPlayers, 0, 4}, {kBullets, 0, 5}));
  EXPECT_TRUE(queryAccepts(QueryFilter{}, wall));
  EXPECT_FALSE(queryAccepts({1, kPlayers}, bullet));
}

TEST(CollisionFilter, MaskedBallFallsThroughTheGroundAndOthersRest) {
  World world;
  addGround(world, inCategory(kPlayers, ~std::uint64_t{0}));
  Dropped ghost = dropBall(world, Vec2(-2, 2), inCategory(kBullets, ~kPlayers));
  Dropped ball = dropBall(world, Vec2(2, 2));
  simulate(world, 2.0);
  EXPECT_LT(stateOf(world, ghost.body).position.y(), -5);
  EXPECT_NEAR(stateOf(world, ball.body).position.y(), 0.25, 0.02);
}

TEST(CollisionFilter, ChangingAFilterEndsTheContactAndRestoringItCatchesTheBody) {
  World world;
  addGround(world);
  Dropped ball = dropBall(world, Vec2(0, 1), withEvents());
  simulate(world, 1.5);
  ASSERT_NEAR(stateOf(world, ball.body).position.y(), 0.25, 0.02);

  ShapeInteraction passing = withEvents();
  passing.filter.maskBits = 0;
  ASSERT_TRUE(world.setShapeInteraction(ball.shape, passing).ok());
  EXPECT_EQ(world.shapeInteraction(ball.shape)->filter.maskBits, 0u);
  world.step(kDt);
  ASSERT_EQ(world.events().contactEnds.size(), 1u);
  EXPECT_EQ(world.events().contactEnds[0].bodyB, ball.body);
  simulate(world, 0.3);
  const Real sunk = stateOf(world, ball.body).position.y();
  EXPECT_LT(sunk, 0);  // through the ground's top

  // Allowed again below the ground's top face: the overlap is pushed out.
  ASSERT_TRUE(world.setShapeInteraction(ball.shape, withEvents()).ok());
  world.step(kDt);
  EXPECT_EQ(world.events().contactBegins.size(), 1u);
  EXPECT_FALSE(world.setShapeInteraction(ShapeId{12345}, {}).ok());
}

TEST(Sensor, ReportsShapesEnteringAndLeavingAndNeverCollides) {
  World world;
  const BodyOptions options = sensorBody();
  const Vec2 zone[] = {Vec2(-1, 4), Vec2(1, 4), Vec2(1, 5), Vec2(-1, 5)};
  CreateResult trigger = world.createPolygon(zone, options);
  ASSERT_TRUE(trigger.ok()) << trigger.error;
  const ShapeId triggerShape = firstShape(world, trigger.id);

  ShapeInteraction unseen;
  unseen.enableSensorEvents = false;
  Dropped ball = dropBall(world, Vec2(0, 7));
  Dropped hidden = dropBall(world, Vec2(0.7f, 7), unseen);

  std::vector<int> beginSteps, endSteps;
  for (int i = 0; i < stepsFor(1.5); ++i) {
    world.step(kDt);
    for (const SensorEvent& event : world.events().sensorBegins) {
      EXPECT_EQ(event.sensor, triggerShape);
      EXPECT_EQ(event.visitor, ball.shape);
      EXPECT_EQ(event.visitorBody, ball.body);
      beginSteps.push_back(i);
    }
    for (const SensorEvent& event : world.events().sensorEnds) {
      EXPECT_EQ(event.visitor, ball.shape);
      endSteps.push_back(i);
    }
  }
  ASSERT_EQ(beginSteps.size(), 1u);
  ASSERT_EQ(endSteps.size(), 1u);
  // Free fall from y = 7: the ball's bottom (6.75) reaches the zone's top (5)
  // after sqrt(2 * 1.75 / g) s and its top (7.25) leaves the bottom (4)
  // after sqrt(2 * 3.25 / g) s; one step either way.
  EXPECT_NEAR(beginSteps[0] + 1, std::sqrt(2 * 1.75 / kG) / kDt, 1.5);
  EXPECT_NEAR(endSteps[0] + 1, std::sqrt(2 * 3.25 / kG) / kDt, 1.5);
  EXPECT_LT(stateOf(world, ball.body).position.y(), 0);  // it fell through
  EXPECT_LT(stateOf(world, hidden.body).position.y(), 0);
}

TEST(Sensor, RemovedVisitorEndsItsVisit) {
  World world;
  const BodyOptions options = sensorBody(true);
  CreateResult zone = world.createCircle(Vec2(0, 0), 2, options);
  ASSERT_TRUE(zone.ok());
  BodyOptions floating;
  floating.properties.ignoreGravity = true;
  CreateResult coin = world.createCircle(Vec2(1, 0), Real(0.25), floating);
  ASSERT_TRUE(coin.ok());
  world.step(kDt);
  ASSERT_EQ(world.events().sensorBegins.size(), 1u);
  world.step(kDt);
  EXPECT_TRUE(world.events().sensorBegins.empty());
  ASSERT_TRUE(world.destroyBody(coin.id));
  world.step(kDt);
  ASSERT_EQ(world.events().sensorEnds.size(), 1u);
  EXPECT_EQ(world.events().sensorEnds[0].visitorBody, coin.id);
}

TEST(ContactEvents, ShapesThatAskNothingReportNothing) {
  World world;
  addGround(world);
  dropBall(world, Vec2(0, 1));
  for (int i = 0; i < stepsFor(1.0); ++i) {
    world.step(kDt);
    EXPECT_TRUE(world.events().empty());
  }
}

TEST(ContactEvents, ALandingBeginsOnceAndHitsAtTheFallSpeed) {
  World world;
  addGround(world);
  const Real height = 2;  // of the ball's bottom above the ground
  Dropped ball = dropBall(world, Vec2(0, height + Real(0.25)), withEvents());
  int begins = 0;
  std::vector<ContactHitEvent> hits;
  for (int i = 0; i < stepsFor(2.0); ++i) {
    world.step(kDt);
    begins += static_cast<int>(world.events().contactBegins.size());
    hits.insert(hits.end(), world.events().contactHits.begin(), world.events().contactHits.end());
  }
  EXPECT_EQ(begins, 1);
  ASSERT_GE(hits.size(), 1u);
  const ContactHitEvent& hit = hits.front();
  // The ball's speed at the start of the step it lands in: sqrt(2 g h) less
  // at most one step of gravity (g dt = 0.16 m/s).
  EXPECT_NEAR(hit.approachSpeed, std::sqrt(2 * kG * height), 0.2);
  EXPECT_NEAR(hit.point.y(), 0, 0.1);
  EXPECT_NEAR(std::abs(hit.normal.y()), 1, 1e-3);
  // The normal points from shape A to shape B: up when the ground is A.
  const bool groundIsA = hit.bodyB == ball.body;
  EXPECT_GT(groundIsA ? hit.normal.y() : -hit.normal.y(), 0);
  // A resting ball makes no more hits.
  EXPECT_LE(hits.size(), 2u);
}

TEST(ContactEvents, RemovingATouchingBodyEndsItsContacts) {
  World world;
  addGround(world);
  Dropped ball = dropBall(world, Vec2(0, 0.5), withEvents());
  simulate(world, 0.5);
  ASSERT_TRUE(world.destroyBody(ball.body));
  world.step(kDt);
  ASSERT_EQ(world.events().contactEnds.size(), 1u);
  EXPECT_EQ(world.events().contactEnds[0].bodyB, ball.body);
}

// Every event of a step, as one comparable record.
struct StepRecord {
  std::vector<ContactTouchEvent> begins;
  std::vector<ContactTouchEvent> ends;
  std::vector<ContactHitEvent> hits;
  std::vector<SensorEvent> sensorBegins, sensorEnds;
  friend bool operator==(const StepRecord&, const StepRecord&) = default;
};

StepRecord recordOf(const StepEvents& events) {
  return {events.contactBegins, events.contactEnds, events.contactHits, events.sensorBegins, events.sensorEnds};
}

// A pile of boxes and balls tumbling through a sensor onto the ground:
// many begins, ends, hits and visits.
void buildPile(World& world) {
  addGround(world, withEvents());
  const BodyOptions zone = sensorBody();
  const Vec2 band[] = {Vec2(-6, 1), Vec2(6, 1), Vec2(6, 2), Vec2(-6, 2)};
  ASSERT_TRUE(world.createPolygon(band, zone).ok());
  BodyOptions options;
  options.interaction = withEvents();
  for (int i = 0; i < 60; ++i) {
    const Vec2 at(Real(-4 + (i % 10) * 0.9), Real(3 + (i / 10) * 1.1));
    if (i % 2 == 0) {
      ASSERT_TRUE(world.createCircle(at, Real(0.35), options).ok());
    } else {
      const Vec2 box[] = {at + Vec2(-0.35f, -0.3f), at + Vec2(0.35f, -0.3f), at + Vec2(0.35f, 0.3f),
                          at + Vec2(-0.35f, 0.3f)};
      ASSERT_TRUE(world.createPolygon(box, options).ok());
    }
  }
}

std::vector<StepRecord> run(World& world, int steps) {
  std::vector<StepRecord> records;
  for (int i = 0; i < steps; ++i) {
    world.step(kDt);
    records.push_back(recordOf(world.events()));
  }
  return records;
}

TEST(EventOrder, SameEventsInTheSameOrderAcrossRunsAndASaveAndLoad) {
  World first;
  buildPile(first);
  const std::vector<StepRecord> before = run(first, 60);
  const WorldState saved = first.exportState();
  const std::vector<StepRecord> after = run(first, 120);

  World second;
  buildPile(second);
  EXPECT_EQ(run(second, 60), before);
  EXPECT_EQ(run(second, 120), after);

  World loaded;
  ASSERT_TRUE(loaded.importState(saved).ok());
  EXPECT_EQ(run(loaded, 120), after);

  int begins = 0, hits = 0, visits = 0;
  std::vector<StepRecord> all = before;
  all.insert(all.end(), after.begin(), after.end());
  for (const StepRecord& record : all) {
    begins += static_cast<int>(record.begins.size());
    hits += static_cast<int>(record.hits.size());
    visits += static_cast<int>(record.sensorBegins.size());
    for (std::size_t i = 1; i < record.begins.size(); ++i) {
      EXPECT_LT(record.begins[i - 1].shapeA.value, record.begins[i].shapeA.value + 1);
    }
  }
  // The comparison means something only if the pile made events.
  EXPECT_GT(begins, 20);
  EXPECT_GT(hits, 5);
  EXPECT_GT(visits, 20);
}

}  // namespace
}  // namespace impulse::test
