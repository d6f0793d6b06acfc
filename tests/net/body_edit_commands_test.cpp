// The commands that edit a live body over the wire (SetTransform,
// SetMaterial, SetBodyType, BodyOptions.is_awake): what the body does and
// what a subscriber's mirror sees afterwards, and every refusal with its
// message.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

v1::BodyInfo infoOf(Client& client, std::uint32_t id) { return client.request(client::queryBody(id)).body_info(); }

TEST(BodyEditCommands, TeleportMaterialAndTypeReachTheBodyAndTheMirror) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const auto ball = client.request(client::spawnCircle({10, 10}, 0.5));
  ASSERT_TRUE(result(ball).ok()) << errorOf(ball);
  const std::uint32_t id = result(ball).body_id();

  ASSERT_TRUE(result(client.request(client::setTransform(id, {12, 5}, 0.5))).ok());
  v1::BodyInfo info = infoOf(client, id);
  EXPECT_NEAR(info.state().position().x(), 12, 1e-6);
  EXPECT_NEAR(info.state().position().y(), 5, 1e-6);
  EXPECT_NEAR(info.state().angle(), 0.5, 1e-6);

  ASSERT_TRUE(result(client.request(client::setMaterial(id, Material::Metal))).ok());
  info = infoOf(client, id);
  EXPECT_EQ(info.descriptor().material(), v1::METAL);
  EXPECT_NEAR(info.mass(), materialProperties(Material::Metal).density * std::numbers::pi * 0.25, 0.05);

  ASSERT_TRUE(result(client.request(client::setBodyType(id, BodyType::Static))).ok());
  EXPECT_TRUE(infoOf(client, id).descriptor().is_static());
  client.ping();
  const auto* mirrored = client.mirror().find(BodyId{id});
  ASSERT_NE(mirrored, nullptr);
  EXPECT_TRUE(mirrored->isStatic) << "the new descriptor replaced the old one";
  EXPECT_EQ(mirrored->material, Material::Metal);

  ASSERT_TRUE(result(client.request(client::setBodyType(id, BodyType::Dynamic))).ok());
  ASSERT_TRUE(result(client.request(client::step(30))).ok());
  EXPECT_LT(infoOf(client, id).state().position().y(), 4.5) << "dynamic again, it falls";
  EXPECT_EQ(server.stop(), 0);
}

TEST(BodyEditCommands, ABodyCreatedAsleepWaitsUntilPushed) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  client::SpawnOptions asleep;
  asleep.isAwake = false;
  const auto box = client.request(client::spawnCircle({5, 8}, 0.5, asleep));
  ASSERT_TRUE(result(box).ok()) << errorOf(box);
  const std::uint32_t id = result(box).body_id();
  ASSERT_TRUE(result(client.request(client::step(30))).ok());
  v1::BodyInfo info = infoOf(client, id);
  EXPECT_FALSE(info.state().awake());
  EXPECT_EQ(info.state().position().y(), 8) << "asleep in mid-air, it keeps still";

  ASSERT_TRUE(result(client.request(client::applyImpulse(id, {0, 1}))).ok());
  ASSERT_TRUE(result(client.request(client::step(30))).ok());
  EXPECT_LT(infoOf(client, id).state().position().y(), 8) << "woken, it falls";
}

TEST(BodyEditCommands, RefusalsNameTheFieldInTheUsersWordsAndChangeNothing) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const auto ball = client.request(client::spawnCircle({10, 10}, 0.5));
  const std::uint32_t id = result(ball).body_id();
  const auto wall = client.request(client::spawnSegment({2, 3}, {2, 9}));
  ASSERT_TRUE(result(wall).ok()) << errorOf(wall);
  auto expectRefused = [&](const v1::ClientMessage& command, const std::string& words) {
    const auto reply = client.request(command);
    EXPECT_FALSE(result(reply).ok()) << words;
    EXPECT_NE(errorOf(reply).find(words), std::string::npos) << errorOf(reply);
  };
  v1::ClientMessage noPosition;
  noPosition.mutable_set_transform()->set_body_id(id);
  expectRefused(noPosition, "teleport position is missing");
  expectRefused(client::setTransform(id, {1e6, 0}), "outside the world bounds");
  expectRefused(client::setTransform(id, {std::nan(""), 0}), "teleport X is not a finite number");
  expectRefused(client::setTransform(4242, {1, 1}), "unknown body id 4242");

  v1::ClientMessage badMaterial;
  badMaterial.mutable_set_material()->set_body_id(id);
  badMaterial.mutable_set_material()->set_material(static_cast<v1::Material>(99));
  expectRefused(badMaterial, "material MATERIAL 99 is not a material");

  v1::ClientMessage noType;
  noType.mutable_set_body_type()->set_body_id(id);
  expectRefused(noType, "body-type TYPE 0 is not a body type");
  expectRefused(client::setBodyType(result(wall).body_id(), BodyType::Dynamic), "area");

  const v1::BodyInfo info = infoOf(client, id);
  EXPECT_EQ(info.state().position().x(), 10);
  EXPECT_EQ(info.descriptor().material(), v1::SOLID);
  EXPECT_FALSE(info.descriptor().is_static());
  EXPECT_TRUE(infoOf(client, result(wall).body_id()).descriptor().is_static());
}

}  // namespace
}  // namespace impulse::net_test
