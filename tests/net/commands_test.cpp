// The real server driven through the client library: handshake, every
// command, and every refusal with its message.
#include <cmath>
#include <limits>
#include <numbers>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ServerSession, FirstLineAndWelcomeDescribeTheServer) {
  ServerProcess server({"--paused", "--tick-hz", "50", "--snapshot-hz", "25"});
  EXPECT_EQ(server.firstLine(), "listening on 127.0.0.1:" + std::to_string(server.port()));
  Client client(localClient(server.port()));
  const auto& welcome = client.welcome();
  EXPECT_EQ(welcome.protocol_version(), 1u);
  EXPECT_GT(welcome.client_id(), 0u);
  EXPECT_EQ(welcome.tick_hz(), 50);
  EXPECT_EQ(welcome.snapshot_hz(), 25);
  EXPECT_TRUE(welcome.paused());
  EXPECT_EQ(welcome.tick(), 0u);
  EXPECT_LT(welcome.world_min().x(), 0);
  EXPECT_GT(welcome.world_max().x(), 25);
  // The first snapshot is full and carries the sandbox preset.
  EXPECT_EQ(client.mirror().snapshotsApplied(), 1u);
  ASSERT_TRUE(client.mirror().preset().has_value());
  EXPECT_EQ(client.mirror().preset()->id, 0);
  EXPECT_EQ(client.mirror().bodies().size(), 3u);  // floor and two walls
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServerSession, SpawnThenQueryReturnsTheBody) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  const auto spawned = client.request(client::spawnCircle({5, 6}, 0.5, {Material::Metal}));
  ASSERT_TRUE(result(spawned).ok()) << result(spawned).error();
  const std::uint32_t id = result(spawned).body_id();
  EXPECT_NE(id, 0u);

  const auto reply = client.request(client::queryBody(id));
  ASSERT_TRUE(reply.has_body_info());
  const auto& info = reply.body_info();
  EXPECT_EQ(info.descriptor().id(), id);
  EXPECT_EQ(info.descriptor().material(), v1::METAL);
  EXPECT_EQ(info.descriptor().shape().circle().radius(), 0.5);
  EXPECT_EQ(info.state().position().x(), 5);
  EXPECT_EQ(info.state().position().y(), 6);
  // METAL: 2000 kg/m^2; restitution 0.1.
  EXPECT_NEAR(info.area(), std::numbers::pi * 0.25, 1e-6);
  EXPECT_NEAR(info.mass(), 2000 * std::numbers::pi * 0.25, 1e-2);
  EXPECT_NEAR(info.restitution(), 0.1, 1e-6);

  // The snapshot that followed the spawn put it in the mirror.
  client.ping();
  const auto* mirrored = client.mirror().find(BodyId{id});
  ASSERT_NE(mirrored, nullptr);
  EXPECT_EQ(mirrored->material, Material::Metal);
}

