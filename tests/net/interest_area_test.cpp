// Areas of interest (SetInterestArea): a subscriber receives only the bodies
// inside its rectangle, with bodies entering and leaving it reported; bad
// areas are refused and change nothing.
#include <cmath>
#include <set>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

// Eleven resting circles along y = 5 at x = 0, 2, ..., 20, and a mover
// heading right at 6 m/s along y = 7 from x = 2; none feels gravity.
struct Row {
  std::vector<std::uint32_t> resting;  ///< by x / 2
  std::uint32_t mover = 0;
};

// Clears the preset's bodies first.
Row spawnRow(Client& driver) {
  EXPECT_TRUE(result(driver.request(client::clearWorld())).ok());
  std::vector<v1::ClientMessage> commands;
  client::SpawnOptions still;
  still.ignoreGravity = true;
  for (int i = 0; i <= 10; ++i) commands.push_back(client::spawnCircle({2.0 * i, 5}, 0.3, still));
  client::SpawnOptions moving = still;
  moving.velocityX = 6;
  commands.push_back(client::spawnCircle({2, 7}, 0.3, moving));
  Row row;
  for (const auto& reply : requestAll(driver, commands)) row.resting.push_back(result(reply).body_id());
  row.mover = row.resting.back();
  row.resting.pop_back();
  return row;
}

std::set<std::uint32_t> mirrored(const Client& client) {
  std::set<std::uint32_t> ids;
  for (const auto& [id, body] : client.mirror().bodies()) ids.insert(id);
  return ids;
}

// Steps the paused world and waits until `watcher` applied the snapshot of
// the step's last tick.
void stepAndWatch(Client& driver, Client& watcher, std::uint32_t ticks) {
  const std::uint64_t tick = result(driver.request(client::step(ticks))).tick();
  while (watcher.mirror().tick() < tick) ASSERT_TRUE(watcher.awaitSnapshot(milliseconds(5000)));
}

v1::ClientMessage area(double x1, double y1, double x2, double y2) {
  return client::setInterestArea(client::Box{{x1, y1}, {x2, y2}});
}

TEST(InterestArea, SubscriberHoldsOnlyTheBodiesInsideAndSeesThemComeAndGo) {
  ServerProcess server({"--paused"});
  Client driver(localClient(server.port(), "driver", false));
  const Row row = spawnRow(driver);
  Client watcher(localClient(server.port(), "watcher"));
  ASSERT_TRUE(result(watcher.request(area(7, 0, 13, 10))).ok());
  std::vector<v1::Snapshot> seen;
  watcher.onSnapshot([&](const v1::Snapshot& snapshot, std::size_t) { seen.push_back(snapshot); });

  stepAndWatch(driver, watcher, 1);
  const std::set<std::uint32_t> middle{row.resting[4], row.resting[5], row.resting[6]};
  EXPECT_EQ(mirrored(watcher), middle) << "the circles at x = 8, 10, 12; not the mover at x = 2";

  stepAndWatch(driver, watcher, 60);  // the mover is at x = 8
  auto withMover = middle;
  withMover.insert(row.mover);
  EXPECT_EQ(mirrored(watcher), withMover);
  const client::MirrorBody* mover = watcher.mirror().find(BodyId{row.mover});
  ASSERT_TRUE(mover);
  EXPECT_NEAR(mover->state.position.x(), 8.1, 0.2) << "it came with its state";

  stepAndWatch(driver, watcher, 60);  // at x = 14: out
  EXPECT_EQ(mirrored(watcher), middle);
  bool reportedLeaving = false;
  for (const auto& snapshot : seen) {
    for (const std::uint32_t id : snapshot.left_area()) reportedLeaving |= id == row.mover;
    EXPECT_LE(snapshot.added_size() + snapshot.bodies_size(), 8) << "never the whole room";
  }
  EXPECT_TRUE(reportedLeaving);

  ASSERT_TRUE(result(watcher.request(client::setInterestArea(std::nullopt))).ok());
  stepAndWatch(driver, watcher, 1);
  EXPECT_EQ(mirrored(watcher).size(), 12u) << "the whole room again";
}

TEST(InterestArea, InAPausedRoomANewAreaComesAtOnce_WithoutAStep) {
  ServerProcess server({"--paused"});
  Client driver(localClient(server.port(), "driver", false));
  const Row row = spawnRow(driver);
  Client watcher(localClient(server.port(), "watcher"));
  while (mirrored(watcher).size() != 12) ASSERT_TRUE(watcher.awaitSnapshot(milliseconds(5000)));
  const std::uint64_t pausedAt = watcher.mirror().tick();

  ASSERT_TRUE(result(watcher.request(area(7, 0, 13, 10))).ok());
  const std::set<std::uint32_t> middle{row.resting[4], row.resting[5], row.resting[6]};
  while (mirrored(watcher) != middle) ASSERT_TRUE(watcher.awaitSnapshot(milliseconds(5000)));
  EXPECT_EQ(watcher.mirror().tick(), pausedAt) << "the room did not step";
}

std::set<std::uint32_t> mirroredJoints(const Client& client) {
  std::set<std::uint32_t> ids;
  for (const auto& [id, joint] : client.mirror().joints()) ids.insert(id);
  return ids;
}

