// Queries over the wire: ray casts, shape casts and box overlaps answered
// from the world the last tick left, filters honoured, and bad input
// refused with the field named.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

constexpr std::uint64_t kCrates = 1 << 1;

// A floor whose top is y = 1, and a crate (category 2) resting on it at x = 10.
struct Yard {
  std::uint32_t floor = 0;
  std::uint32_t crate = 0;
};

Yard buildYard(Client& client) {
  EXPECT_TRUE(result(client.request(client::clearWorld())).ok());
  Yard yard;
  client::SpawnOptions floor;
  floor.isStatic = true;
  const std::vector<client::Point> slab = {{0, 0}, {20, 0}, {20, 1}, {0, 1}};
  yard.floor = result(client.request(client::spawnPolygon(slab, floor))).body_id();
  client::SpawnOptions crate;
  crate.flags.filter.categoryBits = kCrates;
  const std::vector<client::Point> box = {{9.5, 1}, {10.5, 1}, {10.5, 2}, {9.5, 2}};
  yard.crate = result(client.request(client::spawnPolygon(box, crate))).body_id();
  return yard;
}

TEST(QueriesOverTheWire, ARayFindsTheCrateThenTheFloorAndAFilterSeesThroughTheCrate) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const Yard yard = buildYard(client);

  const auto closest = client.request(client::rayCast({10, 5}, {0, -10})).query_result();
  ASSERT_EQ(closest.hits_size(), 1);
  EXPECT_EQ(closest.hits(0).body_id(), yard.crate);
  EXPECT_NEAR(closest.hits(0).point().y(), 2, 1e-4);
  EXPECT_NEAR(closest.hits(0).normal().y(), 1, 1e-5);
  EXPECT_NEAR(closest.hits(0).fraction(), 0.3, 1e-5);

  const auto all = client.request(client::rayCast({10, 5}, {0, -10}, true)).query_result();
  ASSERT_EQ(all.hits_size(), 2);
  EXPECT_EQ(all.hits(0).body_id(), yard.crate);
  EXPECT_EQ(all.hits(1).body_id(), yard.floor);
  EXPECT_NEAR(all.hits(1).point().y(), 1, 1e-4);

  const auto limited = client.request(client::rayCast({10, 5}, {0, -10}, true, {}, 1)).query_result();
  EXPECT_EQ(limited.hits_size(), 1);
  EXPECT_TRUE(limited.truncated());

  QueryFilter groundOnly;
  groundOnly.maskBits = ~kCrates;
  const auto filtered = client.request(client::rayCast({10, 5}, {0, -10}, false, groundOnly)).query_result();
  ASSERT_EQ(filtered.hits_size(), 1);
  EXPECT_EQ(filtered.hits(0).body_id(), yard.floor);
  EXPECT_EQ(server.stop(), 0);
}

TEST(QueriesOverTheWire, AShapeCastStopsOnTheCrateAndABoxListsWhatItHolds) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const Yard yard = buildYard(client);

  // A ball of radius 0.5 dropped from y = 6 onto the crate's top (y = 2):
  // it touches after 3.5 of its 10 m.
  client::BodyPart ball{client::BodyPart::Kind::Circle, {0, 0}, {}, 0.5};
  const auto cast = client.request(client::shapeCast({10, 6}, 0, ball, {0, -10})).query_result();
  ASSERT_EQ(cast.hits_size(), 1);
  EXPECT_EQ(cast.hits(0).body_id(), yard.crate);
  EXPECT_NEAR(cast.hits(0).fraction(), 0.35, 1e-3);

  const auto box = client.request(client::queryAabb({9, 0.5}, {11, 1.5})).query_result();
  ASSERT_EQ(box.shape_ids_size(), 2);
  EXPECT_EQ(box.body_ids_size(), 2);
  const auto nothing = client.request(client::queryAabb({30, 30}, {31, 31})).query_result();
  EXPECT_EQ(nothing.shape_ids_size(), 0);
  EXPECT_EQ(server.stop(), 0);
}

TEST(QueriesOverTheWire, BadQueriesAreRefusedNamingTheField) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  buildYard(client);
  const auto zero = client.request(client::rayCast({10, 5}, {0, 0}));
  EXPECT_FALSE(result(zero).ok());
  EXPECT_NE(errorOf(zero).find("raycast"), std::string::npos) << errorOf(zero);

  const auto notANumber = client.request(client::rayCast({std::nan(""), 5}, {0, -1}));
  EXPECT_FALSE(result(notANumber).ok());
  EXPECT_NE(errorOf(notANumber).find("raycast X"), std::string::npos) << errorOf(notANumber);

  const auto tooMany = client.request(client::rayCast({10, 5}, {0, -10}, true, {}, 100000));
  EXPECT_FALSE(result(tooMany).ok());
  EXPECT_NE(errorOf(tooMany).find("4096"), std::string::npos) << errorOf(tooMany);

  const auto inverted = client.request(client::queryAabb({11, 1.5}, {9, 0.5}));
  EXPECT_FALSE(result(inverted).ok());
  EXPECT_NE(errorOf(inverted).find("overlap"), std::string::npos) << errorOf(inverted);

  v1::ClientMessage segmentCast = client::shapeCast({10, 6}, 0, {}, {0, -10});
  segmentCast.mutable_shape_cast()->mutable_shape()->mutable_segment();
  const auto segment = client.request(segmentCast);
  EXPECT_FALSE(result(segment).ok()) << "a segment cannot be cast";

  // The world is untouched and still answers.
  EXPECT_EQ(client.request(client::rayCast({10, 5}, {0, -10})).query_result().hits_size(), 1);
  EXPECT_EQ(server.stop(), 0);
}

}  // namespace
}  // namespace impulse::net_test
