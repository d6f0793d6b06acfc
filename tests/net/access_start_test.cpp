// Access at start (docs/protocol.md, "Access"): a server bound beyond loopback
// without a token refuses to start, saying how to give one; a token from
// the environment (the Docker image's way) is enough.
#include <sys/wait.h>

#include <cstdio>
#include <optional>
#include <string>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

struct StartAttempt {
  int exitCode = -1;
  std::string output;  // stdout and stderr
};

/// Runs `environment impulse-server arguments` until it exits; a server that
/// does start (prints its listening line) is stopped at once.
StartAttempt startServer(const std::string& environment, const std::string& arguments) {
  const std::string command = "env -u IMPULSE_TOKEN -u IMPULSE_ADMIN_TOKEN " + environment +
                              " timeout --preserve-status -s TERM 2 " + IMPULSE_SERVER_BINARY + " " + arguments +
                              " 2>&1";
  StartAttempt attempt;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return attempt;
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) attempt.output += buffer;
  const int status = pclose(pipe);
  attempt.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return attempt;
}

TEST(AccessAtStart, AnyAddressWithoutTokenIsRefusedSayingHowToSetOne) {
  const auto attempt = startServer("", "--bind 0.0.0.0 --port 0");
  EXPECT_EQ(attempt.exitCode, 2);
  EXPECT_EQ(attempt.output,
            "impulse-server: refusing to bind 0.0.0.0 without a token: give --token (or "
            "IMPULSE_TOKEN), or bind 127.0.0.1\n");
}

TEST(AccessAtStart, RoutableAddressWithoutTokenIsRefused) {
  const auto attempt = startServer("", "--bind 10.1.2.3 --port 0");
  EXPECT_EQ(attempt.exitCode, 2);
  EXPECT_TRUE(mentions(attempt.output, "refusing to bind 10.1.2.3 without a token")) << attempt.output;
}

TEST(AccessAtStart, EmptyTokenIsRefused) {
  const auto attempt = startServer("", "--bind 0.0.0.0 --port 0 --token=");
  EXPECT_EQ(attempt.exitCode, 2);
  EXPECT_TRUE(mentions(attempt.output, "--token expects a non-empty token")) << attempt.output;
}

TEST(AccessAtStart, TokenFromTheEnvironmentLetsItBindAnyAddress) {
  // As the Docker image runs it: --bind 0.0.0.0 and IMPULSE_TOKEN.
  const auto attempt = startServer("IMPULSE_TOKEN=from-env", "--bind 0.0.0.0 --port 0");
  EXPECT_TRUE(mentions(attempt.output, "listening on 0.0.0.0:")) << attempt.output;
  EXPECT_EQ(attempt.exitCode, 0);  // stopped by timeout's SIGTERM: a clean exit
}

/// The Error a Hello offering `token` gets from a server started with --token secret.
std::optional<std::string> helloRefusal(std::uint16_t port, const std::string& token) {
  RawConnection raw(port);
  v1::ClientMessage hello;
  hello.mutable_hello()->set_protocol_version(1);
  hello.mutable_hello()->set_token(token);
  raw.sendMessage(hello);
  auto error = raw.receiveError(milliseconds(3000));
  EXPECT_TRUE(raw.waitClosed(milliseconds(3000)));
  return error;
}

TEST(AccessAtStart, HelloWithoutTheRightTokenIsRefused) {
  ServerProcess server({"--token", "secret"});
  EXPECT_EQ(helloRefusal(server.port(), ""), "this server requires a token (Hello.token)");
  EXPECT_EQ(helloRefusal(server.port(), "guess"), "Hello.token is not valid for this server");
  client::Client admitted(withToken(server.port(), "admitted", "secret"));
  EXPECT_GT(admitted.welcome().client_id(), 0u);
}

}  // namespace
}  // namespace impulse::net_test
