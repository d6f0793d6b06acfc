// Connection churn: clients coming and going leave nothing behind, and the
// client limit is enforced with an Error.
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
using Clock = std::chrono::steady_clock;

// What a hundred clients may leave behind in the server's resident size:
// allocator slack, not per-client state. Under AddressSanitizer freed memory
// waits in its quarantine instead of being reused, so the resident size
// grows with churn by design; there LeakSanitizer, which fails the server's
// exit (stop() below), is what finds anything left behind.
#if defined(__SANITIZE_ADDRESS__)
constexpr long kLeftBehindKb = 64 * 1024;
#else
constexpr long kLeftBehindKb = 8 * 1024;
#endif

TEST(Churn, HundredClientsConnectAndDisconnectInALoop) {
  ServerProcess server({"--preset", "8"});
  Client observer(localClient(server.port(), "observer", false));
  const long before = server.residentKb();
  int welcomed = 0;
  // Ten rounds of ten clients connected at once, each subscribed, pinging
  // and then leaving (some abruptly, mid-stream).
  for (int round = 0; round < 10; ++round) {
    std::vector<std::unique_ptr<Client>> clients;
    for (int i = 0; i < 10; ++i) {
      clients.push_back(std::make_unique<Client>(
          localClient(server.port(), "churn-" + std::to_string(round * 10 + i), i % 2 == 0)));
      welcomed += clients.back()->welcome().client_id() != 0 ? 1 : 0;
    }
    for (auto& client : clients) client->ping();
    EXPECT_GE(observer.ping().stats().clients(), 11u);
  }
  EXPECT_EQ(welcomed, 100);
  // Raw connections that close before saying anything.
  for (int i = 0; i < 50; ++i) RawConnection connection(server.port());

  EXPECT_EQ(clientsOnceSettled(observer, 1), 1u);
  EXPECT_LT(server.residentKb() - before, kLeftBehindKb);
  EXPECT_EQ(observer.ping().stats().ticks_skipped(), 0u);
  EXPECT_EQ(server.stop(), 0);
}

TEST(Churn, ClientLimitIsEnforcedWithAnError) {
  ServerProcess server({"--max-clients", "2"});
  auto first = std::make_unique<Client>(localClient(server.port(), "first"));
  Client second(localClient(server.port(), "second"));
  RawConnection third(server.port());
  const auto error = third.receiveError(milliseconds(5000));
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("server is full (2 clients)"), std::string::npos) << *error;
  EXPECT_TRUE(third.waitClosed(milliseconds(5000)));
  // A place frees up when a client leaves.
  first.reset();
  const auto deadline = Clock::now() + milliseconds(3000);
  while (second.ping().stats().clients() != 1 && Clock::now() < deadline) {
    std::this_thread::sleep_for(milliseconds(10));
  }
  Client replacement(localClient(server.port(), "replacement"));
  EXPECT_GT(replacement.welcome().client_id(), 0u);
}

TEST(Churn, SilentConnectionIsDroppedAfterTheHelloTimeout) {
  ServerProcess server({"--stall-timeout", "0.5"});
  RawConnection silent(server.port());
  const auto error = silent.receiveError(milliseconds(5000));
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("no Hello within"), std::string::npos) << *error;
  EXPECT_TRUE(silent.waitClosed(milliseconds(5000)));
}

}  // namespace
}  // namespace impulse::net_test
