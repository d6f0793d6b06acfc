// Paused stepping is exact: two servers given the same script end in
// bit-identical states, through the client library and through impulse-cli.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

struct RunResult {
  std::vector<std::uint64_t> stepHashes;
  std::map<std::uint32_t, client::MirrorBody> bodies;
  std::uint64_t tick = 0;
};

RunResult runScript(std::uint16_t port) {
  Client client(localClient(port, "determinism"));
  RunResult run;
  auto step = [&](std::uint32_t ticks) {
    const auto reply = client.request(client::step(ticks));
    EXPECT_TRUE(result(reply).ok()) << result(reply).error();
    run.stepHashes.push_back(result(reply).state_hash());
  };
  EXPECT_TRUE(result(client.request(client::loadPreset(8))).ok());
  step(45);
  const auto ball = client.request(client::spawnCircle({6, 12}, 0.6, {Material::Rubber}));
  const std::vector<client::Point> triangle = {{12, 9}, {14, 9}, {13, 11}};
  const auto wedge = client.request(client::spawnPolygon(triangle, {Material::Wood}));
  EXPECT_TRUE(result(ball).ok() && result(wedge).ok());
  step(30);
  EXPECT_TRUE(result(client.request(client::applyImpulse(result(ball).body_id(), {400, 250},
                                                         client::Point{6.1, 12})))
                  .ok());
  EXPECT_TRUE(result(client.request(client::nudgeGravity({1.5, 0}))).ok());
  step(120);
  EXPECT_TRUE(result(client.request(client::removeBody(result(wedge).body_id()))).ok());
  step(60);
  client.ping();
  run.bodies = client.mirror().bodies();
  run.tick = client.mirror().tick();
  return run;
}

TEST(Determinism, TwoServersGivenTheSameScriptEndBitIdentical) {
  ServerProcess first({"--paused"});
  ServerProcess second({"--paused"});
  const RunResult a = runScript(first.port());
  const RunResult b = runScript(second.port());
  EXPECT_EQ(a.tick, 255u);
  EXPECT_EQ(a.stepHashes, b.stepHashes);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  ASSERT_GT(a.bodies.size(), 10u);
  for (const auto& [id, body] : a.bodies) {
    const auto it = b.bodies.find(id);
    ASSERT_NE(it, b.bodies.end()) << id;
    const auto& other = it->second.state;
    // Exact float equality: bit-identical states.
    EXPECT_EQ(body.state.position, other.position) << id;
    EXPECT_EQ(body.state.angle, other.angle) << id;
    EXPECT_EQ(body.state.linearVelocity, other.linearVelocity) << id;
    EXPECT_EQ(body.state.angularVelocity, other.angularVelocity) << id;
    EXPECT_EQ(body.state.awake, other.awake) << id;
  }
  // The world did move: the script is not trivially deterministic.
  EXPECT_NE(a.stepHashes.front(), a.stepHashes.back());
}

TEST(Determinism, SameCliScriptGivesIdenticalOutputOnTwoServers) {
  ServerProcess first({"--paused"});
  ServerProcess second({"--paused"});
  const std::string script =
      "preset 10\n"
      "step 40\n"
      "circle 12 14 0.4 rubber\n"
      "polygon 3 12 4 12 4 13 ice\n"
      "gravity 2 -9.81\n"
      "step 90\n"
      "bodies\n";
  const auto a = runCli(first.port(), script);
  const auto b = runCli(second.port(), script);
  EXPECT_EQ(a.exitCode, 0);
  ASSERT_EQ(a.lines.size(), 8u);  // the connect line and one per command
  EXPECT_EQ(a.lines, b.lines);
}

}  // namespace
}  // namespace impulse::net_test
