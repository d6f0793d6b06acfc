// Soak: for a bounded time (IMPULSE_SOAK_SECONDS, default 20) the server
// carries well-behaved clients pipelining commands, connection churn,
// floods from clients that never read, and a slow snapshot reader at once.
// Checked: the tick rate held, every command of the well-behaved clients was
// answered exactly once, and the server's memory stayed bounded and came
// back down afterwards.
#include <algorithm>
#include <atomic>
#include <deque>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <thread>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
using Clock = std::chrono::steady_clock;

double soakSeconds() {
  const char* text = std::getenv("IMPULSE_SOAK_SECONDS");
  return text != nullptr ? std::max(1.0, std::atof(text)) : 20.0;
}

struct WorkerTally {
  std::uint64_t sent = 0;
  std::uint64_t answered = 0;
  std::uint64_t unanswered = 0;
  std::uint64_t duplicates = 0;
};

// Pipelines rounds of 20 commands (spawn, query, push, ping) and awaits each
// reply by its request id; keeps at most 30 bodies of its own.
WorkerTally runWorker(std::uint16_t port, int index, Clock::time_point end) {
  WorkerTally tally;
  Client client(localClient(port, "worker-" + std::to_string(index), false));
  std::mt19937 random{std::uint32_t(index)};
  std::uniform_real_distribution<double> x(2, 23);
  std::deque<std::uint32_t> bodies;
  while (Clock::now() < end) {
    std::vector<std::uint64_t> ids;
    for (int i = 0; i < 5; ++i) {
      ids.push_back(client.send(client::spawnCircle({x(random), 10}, 0.2)));
      if (!bodies.empty()) {
        ids.push_back(client.send(client::queryBody(bodies.front())));
        ids.push_back(client.send(client::applyImpulse(bodies.back(), {1, 2})));
      }
      ids.push_back(client.send(client::ping(0)));
    }
    while (bodies.size() > 30) {
      ids.push_back(client.send(client::removeBody(bodies.front())));
      bodies.pop_front();
    }
    tally.sent += ids.size();
    for (const auto id : ids) {
      const auto reply = client.awaitReply(id, milliseconds(10000));
      if (!reply) {
        ++tally.unanswered;
        continue;
      }
      ++tally.answered;
      if (reply->has_command_result() && reply->command_result().body_id() != 0 &&
          reply->command_result().ok()) {
        bodies.push_back(reply->command_result().body_id());
      }
    }
  }
  // Anything that arrives now was a second reply to some request.
  tally.duplicates = client.poll(milliseconds(200));
  return tally;
}

// Connects, pings and leaves, over and over; some never say Hello.
std::uint64_t runChurn(std::uint16_t port, Clock::time_point end) {
  std::uint64_t connections = 0;
  while (Clock::now() < end) {
    {
      Client client(localClient(port, "churn", connections % 2 == 0));
      client.ping();
    }
    { RawConnection silent(port); }
    connections += 2;
  }
  return connections;
}

// Hello, then pings as fast as the socket takes them, never reading; the
// server reads them no faster than the rate limit. Reconnects every 2 s.
std::uint64_t runFlood(std::uint16_t port, Clock::time_point end) {
  std::string burst;
  for (int i = 0; i < 1000; ++i) burst += wire::encodeFrame(client::ping(std::uint64_t(i)));
  std::uint64_t floods = 0;
  while (Clock::now() < end) {
    RawConnection flooder(port, 4096);
    flooder.sendHello();
    const auto until = std::min(end, Clock::now() + milliseconds(2000));
    // send() gives up quietly once the server has dropped the connection;
    // the pause keeps a dropped flooder from spinning on the shared cores.
    while (Clock::now() < until) {
      flooder.send(burst);
      std::this_thread::sleep_for(milliseconds(5));
    }
    ++floods;
  }
  return floods;
}