TEST(ServerSession, EveryCommandTakesEffect) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));

  // SpawnPolygon, clockwise input.
  const std::vector<client::Point> square = {{10, 6}, {10, 7}, {11, 7}, {11, 6}};
  const auto polygon = client.request(client::spawnPolygon(square, {Material::Wood}));
  ASSERT_TRUE(result(polygon).ok()) << result(polygon).error();
  const std::uint32_t box = result(polygon).body_id();
  const auto boxInfo = client.request(client::queryBody(box)).body_info();
  EXPECT_EQ(boxInfo.descriptor().shape().polygon().vertices_size(), 4);
  EXPECT_NEAR(boxInfo.state().position().x(), 10.5, 1e-6);
  EXPECT_NEAR(boxInfo.area(), 1.0, 1e-6);

  // Gravity: set, nudge, reset; snapshots carry it.
  ASSERT_TRUE(result(client.request(client::setGravity({1, -2}))).ok());
  ASSERT_TRUE(result(client.request(client::nudgeGravity({0.5, -1}))).ok());
  client.ping();
  EXPECT_EQ(client.mirror().gravity(), Vec2(1.5f, -3.0f));
  ASSERT_TRUE(result(client.request(client::resetGravity())).ok());
  client.ping();
  EXPECT_EQ(client.mirror().gravity(), Vec2(0, -9.81f));

  // ApplyImpulse changes the velocity: 10 N*s on 700 kg of wood.
  ASSERT_TRUE(result(client.request(client::applyImpulse(box, {700, 0}))).ok());
  const auto pushed = client.request(client::queryBody(box)).body_info();
  EXPECT_NEAR(pushed.state().velocity().x(), 1.0, 1e-5);

  // Step advances exactly; the snapshot after it has that tick.
  const auto stepped = client.request(client::step(30));
  ASSERT_TRUE(result(stepped).ok()) << result(stepped).error();
  EXPECT_EQ(result(stepped).tick(), 30u);
  EXPECT_NE(result(stepped).state_hash(), 0u);
  client.ping();
  EXPECT_EQ(client.mirror().tick(), 30u);
  EXPECT_GT(client.mirror().find(BodyId{box})->state.position.x(), 10.5f);

  // Ping reports the tick.
  EXPECT_EQ(client.ping().server_tick(), 30u);

  // RemoveBody.
  ASSERT_TRUE(result(client.request(client::removeBody(box))).ok());
  EXPECT_FALSE(result(client.request(client::queryBody(box))).ok());
  client.ping();
  EXPECT_EQ(client.mirror().find(BodyId{box}), nullptr);

  // Clear.
  ASSERT_TRUE(result(client.request(client::spawnCircle({3, 3}, 0.3))).ok());
  ASSERT_TRUE(result(client.request(client::clearWorld())).ok());
  client.ping();
  EXPECT_TRUE(client.mirror().bodies().empty());
  EXPECT_EQ(client.ping().stats().bodies(), 0u);

  // SetPaused: running, the tick advances on its own; paused, it stops.
  ASSERT_TRUE(result(client.request(client::setPaused(false))).ok());
  const auto before = client.ping().server_tick();
  ASSERT_TRUE(client.awaitSnapshot(milliseconds(2000)));
  ASSERT_TRUE(client.awaitSnapshot(milliseconds(2000)));
  EXPECT_GT(client.ping().server_tick(), before);
  ASSERT_TRUE(result(client.request(client::setPaused(true))).ok());
  const auto frozen = client.ping().server_tick();
  ASSERT_FALSE(client.awaitSnapshot(milliseconds(200)));
  EXPECT_EQ(client.ping().server_tick(), frozen);
  EXPECT_TRUE(client.mirror().paused());
}

TEST(ServerSession, PresetLoadSendsAFullSnapshotWithItsPresetInfo) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port()));
  std::vector<v1::Snapshot> snapshots;
  client.onSnapshot([&](const v1::Snapshot& s, std::size_t) { snapshots.push_back(s); });
  ASSERT_TRUE(result(client.request(client::loadPreset(4))).ok());
  client.ping();
  ASSERT_FALSE(snapshots.empty());
  const auto& snapshot = snapshots.back();
  EXPECT_TRUE(snapshot.full());
  EXPECT_EQ(snapshot.preset().id(), 4);
  EXPECT_FALSE(snapshot.preset().title().empty());
  EXPECT_FALSE(snapshot.preset().explanation().empty());
  EXPECT_EQ(snapshot.preset().markers_size(), 2);  // centre and radius markers
  EXPECT_EQ(snapshot.added_size(), snapshot.bodies_size());
  EXPECT_EQ(client.mirror().preset()->id, 4);

  // Running, too: the next snapshot after the load is full.
  ASSERT_TRUE(result(client.request(client::setPaused(false))).ok());
  snapshots.clear();
  ASSERT_TRUE(result(client.request(client::loadPreset(9, Material::Ice))).ok());
  while (snapshots.empty() || snapshots.back().preset().id() != 9) {
    ASSERT_TRUE(client.awaitSnapshot(milliseconds(2000)));
  }
  EXPECT_TRUE(snapshots.back().full());
  EXPECT_EQ(client.mirror().preset()->id, 9);
}