std::set<std::uint32_t> mirroredFields(const Client& client) {
  std::set<std::uint32_t> ids;
  for (const auto& [id, field] : client.mirror().fields()) ids.insert(id);
  return ids;
}

v1::ClientMessage fanAt(double x, double y) {
  v1::Fan fan;
  fan.mutable_position()->set_x(x);
  fan.mutable_position()->set_y(y);
  fan.mutable_direction()->set_x(1);
  fan.set_speed(5);
  fan.set_range(2);
  fan.set_spread(0.3);
  return client::fanField(fan);
}

// A joint goes to an area holding either of its bodies, a field to an area
// its reach overlaps (gravitation reaches everywhere); as the area moves,
// they come and go with the bodies.
TEST(InterestArea, JointsAndFieldsGoOnlyWhereTheyReach) {
  ServerProcess server({"--paused"});
  Client driver(localClient(server.port(), "driver", false));
  const Row row = spawnRow(driver);
  const auto joined = [&](std::size_t a, std::size_t b) {
    const client::Point pointA{2.0 * double(a), 5};
    const client::Point pointB{2.0 * double(b), 5};
    return result(driver.request(client::distanceJoint({row.resting[a], row.resting[b], pointA, pointB}, {})))
        .joint_id();
  };
  const std::uint32_t left = joined(0, 1);     // x = 0 and 2
  const std::uint32_t across = joined(4, 7);   // x = 8 and 14
  const std::uint32_t right = joined(9, 10);   // x = 18 and 20
  const std::uint32_t leftFan = result(driver.request(fanAt(1, 5))).field_id();
  const std::uint32_t rightFan = result(driver.request(fanAt(19, 5))).field_id();
  const std::uint32_t gravitation = result(driver.request(client::gravitationField(1))).field_id();

  Client watcher(localClient(server.port(), "watcher"));
  ASSERT_TRUE(result(watcher.request(area(-1, 0, 9, 10))).ok());
  stepAndWatch(driver, watcher, 1);
  EXPECT_EQ(mirroredJoints(watcher), (std::set{left, across})) << "full snapshot of the area";
  EXPECT_EQ(mirroredFields(watcher), (std::set{leftFan, gravitation}));

  ASSERT_TRUE(result(watcher.request(area(13, 0, 23, 10))).ok());
  stepAndWatch(driver, watcher, 1);
  EXPECT_EQ(mirroredJoints(watcher), (std::set{across, right})) << "a delta: the left joint left with its bodies";
  EXPECT_EQ(mirroredFields(watcher), (std::set{rightFan, gravitation}));

  ASSERT_TRUE(result(driver.request(client::removeJoint(across))).ok());
  ASSERT_TRUE(result(driver.request(client::removeField(rightFan))).ok());
  stepAndWatch(driver, watcher, 1);
  EXPECT_EQ(mirroredJoints(watcher), (std::set{right}));
  EXPECT_EQ(mirroredFields(watcher), (std::set{gravitation}));
}

TEST(InterestArea, BadAreasAreRefusedNamingTheFieldAndChangeNothing) {
  ServerProcess server({"--paused"});
  Client driver(localClient(server.port(), "driver", false));
  spawnRow(driver);
  Client watcher(localClient(server.port(), "watcher"));
  v1::ClientMessage onlyMin = area(0, 0, 1, 1);
  onlyMin.mutable_set_interest_area()->clear_max();
  const std::vector<std::pair<v1::ClientMessage, std::string>> cases = {
      {area(3, 3, 3, 8), "area is 0 m wide and 5 m high: area X2 Y2 must exceed area X1 Y1 in x and y"},
      {area(5, 0, 1, 8), "area is -4 m wide and 8 m high: area X2 Y2 must exceed area X1 Y1"},
      {area(-15000, 0, 15000, 8), "each side may be at most 20000 m"},
      {area(std::nan(""), 0, 1, 1), "area X1 Y1 is not a finite point"},
      {area(0, 0, 1, INFINITY), "area X2 Y2 is not a finite point"},
      {onlyMin, "area X2 Y2 is missing"},
  };
  for (const auto& [command, expected] : cases) {
    const v1::CommandResult refused = result(watcher.request(command));
    EXPECT_FALSE(refused.ok());
    EXPECT_TRUE(mentions(refused.error(), expected)) << refused.error();
  }
  stepAndWatch(driver, watcher, 1);
  EXPECT_EQ(mirrored(watcher).size(), 12u) << "still the whole room";
}

TEST(InterestArea, QuantizedSubscribersAreRefused) {
  ServerProcess server({"--paused"});
  auto options = localClient(server.port(), "compact");
  options.snapshotEncoding = v1::SNAPSHOT_ENCODING_QUANTIZED;
  Client compact(options);
  const v1::CommandResult refused = result(compact.request(area(0, 0, 5, 5)));
  EXPECT_FALSE(refused.ok());
  EXPECT_TRUE(mentions(refused.error(), "SNAPSHOT_ENCODING_PLAIN")) << refused.error();
}

}  // namespace
}  // namespace impulse::net_test
