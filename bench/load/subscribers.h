#pragma once
// The load bench's subscribers: N raw connections that say Hello with
// want_snapshots and the chosen encoding, then read everything the server
// sends, counting bytes and frames. One thread polls them all, so the
// readers cost the shared machine little; they never decode (a client's
// decoding is not the server's load), except for one frame in 30 that
// checks how many body states a snapshot carries.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "impulse.pb.h"

namespace load {

/// What a subscriber asks for in Hello (docs/protocol.md, "Compact snapshots").
enum class Encoding { Plain, Quantized };

/// "plain" or "quantized"; false for a name this build does not know.
bool parseEncoding(const std::string& name, Encoding& encoding);
/// The Hello a subscriber sends to `room`.
impulse::v1::ClientMessage subscriberHello(Encoding encoding, int index, const std::string& room);

/// What subscriber `index` sends when it connects: its Hello, then any
/// commands (an area of interest, a budget).
using Opening = std::function<std::vector<impulse::v1::ClientMessage>(int index)>;

struct SubscriberCounts {
  std::uint64_t bytes = 0;
  std::uint64_t frames = 0;
};

class Subscribers {
 public:
  /// Connects `count` subscribers to 127.0.0.1:`port`, sends each its
  /// opening and starts reading. Subscriber 0 decodes one frame in
  /// `sampleEvery`.
  Subscribers(std::uint16_t port, int count, const Opening& opening, std::uint64_t sampleEvery);
  ~Subscribers();
  Subscribers(const Subscribers&) = delete;
  Subscribers& operator=(const Subscribers&) = delete;

  /// Bytes and frames each subscriber has read so far.
  std::vector<SubscriberCounts> counts() const;
  /// Body states in the newest sampled snapshot (subscriber 0; a full one
  /// when it fell behind).
  std::uint32_t sampledBodies() const { return sampledBodies_.load(); }
  /// Bytes of quantized body states in that snapshot (quantized encoding).
  std::uint32_t sampledQuantizedBytes() const { return sampledQuantizedBytes_.load(); }
  /// The most Snapshot.oldest_withheld_ticks seen in a sampled snapshot (a
  /// bandwidth budget's longest wait, as far as the samples saw it).
  std::uint64_t sampledOldestWithheldTicks() const { return sampledOldestWithheld_.load(); }
  /// Connections the server closed (a healthy run has none).
  int closed() const { return closed_.load(); }

 private:
  struct Connection {
    int socket = -1;
    std::atomic<std::uint64_t> bytes = 0;
    std::atomic<std::uint64_t> frames = 0;
    /// Frame parsing: payload bytes left of the current frame, else the
    /// varint length being read.
    std::uint64_t frameLeft = 0;
    std::uint64_t header = 0;
    int headerShift = 0;
    /// The current frame is kept for the body-count sample.
    bool sampling = false;
  };
  void run();
  /// Reads what `connection` has; false once the server closed it.
  bool readFrom(Connection& connection, bool sampled);
  void consume(Connection& connection, const char* data, std::size_t size, bool sampled);
  void sampleFrame();

  std::vector<std::unique_ptr<Connection>> connections_;
  std::string sample_;
  std::atomic<std::uint32_t> sampledBodies_ = 0;
  std::atomic<std::uint32_t> sampledQuantizedBytes_ = 0;
  std::atomic<std::uint64_t> sampledOldestWithheld_ = 0;
  std::uint64_t sampleEvery_;
  std::atomic<int> closed_ = 0;
  std::atomic<bool> stop_ = false;
  std::thread reader_;
};

}  // namespace load
