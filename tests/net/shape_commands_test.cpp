// The shape commands over the wire: capsules, segments, chains, compound and
// kinematic bodies and target transforms, what a subscriber's mirror sees of
// them, and every refusal with its message.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

TEST(ShapeCommands, CapsuleSegmentAndChainArriveWithTheirShapes) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const auto capsule = client.request(client::spawnCapsule({5, 6}, {7, 6}, 0.4, {Material::Rubber}));
  ASSERT_TRUE(result(capsule).ok()) << errorOf(capsule);
  const auto capsuleInfo = client.request(client::queryBody(result(capsule).body_id())).body_info();
  ASSERT_TRUE(capsuleInfo.descriptor().shape().has_capsule());
  EXPECT_NEAR(capsuleInfo.state().position().x(), 6, 1e-6) << "centred between the two centres";
  // A 2 x 0.8 rectangle and a disc of radius 0.4.
  EXPECT_NEAR(capsuleInfo.area(), 2 * 0.8 + std::numbers::pi * 0.16, 1e-4);

  const auto wall = client.request(client::spawnSegment({2, 3}, {2, 9}));
  ASSERT_TRUE(result(wall).ok()) << errorOf(wall);
  EXPECT_TRUE(client.request(client::queryBody(result(wall).body_id())).body_info().descriptor().is_static())
      << "a segment has no area, so it is static unless kinematic";

  const std::vector<client::Point> hills = {{20, 2}, {16, 3}, {12, 2}, {8, 3}, {4, 2}};
  const auto chain = client.request(client::spawnChain(hills, false));
  ASSERT_TRUE(result(chain).ok()) << errorOf(chain);
  const auto chainInfo = client.request(client::queryBody(result(chain).body_id())).body_info();
  EXPECT_TRUE(chainInfo.descriptor().shape().has_chain_segment());
  EXPECT_EQ(chainInfo.descriptor().extra_shapes_size(), 1) << "5 points, open: 2 segments";

  client.ping();
  const auto* mirrored = client.mirror().find(BodyId{result(chain).body_id()});
  ASSERT_NE(mirrored, nullptr);
  EXPECT_EQ(mirrored->extraShapes.size(), 1u);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ShapeCommands, ACompoundBodyHasTheUnionsMass) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  using Part = client::BodyPart;
  const std::vector<Part> parts = {{Part::Kind::Box, {-1, 0}, {0.5, 0.5}, 0, Material::Wood},
                                   {Part::Kind::Box, {1, 0}, {0.5, 0.5}, 0, Material::Wood},
                                   {Part::Kind::Circle, {0, 1}, {}, 0.5, Material::Metal}};
  const auto body = client.request(client::spawnBody({10, 8}, 0, parts));
  ASSERT_TRUE(result(body).ok()) << errorOf(body);
  const auto info = client.request(client::queryBody(result(body).body_id())).body_info();
  EXPECT_EQ(info.descriptor().extra_shapes_size(), 2);
  const double wood = materialProperties(Material::Wood).density;
  const double metal = materialProperties(Material::Metal).density;
  EXPECT_NEAR(info.mass(), 2 * wood + metal * std::numbers::pi * 0.25, 0.05);
  // The centre of mass lies above the boxes, towards the heavy circle.
  const double circleMass = metal * std::numbers::pi * 0.25;
  EXPECT_NEAR(info.state().position().y(), 8 + circleMass / (2 * wood + circleMass), 1e-4);
}

TEST(ShapeCommands, AKinematicBodyFollowsItsTargetAndRefusesPushes) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  client::SpawnOptions kinematic;
  kinematic.isKinematic = true;
  const auto platform = client.request(client::spawnCapsule({10, 5}, {14, 5}, 0.25, kinematic));
  ASSERT_TRUE(result(platform).ok()) << errorOf(platform);
  const std::uint32_t id = result(platform).body_id();
  EXPECT_TRUE(client.request(client::queryBody(id)).body_info().descriptor().is_kinematic());

  ASSERT_TRUE(result(client.request(client::setTargetTransform(id, {12, 7}, 0))).ok());
  ASSERT_TRUE(result(client.request(client::step(1))).ok());
  const auto moved = client.request(client::queryBody(id)).body_info();
  EXPECT_NEAR(moved.state().position().y(), 7, 1e-4) << "there in one tick";

  const auto pushed = client.request(client::applyImpulse(id, {10, 0}));
  EXPECT_FALSE(result(pushed).ok());
  EXPECT_NE(errorOf(pushed).find("kinematic"), std::string::npos) << errorOf(pushed);
}

TEST(ShapeCommands, BadShapesAreRefusedByNameAndChangeNothing) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const int before = int(client.request(client::ping(0)).pong().stats().bodies());
  auto expectRefused = [&](const v1::ClientMessage& command, const std::string& words) {
    const auto reply = client.request(command);
    EXPECT_FALSE(result(reply).ok());
    EXPECT_NE(errorOf(reply).find(words), std::string::npos) << errorOf(reply);
  };
  expectRefused(client::spawnSegment({3, 3}, {3, 3.001}), "segment is shorter than 5 mm");
  expectRefused(client::spawnCapsule({3, 3}, {3, 3}, 0.5), "5 mm");
  expectRefused(client::spawnChain(std::vector<client::Point>{{1, 1}, {2, 1}, {3, 1}}, false), "4");
  const std::vector<client::Point> crossing = {{0, 0}, {4, 4}, {4, 0}, {0, 4}, {2, 6}};
  expectRefused(client::spawnChain(crossing, false), "cross");
  using Part = client::BodyPart;
  const std::vector<Part> farApart = {{Part::Kind::Circle, {0, 0}, {}, 0.5, Material::Solid},
                                      {Part::Kind::Circle, {120, 0}, {}, 0.5, Material::Solid}};
  expectRefused(client::spawnBody({5, 5}, 0, farApart), "50 m");
  expectRefused(client::spawnBody({5, 5}, 0, std::vector<Part>{}), "1 to");
  client::SpawnOptions both;
  both.isStatic = true;
  both.isKinematic = true;
  expectRefused(client::spawnCapsule({3, 3}, {5, 3}, 0.5, both), "static or kinematic, not both");
  EXPECT_EQ(int(client.request(client::ping(0)).pong().stats().bodies()), before);
}

}  // namespace
}  // namespace impulse::net_test