struct Refusal {
  const char* what;
  v1::ClientMessage command;
  const char* expected;  // part of the error message
};

TEST(ServerSession, InvalidCommandsAreRefusedWithAReasonAndChangeNothing) {
  ServerProcess server({"--paused", "--max-bodies", "5"});
  Client client(localClient(server.port()));
  const auto spawned = client.request(client::spawnCircle({5, 5}, 0.5));
  ASSERT_TRUE(result(spawned).ok());
  const auto ball = result(spawned).body_id();
  const std::uint32_t wall = client.mirror().bodies().begin()->first;  // static

  auto polygon = [](std::vector<client::Point> points) { return client::spawnPolygon(points); };
  auto withMaterial = [](int material) {
    auto command = client::spawnCircle({5, 8}, 0.5);
    command.mutable_spawn_circle()->mutable_options()->set_material(
        static_cast<v1::Material>(material));
    return command;
  };
  v1::ClientMessage noCenter;
  noCenter.mutable_spawn_circle()->set_radius(1);
  v1::ClientMessage empty;
  v1::ClientMessage hello;
  hello.mutable_hello()->set_protocol_version(1);
  std::vector<client::Point> seventeen;
  for (int i = 0; i < 17; ++i) {
    seventeen.push_back({10 + std::cos(i * 0.37), 10 + std::sin(i * 0.37)});
  }
  auto nanVelocity = client::spawnCircle({5, 8}, 0.5);
  nanVelocity.mutable_spawn_circle()->mutable_options()->mutable_velocity()->set_x(kNaN);

  const std::vector<Refusal> refusals = {
      {"NaN centre", client::spawnCircle({kNaN, 1}, 0.5), "circle X is not a finite number"},
      {"infinite radius", client::spawnCircle({5, 5}, kInf), "circle R is not a finite number"},
      {"float overflow", client::spawnCircle({1e300, 5}, 0.5), "too large"},
      {"NaN velocity", nanVelocity, "circle velocity x is not a finite number"},
      {"NaN gravity", client::setGravity({0, kNaN}), "gravity GY is not a finite number"},
      {"huge gravity", client::setGravity({0, -5000}), "within +-1000"},
      {"infinite nudge", client::nudgeGravity({kInf, 0}), "not a finite number"},
      {"NaN impulse", client::applyImpulse(ball, {kNaN, 0}), "not a finite number"},
      {"NaN impulse point", client::applyImpulse(ball, {1, 0}, client::Point{kNaN, 0}),
       "impulse PX is not a finite number"},
      {"polygon NaN vertex", polygon({{1, 1}, {2, kNaN}, {1, 2}}), "is not a finite number"},
      {"radius too small", client::spawnCircle({5, 5}, 0.001), ""},
      {"radius too large", client::spawnCircle({5, 5}, 500), ""},
      {"outside the world", client::spawnCircle({500, 5}, 0.5), ""},
      {"two vertices", polygon({{1, 1}, {2, 2}}), "at least 3"},
      {"seventeen vertices", polygon(seventeen), "17 vertices"},
      {"duplicate points", polygon({{1, 1}, {2, 1}, {2, 1}, {1, 2}}), ""},
      {"collinear points", polygon({{1, 1}, {2, 1}, {3, 1}}), ""},
      {"self-intersecting", polygon({{0, 0}, {4, 4}, {4, 0}, {0, 4}}), ""},
      {"area too small", polygon({{1, 1}, {1.01, 1}, {1, 1.01}}), ""},
      {"unknown material", withMaterial(9), "MATERIAL 9 is not a material"},
      {"missing centre", noCenter, "center is missing"},
      {"remove unknown id", client::removeBody(987654), "unknown body id 987654"},
      {"query unknown id", client::queryBody(987654), "unknown body id 987654"},
      {"query null id", client::queryBody(0), "unknown body id 0"},
      {"impulse unknown id", client::applyImpulse(987654, {1, 0}), "unknown body id 987654"},
      {"impulse on static", client::applyImpulse(wall, {1, 0}), "is static"},
      {"preset too high", client::loadPreset(22), "preset 22 does not exist"},
      {"preset negative", client::loadPreset(-1), "preset -1 does not exist"},
      {"step zero", client::step(0), "ticks must be 1..600"},
      {"step too long", client::step(100000), "ticks must be 1..600"},
      {"second hello", hello, "hello was already received"},
      {"no command", empty, "carries no command"},
  };
  const auto statsBefore = client.ping(milliseconds(10000), true).stats();
  for (const auto& refusal : refusals) {
    const auto reply = client.request(refusal.command);
    ASSERT_TRUE(reply.has_command_result()) << refusal.what;
    EXPECT_FALSE(reply.command_result().ok()) << refusal.what;
    EXPECT_FALSE(reply.command_result().error().empty()) << refusal.what;
    EXPECT_NE(reply.command_result().error().find(refusal.expected), std::string::npos)
        << refusal.what << ": " << reply.command_result().error();
  }
  // Nothing changed: the same bodies in bit-identical states, same gravity.
  const auto statsAfter = client.ping(milliseconds(10000), true).stats();
  ASSERT_NE(statsBefore.state_hash(), 0u);
  EXPECT_EQ(statsAfter.bodies(), statsBefore.bodies());
  EXPECT_EQ(statsAfter.state_hash(), statsBefore.state_hash());
  EXPECT_EQ(client.mirror().gravity(), Vec2(0, -9.81f));

  // The body limit: 5 bodies allowed, 4 exist (3 walls and the ball).
  ASSERT_TRUE(result(client.request(client::spawnCircle({8, 8}, 0.5))).ok());
  const auto full = client.request(client::spawnCircle({10, 8}, 0.5));
  EXPECT_FALSE(result(full).ok());
  EXPECT_FALSE(result(full).error().empty());

  // Step is refused while running.
  ASSERT_TRUE(result(client.request(client::setPaused(false))).ok());
  const auto running = client.request(client::step(1));
  EXPECT_FALSE(result(running).ok());
  EXPECT_NE(result(running).error().find("running"), std::string::npos);
}

