// Quantized subscribers through the real server: a quantized subscriber's mirror
// stays within a quantum of a plain subscriber's (full precision) at every
// step, a quantized client joining late starts from a key frame and agrees
// too, and an unknown encoding is refused at Hello.
#include <cmath>

#include "impulse/wire/quantized_state.h"
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
namespace q = wire::quantized;

client::ConnectOptions quantizedClient(std::uint16_t port, std::string name) {
  auto options = localClient(port, std::move(name));
  options.snapshotEncoding = v1::SNAPSHOT_ENCODING_QUANTIZED;
  return options;
}

// Snapshots until the mirror shows `tick`.
void catchUp(Client& client, std::uint64_t tick) {
  while (client.mirror().tick() < tick) {
    ASSERT_TRUE(client.awaitSnapshot(milliseconds(5000))) << "no snapshot for tick " << tick;
  }
}

void expectWithinAQuantum(const Client& plain, const Client& quantized) {
  const double position = double(q::kPositionQuantum) * q::kPositionUnit;
  const double velocity = double(q::kVelocityQuantum) * q::kVelocityUnit;
  ASSERT_EQ(plain.mirror().bodies().size(), quantized.mirror().bodies().size());
  for (const auto& [id, body] : plain.mirror().bodies()) {
    const BodyState& truth = body.state;
    const BodyState& seen = quantized.mirror().find(BodyId{id})->state;
    ASSERT_LT((seen.position - truth.position).cwiseAbs().maxCoeff(), position) << "body " << id;
    ASSERT_LT(std::abs(seen.angle - truth.angle), position) << "body " << id;
    ASSERT_LT((seen.linearVelocity - truth.linearVelocity).cwiseAbs().maxCoeff(), velocity)
        << "body " << id;
    ASSERT_LT(std::abs(seen.angularVelocity - truth.angularVelocity), velocity) << "body " << id;
    ASSERT_EQ(seen.awake, truth.awake) << "body " << id;
  }
}

TEST(QuantizedSubscribers, QuantizedMirrorStaysWithinAQuantumOfThePlainOne_LateJoinerToo) {
  ServerProcess server(timedRates());
  Client driver(localClient(server.port(), "driver", false));
  requestAll(driver, {client::setPaused(true)});
  std::vector<v1::ClientMessage> spawns;
  for (int i = 0; i < 60; ++i) {
    spawns.push_back(client::spawnCircle({1.0 + 0.5 * (i % 20), 2.0 + 0.6 * (i / 20)}, 0.2));
  }
  requestAll(driver, spawns);
  Client plain(localClient(server.port(), "plain"));
  Client quantized(quantizedClient(server.port(), "quantized"));
  std::optional<Client> late;

  for (int round = 0; round < 40; ++round) {
    ASSERT_TRUE(result(driver.request(client::step(2))).ok());
    const std::uint64_t tick = driver.ping().server_tick();
    catchUp(plain, tick);
    catchUp(quantized, tick);
    expectWithinAQuantum(plain, quantized);
    if (round == 15) late.emplace(quantizedClient(server.port(), "late"));
    if (late) {
      catchUp(*late, tick);
      expectWithinAQuantum(plain, *late);
    }
  }
  EXPECT_TRUE(quantized.lastSnapshot()->bodies().empty());
  EXPECT_FALSE(quantized.lastSnapshot()->quantized_bodies().empty());
}

TEST(QuantizedSubscribers, UnknownEncoding_IsRefusedAtHello) {
  ServerProcess server;
  auto options = localClient(server.port(), "odd");
  options.snapshotEncoding = v1::SnapshotEncoding(7);
  try {
    Client odd(options);
    FAIL() << "a Hello with snapshot_encoding 7 was accepted";
  } catch (const client::ConnectionError& error) {
    EXPECT_TRUE(mentions(error.what(), "snapshot_encoding 7 is not 0")) << error.what();
  }
}

}  // namespace
}  // namespace impulse::net_test
