// Malformed input: each abusive connection gets an Error and is closed,
// while another client's Ping is still answered promptly.
#include <random>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
using Clock = std::chrono::steady_clock;

// A tick is 16.7 ms; "promptly" leaves room for a loaded 2-core machine and
// sanitizer builds.
constexpr auto kPrompt = milliseconds(500);

class MalformedInput : public ::testing::Test {
 protected:
  MalformedInput() : observer_(localClient(server_.port(), "observer")) {}

  // The connection got an Error containing `expected` and was closed, and
  // the observer's Ping came back promptly.
  void expectErrorAndClose(RawConnection& connection, const std::string& expected) {
    const auto error = connection.receiveError(milliseconds(5000));
    ASSERT_TRUE(error.has_value()) << "no Error for: " << expected;
    EXPECT_NE(error->find(expected), std::string::npos) << *error;
    EXPECT_TRUE(connection.waitClosed(milliseconds(5000))) << expected;
    expectObserverAnswered();
  }

  void expectObserverAnswered() {
    const auto start = Clock::now();
    const auto pong = observer_.ping(milliseconds(5000));
    EXPECT_LT(Clock::now() - start, kPrompt);
    EXPECT_GT(pong.stats().clock_ticks(), 0u);
  }

  ServerProcess server_{{"--max-frame-bytes", "65536"}};
  Client observer_;
};

TEST_F(MalformedInput, RandomBytes) {
  std::mt19937 random(1234);
  std::string bytes(4096, '\0');
  for (auto& byte : bytes) byte = char(random());
  // The first byte decides whether the length is legal; make it a small,
  // valid length so the bytes themselves must be judged.
  bytes[0] = 40;
  RawConnection connection(server_.port());
  connection.send(bytes);
  expectErrorAndClose(connection, "");
}

TEST_F(MalformedInput, OversizedFrameHeader) {
  RawConnection connection(server_.port());
  connection.send(wire::encodeVarint(65537));
  expectErrorAndClose(connection, "exceeds the limit of 65536 bytes");
}

TEST_F(MalformedInput, HugeLengthBeforeHello) {
  RawConnection connection(server_.port());
  connection.send(wire::encodeVarint(~std::uint64_t(0)));
  expectErrorAndClose(connection, "exceeds the limit");
}

TEST_F(MalformedInput, OverLongVarint) {
  RawConnection connection(server_.port());
  connection.send(std::string(11, char(0x80)) + char(0x01));
  expectErrorAndClose(connection, "longer than 10 bytes");
}

TEST_F(MalformedInput, CommandBeforeHello) {
  RawConnection connection(server_.port());
  connection.sendMessage(client::ping(1));
  expectErrorAndClose(connection, "the first message must be Hello");
}

TEST_F(MalformedInput, UnsupportedProtocolVersion) {
  RawConnection connection(server_.port());
  connection.sendHello(2);
  expectErrorAndClose(connection, "unsupported protocol version 2");
}

TEST_F(MalformedInput, UnsupportedVersionThroughTheClientLibrary) {
  auto options = localClient(server_.port());
  options.protocolVersion = 7;
  try {
    Client client(options);
    FAIL() << "connected with protocol version 7";
  } catch (const client::ConnectionError& error) {
    EXPECT_NE(std::string(error.what()).find("unsupported protocol version 7"), std::string::npos)
        << error.what();
  }
  expectObserverAnswered();
}

TEST_F(MalformedInput, FrameCutOffMidway) {
  RawConnection connection(server_.port());
  connection.sendHello();
  ASSERT_TRUE(connection.receive(milliseconds(5000)).has_value());  // Welcome
  connection.send(wire::encodeVarint(100) + std::string(50, 'z'));
  connection.shutdownWrite();
  expectErrorAndClose(connection, "stream ended inside a frame: 50 of 100 bytes received");
}

TEST_F(MalformedInput, FrameThatIsNotAMessage) {
  RawConnection connection(server_.port());
  connection.sendHello();
  // Field 1 as a length-delimited field running past the frame.
  connection.send(wire::encodeVarint(2) + std::string("\x0a\x7f", 2));
  expectErrorAndClose(connection, "does not parse as a ClientMessage");
}

TEST_F(MalformedInput, BadCommandsAfterHelloKeepTheConnection) {
  Client client(localClient(server_.port(), "bad-commands", false));
  const auto nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<v1::ClientMessage> bad = {
      client::spawnCircle({nan, 1}, 1),
      client::spawnPolygon(std::vector<client::Point>{{1, 1}, {2, 2}}),
      client::removeBody(4242),
      client::queryBody(4242),
      client::applyImpulse(4242, {1, 1}),
  };
  for (const auto& reply : requestAll(client, bad)) {
    EXPECT_FALSE(result(reply).ok());
    EXPECT_FALSE(result(reply).error().empty());
  }
  // Still connected and served.
  EXPECT_GT(client.ping().stats().clock_ticks(), 0u);
  expectObserverAnswered();
}

TEST_F(MalformedInput, ManyAbusersAtOnce) {
  std::vector<std::unique_ptr<RawConnection>> abusers;
  for (int i = 0; i < 20; ++i) {
    abusers.push_back(std::make_unique<RawConnection>(server_.port()));
    abusers.back()->send(i % 2 == 0 ? wire::encodeVarint(1) + "\xff" : std::string(12, char(0x80)));
  }
  expectObserverAnswered();
  for (auto& abuser : abusers) {
    EXPECT_TRUE(abuser->receiveError(milliseconds(5000)).has_value());
    EXPECT_TRUE(abuser->waitClosed(milliseconds(5000)));
  }
  expectObserverAnswered();
}

}  // namespace
}  // namespace impulse::net_test
