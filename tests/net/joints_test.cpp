// Joints on the wire (docs/protocol.md, "Joints"): each command accepted and
// answered, refused with an error naming the field, and carried by
// snapshots (added, removed, every joint in a full snapshot, and the joints
// a removed body takes with it).
#include <limits>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

std::uint32_t spawnedBall(Client& client, client::Point at, bool isStatic = false) {
  client::SpawnOptions options;
  options.isStatic = isStatic;
  const auto reply = client.request(client::spawnCircle(at, 0.3, options));
  EXPECT_TRUE(result(reply).ok()) << result(reply).error();
  return result(reply).body_id();
}

// A rod from a static anchor ball at (10, 12) to a ball at (10, 10).
struct Pendulum {
  std::uint32_t pivot = 0;
  std::uint32_t bob = 0;
  std::uint32_t joint = 0;
};

Pendulum pendulum(Client& client) {
  Pendulum p;
  p.pivot = spawnedBall(client, {10, 12}, true);
  p.bob = spawnedBall(client, {10, 10});
  const auto reply =
      client.request(client::distanceJoint({p.pivot, p.bob, {10, 12}, {10, 10}, false}, {}));
  EXPECT_TRUE(result(reply).ok()) << result(reply).error();
  p.joint = result(reply).joint_id();
  EXPECT_NE(p.joint, 0u);
  return p;
}

// Waits for the snapshots the commands so far caused (a ping's reply
// follows them).
void settle(Client& client) { client.ping(); }

TEST(Joints, CreateQueryAndSnapshotCarryTheJoint) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const Pendulum p = pendulum(client);

  const auto reply = client.request(client::queryJoint(p.joint));
  ASSERT_TRUE(reply.has_joint_info()) << reply.DebugString();
  const auto& info = reply.joint_info();
  EXPECT_EQ(info.descriptor().id(), p.joint);
  EXPECT_EQ(info.descriptor().body_a(), p.pivot);
  EXPECT_EQ(info.descriptor().body_b(), p.bob);
  EXPECT_TRUE(info.descriptor().has_distance());
  EXPECT_NEAR(info.length(), 2.0, 1e-5);

  settle(client);
  const auto& joints = client.mirror().joints();
  ASSERT_EQ(joints.count(p.joint), 1u);
  EXPECT_EQ(joints.at(p.joint).bodyB.value, p.bob);

  // A client joining now gets the joint in its full snapshot.
  Client late(localClient(server.port(), "late"));
  EXPECT_EQ(late.mirror().joints().count(p.joint), 1u);
}

TEST(Joints, EveryKindIsCreatedThroughTheClientLibrary) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const auto a = spawnedBall(client, {6, 8});
  const auto b = spawnedBall(client, {7, 8});
  const client::JointEnds ends{a, b, {6, 8}, {7, 8}, false};
  v1::PrismaticJoint prismatic;
  prismatic.mutable_axis()->set_x(1);
  v1::WheelJoint wheel;
  wheel.mutable_axis()->set_y(1);
  v1::MouseJoint mouse;
  mouse.set_max_force(100);
  mouse.set_stiffness(50);
  const std::vector<v1::ClientMessage> commands = {
      client::distanceJoint(ends, {}), client::ropeJoint(ends, {}),
      client::revoluteJoint(ends, {}), client::prismaticJoint(ends, prismatic),
      client::weldJoint(ends, {}),     client::wheelJoint(ends, wheel),
      client::mouseJoint(a, {6, 8}, mouse)};
  for (const auto& command : commands) {
    const auto reply = client.request(command);
    EXPECT_TRUE(result(reply).ok()) << command.DebugString() << result(reply).error();
  }
  settle(client);
  EXPECT_EQ(client.mirror().joints().size(), commands.size());
}

TEST(Joints, UpdateAndRemoveReachTheSnapshots) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const auto ball = spawnedBall(client, {8, 8});
  v1::MouseJoint mouse;
  mouse.set_max_force(1000);
  mouse.set_stiffness(100);
  const auto created = client.request(client::mouseJoint(ball, {8, 8}, mouse));
  ASSERT_TRUE(result(created).ok()) << result(created).error();
  const auto joint = result(created).joint_id();

  EXPECT_TRUE(result(client.request(client::setJointTarget(joint, {9, 9}))).ok());
  EXPECT_TRUE(result(client.request(client::removeJoint(joint))).ok());
  settle(client);
  EXPECT_EQ(client.mirror().joints().count(joint), 0u);
  const auto again = client.request(client::removeJoint(joint));
  EXPECT_FALSE(result(again).ok());
  EXPECT_EQ(result(again).error(), "remove-joint: unknown joint id " + std::to_string(joint));
}

