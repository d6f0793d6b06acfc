// Per-body properties over the wire (docs/protocol.md, "Per-body properties"):
// spawn options reach the engine, and BodyDescriptor and BodyInfo report the
// values in force; bad numbers are refused naming the field.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

const v1::BodyDescriptor* addedDescriptor(const v1::Snapshot& snapshot, std::uint32_t id) {
  for (const auto& descriptor : snapshot.added()) {
    if (descriptor.id() == id) return &descriptor;
  }
  return nullptr;
}

TEST(BodyPropertiesWire, SpawnOptionsRoundTripInDescriptorAndBodyInfo) {
  ServerProcess server(timedRates());
  Client client(localClient(server.port(), "props"));
  client::SpawnOptions options;
  options.material = Material::Stone;
  options.density = 321.5;
  options.friction = 0.125;
  options.restitution = 0.625;
  options.linearDamping = 0.5;
  options.angularDamping = 0.25;
  options.gravityScale = -0.75;
  const v1::CommandResult spawned =
      result(client.request(client::spawnCircle({5, 5}, 0.5, options)));
  ASSERT_TRUE(spawned.ok()) << spawned.error();

  // Values exact in float, so the engine's float holds them unchanged.
  const v1::BodyDescriptor* descriptor = nullptr;
  for (int i = 0; i < 10 && descriptor == nullptr; ++i) {
    const auto snapshot = client.awaitSnapshot(milliseconds(2000));
    ASSERT_TRUE(snapshot);
    descriptor = addedDescriptor(*client.lastSnapshot(), spawned.body_id());
  }
  ASSERT_NE(descriptor, nullptr);
  EXPECT_EQ(descriptor->material(), v1::STONE);
  EXPECT_EQ(descriptor->density(), 321.5);
  EXPECT_EQ(descriptor->static_friction(), 0.125);
  EXPECT_EQ(descriptor->dynamic_friction(), 0.125);
  EXPECT_EQ(descriptor->restitution(), 0.625);
  EXPECT_EQ(descriptor->linear_damping(), 0.5);
  EXPECT_EQ(descriptor->angular_damping(), 0.25);
  EXPECT_EQ(descriptor->gravity_scale(), -0.75);

  const auto reply = client.request(client::queryBody(spawned.body_id()));
  ASSERT_TRUE(reply.has_body_info());
  const auto& info = reply.body_info();
  EXPECT_EQ(info.density(), 321.5);
  EXPECT_EQ(info.static_friction(), 0.125);
  EXPECT_EQ(info.restitution(), 0.625);
  EXPECT_EQ(info.linear_damping(), 0.5);
  EXPECT_EQ(info.gravity_scale(), -0.75);
  // Mass = density x area, relative 1e-6 (float).
  EXPECT_NEAR(info.mass(), 321.5 * info.area(), 1e-6 * info.mass());
  EXPECT_EQ(info.rolling_resistance(), materialProperties(Material::Stone).rollingResistance);
}

TEST(BodyPropertiesWire, UnsetPropertiesReportTheMaterials) {
  ServerProcess server(timedRates());
  Client client(localClient(server.port(), "plain", false));
  const v1::CommandResult spawned =
      result(client.request(client::spawnCircle({5, 5}, 0.5, {Material::Foam})));
  ASSERT_TRUE(spawned.ok()) << spawned.error();
  const auto info = client.request(client::queryBody(spawned.body_id())).body_info();
  const MaterialProperties& foam = materialProperties(Material::Foam);
  EXPECT_EQ(info.descriptor().material(), v1::FOAM);
  EXPECT_EQ(info.density(), foam.density);
  EXPECT_EQ(info.restitution(), foam.restitution);
  EXPECT_EQ(info.gravity_scale(), 1);
  EXPECT_EQ(info.linear_damping(), 0);
}

TEST(BodyPropertiesWire, BadPropertiesAreRefusedNamingTheField) {
  ServerProcess server(timedRates());
  Client client(localClient(server.port(), "bad", false));
  auto refusal = [&](client::SpawnOptions options) {
    const v1::CommandResult reply =
        result(client.request(client::spawnCircle({5, 5}, 0.5, options)));
    EXPECT_FALSE(reply.ok());
    return reply.error();
  };
  EXPECT_TRUE(mentions(refusal({.gravityScale = 11}), "gravity scale 11 must be in [-10, 10]"));
  EXPECT_TRUE(mentions(refusal({.linearDamping = -1}), "linear damping -1 must be in [0, 1000]"));
  EXPECT_TRUE(mentions(refusal({.friction = std::nan("")}), "circle friction is not a finite"));
  EXPECT_TRUE(mentions(refusal({.restitution = 1.5}), "restitution must be in [0, 1]"));
  EXPECT_TRUE(mentions(refusal({.density = 0}), "density must be in"));
  EXPECT_EQ(client.ping().stats().bodies(), 3u) << "the sandbox's floor and walls only";
}

}  // namespace
}  // namespace impulse::net_test
