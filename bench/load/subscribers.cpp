#include "subscribers.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>

#include "impulse/wire/framing.h"

namespace load {

namespace {

int connectLoopback(std::uint16_t port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (fd < 0 || connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    if (fd >= 0) close(fd);
    throw std::runtime_error("cannot connect a subscriber to port " + std::to_string(port));
  }
  return fd;
}

void sendAll(int fd, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const auto n = send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) throw std::runtime_error("a subscriber's Hello could not be sent");
    sent += std::size_t(n);
  }
}

}  // namespace

bool parseEncoding(const std::string& name, Encoding& encoding) {
  if (name == "plain") {
    encoding = Encoding::Plain;
    return true;
  }
  if (name == "quantized") {
    encoding = Encoding::Quantized;
    return true;
  }
  return false;
}

impulse::v1::ClientMessage subscriberHello(Encoding encoding, int index, const std::string& room) {
  impulse::v1::ClientMessage message;
  auto* hello = message.mutable_hello();
  hello->set_protocol_version(1);
  hello->set_room(room);
  hello->set_client_name("load-subscriber-" + std::to_string(index));
  hello->set_want_snapshots(true);
  switch (encoding) {
    case Encoding::Plain:
      break;  // SNAPSHOT_ENCODING_PLAIN is Hello's default
    case Encoding::Quantized:
      hello->set_snapshot_encoding(impulse::v1::SNAPSHOT_ENCODING_QUANTIZED);
      break;
  }
  return message;
}

Subscribers::Subscribers(std::uint16_t port, int count, const Opening& opening, std::uint64_t sampleEvery)
    : sampleEvery_(sampleEvery) {
  for (int i = 0; i < count; ++i) {
    auto connection = std::make_unique<Connection>();
    connection->socket = connectLoopback(port);
    for (const auto& message : opening(i)) sendAll(connection->socket, impulse::wire::encodeFrame(message));
    connections_.push_back(std::move(connection));
  }
  reader_ = std::thread([this] { run(); });
}

Subscribers::~Subscribers() {
  stop_ = true;
  reader_.join();
  for (const auto& connection : connections_) close(connection->socket);
}

std::vector<SubscriberCounts> Subscribers::counts() const {
  std::vector<SubscriberCounts> counts;
  for (const auto& connection : connections_) {
    counts.push_back({connection->bytes.load(), connection->frames.load()});
  }
  return counts;
}

void Subscribers::run() {
  std::vector<pollfd> fds;
  for (const auto& connection : connections_) fds.push_back({connection->socket, POLLIN, 0});
  while (!stop_) {
    if (poll(fds.data(), fds.size(), 100) <= 0) continue;
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd < 0 || (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
      if (!readFrom(*connections_[i], i == 0)) {
        fds[i].fd = -1;  // poll ignores it from now on
        ++closed_;
      }
    }
  }
}

bool Subscribers::readFrom(Connection& connection, bool sampled) {
  char buffer[1 << 16];
  const auto n = recv(connection.socket, buffer, sizeof buffer, MSG_DONTWAIT);
  if (n == 0) return false;
  if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
  connection.bytes += std::uint64_t(n);
  consume(connection, buffer, std::size_t(n), sampled);
  return true;
}

void Subscribers::consume(Connection& connection, const char* data, std::size_t size,
                          bool sampled) {
  std::size_t at = 0;
  while (at < size) {
    if (connection.frameLeft == 0) {
      // The varint length before each frame (framing.h).
      const auto byte = static_cast<unsigned char>(data[at++]);
      connection.header |= std::uint64_t(byte & 0x7f) << connection.headerShift;
      connection.headerShift += 7;
      if (byte & 0x80) continue;
      connection.frameLeft = connection.header;
      connection.header = 0;
      connection.headerShift = 0;
      const std::uint64_t frame = connection.frames++;
      connection.sampling = sampled && frame % sampleEvery_ == 0;
      sample_.clear();
      continue;
    }
    const std::size_t take = std::size_t(std::min<std::uint64_t>(connection.frameLeft, size - at));
    if (connection.sampling) sample_.append(data + at, take);
    connection.frameLeft -= take;
    at += take;
    if (connection.frameLeft == 0 && connection.sampling) sampleFrame();
  }
}

void Subscribers::sampleFrame() {
  impulse::v1::ServerMessage message;
  if (!message.ParseFromString(sample_) || !message.has_snapshot()) return;
  sampledBodies_ = std::uint32_t(message.snapshot().bodies_size());
  sampledQuantizedBytes_ = std::uint32_t(message.snapshot().quantized_bodies().size());
  sampledOldestWithheld_ = std::max(sampledOldestWithheld_.load(), message.snapshot().oldest_withheld_ticks());
}

}  // namespace load