// A subscriber with a tiny receive buffer that reads for 50 ms every 500 ms.
std::uint64_t runSlowReader(std::uint16_t port, Clock::time_point end) {
  auto options = localClient(port, "slow-reader", true);
  options.receiveBufferBytes = 4096;
  Client reader(options);
  std::uint64_t snapshots = 0;
  reader.onSnapshot([&](const v1::Snapshot&, std::size_t) { ++snapshots; });
  while (Clock::now() < end) {
    reader.poll(milliseconds(50));
    std::this_thread::sleep_for(milliseconds(450));
  }
  return snapshots;
}

TEST(Soak, ManyClientsChurnFloodsAndASlowReader_TickRateHeldEveryCommandAnsweredOnce) {
  const double seconds = soakSeconds();
  auto args = timedRates();
  args.insert(args.end(), {"--preset", "8"});
  ServerProcess server(args);
  Client observer(localClient(server.port(), "observer", false));
  const long rssStart = server.residentKb();
  const auto first = observer.ping();
  const auto start = Clock::now();
  const auto end = start + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(seconds));

  constexpr int kWorkers = 6;
  std::vector<WorkerTally> tallies(kWorkers);
  std::atomic<std::uint64_t> churned{0}, floods{0}, slowSnapshots{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < kWorkers; ++i) {
    threads.emplace_back([&, i] { tallies[std::size_t(i)] = runWorker(server.port(), i, end); });
  }
  threads.emplace_back([&] { churned = runChurn(server.port(), end); });
  threads.emplace_back([&] { floods = runFlood(server.port(), end); });
  threads.emplace_back([&] { slowSnapshots = runSlowReader(server.port(), end); });

  long rssPeak = rssStart;
  double worstMeanTick = 0;
  while (Clock::now() < end) {
    std::this_thread::sleep_for(milliseconds(500));
    rssPeak = std::max(rssPeak, server.residentKb());
    worstMeanTick = std::max(worstMeanTick, observer.ping().stats().mean_tick_ms());
  }
  for (auto& thread : threads) thread.join();
  const auto last = observer.ping();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  std::this_thread::sleep_for(milliseconds(3000));  // closes linger, memory is trimmed
  const long rssAfter = server.residentKb();

  WorkerTally total;
  for (const auto& t : tallies) {
    total.sent += t.sent;
    total.answered += t.answered;
    total.unanswered += t.unanswered;
    total.duplicates += t.duplicates;
  }
  const double tickRate = double(last.server_tick() - first.server_tick()) / elapsed;
  std::printf(
      "[ measure ] soak %.0f s: %.1f ticks/s (target %.0f), %llu ticks skipped, worst mean tick "
      "%.2f ms; %llu commands sent by %d workers, %llu answered, %llu unanswered, %llu "
      "duplicates; %llu churn connections, %llu floods (%llu commands rate-limited), slow reader "
      "got %llu snapshots; server RSS %ld KiB at start, %ld peak, %ld after\n",
      elapsed, tickRate, kTestTickHz, (unsigned long long)last.stats().ticks_skipped(),
      worstMeanTick, (unsigned long long)total.sent, kWorkers,
      (unsigned long long)total.answered, (unsigned long long)total.unanswered,
      (unsigned long long)total.duplicates, (unsigned long long)churned.load(),
      (unsigned long long)floods.load(), (unsigned long long)last.stats().commands_rate_limited(),
      (unsigned long long)slowSnapshots.load(), rssStart, rssPeak, rssAfter);

  EXPECT_GT(tickRate, 0.95 * kTestTickHz);
  EXPECT_GT(total.sent, 1000u);
  EXPECT_EQ(total.answered, total.sent);
  EXPECT_EQ(total.unanswered, 0u);
  EXPECT_EQ(total.duplicates, 0u);
  EXPECT_GT(churned.load(), 10u);
  EXPECT_GT(floods.load(), 0u);
  EXPECT_GT(slowSnapshots.load(), 0u);
  // AddressSanitizer keeps freed memory in quarantine: looser there.
  EXPECT_LT(rssPeak - rssStart, (kSanitized ? 128 : 32) * 1024);
  EXPECT_LT(rssAfter - rssStart, (kSanitized ? 64 : 8) * 1024);
  EXPECT_EQ(clientsOnceSettled(observer, 1), 1u);
}

}  // namespace
}  // namespace impulse::net_test
