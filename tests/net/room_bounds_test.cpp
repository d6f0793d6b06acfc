// Bounds per room (Hello.room_min, room_max): the admin making a room gives
// its world bounds, within the stated limits; anything else is refused with
// an Error naming the field, and no room is made.
#include <cmath>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

v1::Vec2 point(double x, double y) {
  v1::Vec2 out;
  out.set_x(x);
  out.set_y(y);
  return out;
}

/// The Error a Hello for `room` with the given corners gets (nothing if it is welcomed).
std::optional<std::string> boundsRefusal(std::uint16_t port, const std::string& room, std::optional<v1::Vec2> min,
                                         std::optional<v1::Vec2> max, const std::string& token = "") {
  RawConnection raw(port);
  v1::ClientMessage hello;
  hello.mutable_hello()->set_protocol_version(1);
  hello.mutable_hello()->set_room(room);
  hello.mutable_hello()->set_token(token);
  if (min) *hello.mutable_hello()->mutable_room_min() = *min;
  if (max) *hello.mutable_hello()->mutable_room_max() = *max;
  raw.sendMessage(hello);
  const auto reply = raw.receive(milliseconds(3000));
  if (!reply || !reply->has_error()) return std::nullopt;
  return reply->error().message();
}

std::uint32_t roomCount(Client& client) {
  return std::uint32_t(client.request(client::listRooms()).room_list().rooms_size());
}

TEST(RoomBounds, TheAdminMakesALevelSizedRoom) {
  ServerProcess server;
  auto options = localClient(server.port(), "maker", false);
  options.room = "level";
  options.roomBounds = client::Box{{-1000, -100}, {3000, 500}};
  Client maker(options);
  ASSERT_TRUE(result(maker.request(client::clearWorld())).ok()) << "the preset's bodies";
  EXPECT_EQ(maker.welcome().world_min().x(), -1000);
  EXPECT_EQ(maker.welcome().world_max().x(), 3000);
  EXPECT_EQ(maker.welcome().world_max().y(), 500);
  const v1::CommandResult far = result(maker.request(client::spawnCircle({2500, 10}, 0.5)));
  EXPECT_TRUE(far.ok()) << far.error();
  const v1::CommandResult outside = result(maker.request(client::spawnCircle({3500, 10}, 0.5)));
  EXPECT_FALSE(outside.ok());

  auto joining = localClient(server.port(), "joiner");
  joining.room = "level";
  Client joiner(joining);
  EXPECT_EQ(joiner.welcome().world_min().x(), -1000) << "a joiner takes the room's bounds";
  ASSERT_EQ(joiner.mirror().bodies().size(), 1u);
  EXPECT_NEAR(joiner.mirror().bodies().begin()->second.state.position.x(), 2500, 0.01);
  const v1::ServerMessage list = joiner.request(client::listRooms());
  for (const auto& room : list.room_list().rooms()) {
    EXPECT_EQ(room.world_max().x(), room.name() == "level" ? 3000 : 50) << room.name();
  }
}

TEST(RoomBounds, BadBoundsAreRefusedNamingTheFieldAndMakeNoRoom) {
  ServerProcess server;
  Client observer(localClient(server.port(), "observer", false));
  const std::vector<std::tuple<std::optional<v1::Vec2>, std::optional<v1::Vec2>, std::string>> cases = {
      {point(0, 0), std::nullopt, "hello.room_max is missing"},
      {std::nullopt, point(5, 5), "hello.room_min is missing"},
      {point(std::nan(""), 0), point(5, 5), "hello.room_min is not a finite point"},
      {point(0, 0), point(2e6, 5), "hello.room_max (2000000, 5) lies outside the largest room: each coordinate must be within +-1000000 m"},
      {point(0, 0), point(20001, 5), "each side may be at most 20000 m"},
      {point(0, 0), point(0.5, 5), "at least 1 m"},
      {point(10, 0), point(0, 5), "at least 1 m"},
  };
  for (const auto& [min, max, expected] : cases) {
    const auto refusal = boundsRefusal(server.port(), "bad", min, max);
    ASSERT_TRUE(refusal) << expected;
    EXPECT_TRUE(mentions(*refusal, expected)) << *refusal;
  }
  EXPECT_EQ(roomCount(observer), 1u) << "only the default room";

  const auto differing = boundsRefusal(server.port(), "default", point(-50, -50), point(50, 50));
  ASSERT_TRUE(differing);
  EXPECT_TRUE(mentions(*differing, "room default exists with bounds (-25, -25) to (50, 45) m")) << *differing;
}

TEST(RoomBounds, ARoomFarOutGetsTheOriginItsWorldComputesAround) {
  ServerProcess server;
  auto options = localClient(server.port(), "maker", false);
  options.room = "far";
  options.roomBounds = client::Box{{985000, -20000}, {999000, -15000}};
  Client maker(options);
  EXPECT_EQ(maker.welcome().world_origin().x(), 990000) << "the centre (992000, -17500) rounded to 10 km";
  EXPECT_EQ(maker.welcome().world_origin().y(), -20000);
  EXPECT_EQ(maker.welcome().world_min().x(), 985000);
  const v1::ServerMessage list = maker.request(client::listRooms());
  for (const auto& room : list.room_list().rooms()) {
    EXPECT_EQ(room.world_origin().x(), room.name() == "far" ? 990000 : 0) << room.name();
  }
}

TEST(RoomBounds, PlayersMayNotGiveBounds) {
  ServerProcess server({"--token", "player", "--admin-token", "admin"});
  const auto refusal = boundsRefusal(server.port(), "mine", point(0, 0), point(100, 100), "player");
  ASSERT_TRUE(refusal);
  EXPECT_TRUE(mentions(*refusal, "only the admin role")) << *refusal;
  EXPECT_FALSE(boundsRefusal(server.port(), "mine", point(0, 0), point(100, 100), "admin")) << "the admin may";
}

}  // namespace
}  // namespace impulse::net_test
