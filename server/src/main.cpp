// impulse-server: the authoritative world served over TCP.
#include <pthread.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <string_view>
#include <vector>

#include <asio/thread_pool.hpp>

#include "impulse/server/log.h"
#include "impulse/server/options.h"
#include "impulse/server/server.h"

namespace {

// timeout(1), and some orchestrators, signal the process group as well as
// the process: a second SIGTERM can come once the signal set is gone and
// would kill a server that is already stopping (exit 143 instead of 0).
// Called when only this thread is left: blocked, it is dropped at exit.
void blockStopSignals() {
  sigset_t stops;
  sigemptyset(&stops);
  sigaddset(&stops, SIGINT);
  sigaddset(&stops, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stops, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace impulse::server;
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  const auto parsed = parseOptions(args, optionsFromEnvironment());
  if (parsed.help) {
    std::fputs(usage().c_str(), stdout);
    return 0;
  }
  if (!parsed.options) {
    std::fprintf(stderr, "impulse-server: %s\n", parsed.error.c_str());
    return 2;
  }
  try {
    // Declared first: the rooms' strands post to the io_context until the pool is joined.
    asio::thread_pool steppers(std::size_t(parsed.options->roomThreads));
    asio::io_context io;
    Server server(io, steppers, *parsed.options);
    asio::signal_set signals(io, SIGINT, SIGTERM);
    signals.async_wait([&server](const asio::error_code& ec, int signal) {
      if (ec) return;
      logLine(std::string("received ") + (signal == SIGINT ? "SIGINT" : "SIGTERM"));
      server.stop();
    });
    server.start();
    const auto endpoint = server.endpoint();
    const auto address = endpoint.address();
    const std::string host =
        address.is_v6() ? "[" + address.to_string() + "]" : address.to_string();
    // Scripts read the port from this line: keep it first and exact.
    std::printf("listening on %s:%u\n", host.c_str(), unsigned(endpoint.port()));
    std::fflush(stdout);
    io.run();
    steppers.join();
    blockStopSignals();
    logLine("stopped");
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impulse-server: %s\n", error.what());
    return 1;
  }
}