TEST(Joints, RemovingABodyRemovesItsJointsOnTheWire) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const Pendulum p = pendulum(client);
  settle(client);
  ASSERT_EQ(client.mirror().joints().count(p.joint), 1u);

  ASSERT_TRUE(result(client.request(client::removeBody(p.bob))).ok());
  settle(client);
  EXPECT_EQ(client.mirror().joints().count(p.joint), 0u);
  EXPECT_FALSE(client.request(client::queryJoint(p.joint)).has_joint_info());
}

TEST(Joints, BadJointsAreRefusedWithTheFieldNamedAndChangeNothing) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const auto a = spawnedBall(client, {6, 8});
  const auto b = spawnedBall(client, {7, 8});
  const double nan = std::numeric_limits<double>::quiet_NaN();

  v1::DistanceJoint badSpring;
  badSpring.set_stiffness(nan);
  v1::ClientMessage noKind = client::ropeJoint({a, b, {6, 8}, {7, 8}, false}, {});
  noKind.mutable_create_joint()->clear_kind();
  v1::ClientMessage badAnchor = client::ropeJoint({a, b, {nan, 8}, {7, 8}, false}, {});
  const std::vector<std::pair<v1::ClientMessage, std::string>> refused = {
      {client::distanceJoint({a, b, {6, 8}, {7, 8}, false}, badSpring),
       "distance stiffness is not a finite number"},
      {badAnchor, "rope anchor a x is not a finite number"},
      {noKind, "create_joint kind"},
      {client::distanceJoint({a, 999, {6, 8}, {7, 8}, false}, {}), "distance: "},
      {client::distanceJoint({a, a, {6, 8}, {7, 8}, false}, {}), "distance: "},
      {client::setJointTarget(12345, {1, 1}), "target: "},
      {client::setJointMotor(1, nan), "motor SPEED is not a finite number"},
      {client::removeJoint(12345), "remove-joint: unknown joint id 12345"},
  };
  for (const auto& [command, error] : refused) {
    const auto reply = client.request(command);
    EXPECT_FALSE(result(reply).ok()) << command.DebugString();
    EXPECT_TRUE(mentions(result(reply).error(), error)) << result(reply).error();
  }
  const auto query = client.request(client::queryJoint(12345));
  EXPECT_FALSE(result(query).ok());
  EXPECT_EQ(result(query).error(), "query-joint: unknown joint id 12345");
  settle(client);
  EXPECT_TRUE(client.mirror().joints().empty());
}

TEST(Joints, PlayersJoinTheirOwnBodiesAndChangeTheirOwnJointsOnly) {
  ServerProcess server({"--paused", "--token", "play", "--admin-token", "rule"});
  Client admin(withToken(server.port(), "admin", "rule"));
  Client player(withToken(server.port(), "player", "play"));
  const auto adminBall = spawnedBall(admin, {5, 5});
  const auto own = spawnedBall(player, {8, 5});
  const auto own2 = spawnedBall(player, {9, 5});

  const auto refused =
      player.request(client::distanceJoint({own, adminBall, {8, 5}, {5, 5}, false}, {}));
  EXPECT_TRUE(mentions(result(refused).error(), "refused for the player role"))
      << result(refused).error();
  // Pinned to the world (body 0) or to another own body: allowed.
  const auto pinned = player.request(client::revoluteJoint({own, 0, {8, 6}, {8, 6}, false}, {}));
  EXPECT_TRUE(result(pinned).ok()) << result(pinned).error();
  const auto joined = player.request(client::ropeJoint({own, own2, {8, 5}, {9, 5}, false}, {}));
  ASSERT_TRUE(result(joined).ok()) << result(joined).error();

  const auto adminJoint = result(admin.request(client::weldJoint(
      {adminBall, 0, {5, 5}, {5, 5}, false}, {}))).joint_id();
  EXPECT_FALSE(result(player.request(client::removeJoint(adminJoint))).ok());
  EXPECT_TRUE(result(player.request(client::removeJoint(result(joined).joint_id()))).ok());
  EXPECT_TRUE(result(admin.request(client::removeJoint(adminJoint))).ok());
}

}  // namespace
}  // namespace impulse::net_test
