// Every subscriber receives the same snapshots for the same ticks, at
// snapshot_hz, and a late joiner starts from a full snapshot.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

struct Received {
  std::uint64_t tick;
  bool full;
  int states;
  std::size_t bytes;
  bool operator==(const Received&) const = default;
};

TEST(Subscribers, TwoSubscribersReceiveTheSameTickSequence) {
  ServerProcess server;  // 60 Hz ticks, 30 Hz snapshots
  Client driver(localClient(server.port(), "driver", false));
  std::vector<v1::ClientMessage> rising;
  for (int i = 0; i < 40; ++i) {
    client::SpawnOptions options;
    options.ignoreGravity = true;
    options.velocityY = 0.5;
    rising.push_back(client::spawnCircle({1.0 + 0.5 * i, 3}, 0.2, options));
  }
  requestAll(driver, rising);

  Client a(localClient(server.port(), "a"));
  Client b(localClient(server.port(), "b"));
  std::vector<Received> gotA, gotB;
  a.onSnapshot([&](const v1::Snapshot& s, std::size_t bytes) {
    gotA.push_back({s.tick(), s.full(), s.bodies_size(), bytes});
  });
  b.onSnapshot([&](const v1::Snapshot& s, std::size_t bytes) {
    gotB.push_back({s.tick(), s.full(), s.bodies_size(), bytes});
  });
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < milliseconds(1500)) {
    a.poll(milliseconds(5));
    b.poll(milliseconds(5));
  }
  a.poll(milliseconds(100));
  b.poll(milliseconds(100));

  // The ticks both saw, in the window both were subscribed.
  auto window = [](const std::vector<Received>& got, std::uint64_t from, std::uint64_t to) {
    std::vector<Received> out;
    for (const auto& r : got) {
      if (r.tick > from && r.tick <= to && !r.full) out.push_back(r);
    }
    return out;
  };
  ASSERT_GT(gotA.size(), 10u);
  ASSERT_GT(gotB.size(), 10u);
  const auto from = std::max(gotA.front().tick, gotB.front().tick);
  const auto to = std::min(gotA.back().tick, gotB.back().tick);
  const auto commonA = window(gotA, from, to);
  const auto commonB = window(gotB, from, to);
  EXPECT_EQ(commonA, commonB);
  ASSERT_GT(commonA.size(), 30u);  // about 1.5 s at 30 Hz
  for (std::size_t i = 1; i < commonA.size(); ++i) {
    EXPECT_EQ(commonA[i].tick - commonA[i - 1].tick, 2u) << "60 Hz ticks / 30 Hz snapshots";
    EXPECT_EQ(commonA[i].states, 40) << "the 40 moving bodies, not the sleeping walls";
  }
  EXPECT_EQ(server.stop(), 0);
}

TEST(Subscribers, SnapshotRateFollowsTheFlags) {
  ServerProcess server({"--tick-hz", "100", "--snapshot-hz", "20"});
  Client client(localClient(server.port()));
  std::vector<std::uint64_t> ticks;
  client.onSnapshot([&](const v1::Snapshot& s, std::size_t) { ticks.push_back(s.tick()); });
  client.poll(milliseconds(1000));
  ASSERT_GT(ticks.size(), 10u);
  for (std::size_t i = 1; i < ticks.size(); ++i) EXPECT_EQ(ticks[i] - ticks[i - 1], 5u);
  // 20 per second, allowing for the timing of the window's ends.
  EXPECT_NEAR(double(ticks.size()), 20.0, 3.0);
}

}  // namespace
}  // namespace impulse::net_test