TEST(ServerSession, PipelinedCommandsAreAnsweredOnceEachInArrivalOrder) {
  ServerProcess server({"--paused"});
  Client client(localClient(server.port(), "pipeline", false));
  std::vector<v1::ClientMessage> commands;
  for (int i = 0; i < 300; ++i) commands.push_back(client::spawnCircle({1.0 + i * 0.07, 5}, 0.03));
  const auto replies = requestAll(client, commands);
  std::uint32_t previous = 0;
  for (const auto& reply : replies) {
    ASSERT_TRUE(result(reply).ok()) << result(reply).error();
    // Ids are given in arrival order.
    EXPECT_GT(result(reply).body_id() & BodyId::kIndexMask, previous & BodyId::kIndexMask);
    previous = result(reply).body_id();
  }
  EXPECT_EQ(client.ping().stats().bodies(), 303u);
  // Nothing is left over: no second reply to any request.
  EXPECT_EQ(client.poll(milliseconds(100)), 0u);
}

TEST(ServerSession, SigtermShutsDownCleanly) {
  ServerProcess server;
  Client client(localClient(server.port()));
  client.ping();
  EXPECT_EQ(server.stop(milliseconds(3000)), 0);
  EXPECT_NE(server.log().find("shutting down"), std::string::npos);
  EXPECT_THROW(
      {
        for (int i = 0; i < 100; ++i) client.poll(milliseconds(20));
      },
      client::ConnectionError);
}

}  // namespace
}  // namespace impulse::net_test
