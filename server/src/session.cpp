#include "impulse/server/session.h"

#include <algorithm>
#include <cassert>
#include <vector>

#include "impulse/server/log.h"

namespace impulse::server {

namespace {

// Frames gathered into one write call.
constexpr std::size_t kMaxGather = 32;
// Enough for 30 full-rate deltas of 2000 bodies per second over a 100 ms
// round trip (Linux doubles the value for its bookkeeping).
constexpr int kSendBufferBytes = 512 * 1024;
// How long a connection closed for an error drains input before it is reset.
constexpr auto kLingerTimeout = std::chrono::seconds(2);
// Read buffer range: most clients send a few small commands per tick, and a
// thousand idle connections should cost little; a flood earns the large one.
constexpr std::size_t kMinReadBuffer = 2 * 1024;
constexpr std::size_t kMaxReadBuffer = 64 * 1024;

// Refused commands logged per client: a burst of this many, then one a second.
constexpr double kRefusalLinesPerSecond = 1;
constexpr double kRefusalLineBurst = 10;

// How long a connection must have been silent before a newcomer may evict it.
constexpr auto kEvictableAfter = std::chrono::seconds(2);

std::string seconds(Clock::duration duration) {
  return std::to_string(std::chrono::duration<double>(duration).count()) + " s";
}

}  // namespace

Session::Session(asio::ip::tcp::socket socket, SessionHost& host, std::uint32_t id,
                 const SessionLimits& limits)
    : socket_(std::move(socket)),
      host_(host),
      id_(id),
      limits_(limits),
      connectedAt_(Clock::now()),
      lastActive_(connectedAt_),
      rate_(limits.commandsPerSecond, 2 * limits.commandsPerSecond, connectedAt_),
      rateTimer_(socket_.get_executor()),
      refusalLines_(kRefusalLinesPerSecond, kRefusalLineBurst, connectedAt_),
      readBuffer_(kMinReadBuffer),
      reader_(limits.maxFrameBytes),
      lastWriteProgress_(connectedAt_) {
  asio::error_code ec;
  const auto remote = socket_.remote_endpoint(ec);
  if (!ec) {
    address_ = remote.address().to_string();
    peer_ = address_ + ":" + std::to_string(remote.port());
  }
  // Replies are small and latency matters more than packet count.
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);
  // A fixed kernel send buffer (instead of autotuning up to several MiB)
  // bounds what a slow client holds in the kernel too, and makes it skip
  // snapshots after a fraction of a second instead of seconds.
  socket_.set_option(asio::socket_base::send_buffer_size(kSendBufferBytes), ec);
}

std::string Session::label() const {
  std::string text = room_.empty() ? "" : "room " + room_ + ", ";
  text += "client " + std::to_string(id_);
  if (!name_.empty()) text += " '" + name_ + "'";
  if (!peer_.empty()) text += " (" + peer_ + ")";
  return text;
}

void Session::log(std::string_view message) const { logLine(label() + " " + std::string(message)); }

void Session::logRefusal(std::string_view error) {
  if (!refusalLines_.take(Clock::now())) {
    ++refusalsNotLogged_;
    return;
  }
  std::string line = "refused: " + std::string(error);
  if (refusalsNotLogged_ > 0) {
    line += " (and " + std::to_string(refusalsNotLogged_) + " refusals before it not logged)";
    refusalsNotLogged_ = 0;
  }
  log(line);
}

bool Session::allowed(Phase from, Phase to) {
  switch (to) {
    case Phase::AwaitingHello:
      return false;
    case Phase::Serving:
      return from == Phase::AwaitingHello;
    case Phase::Streaming:
      return from == Phase::Serving;
    case Phase::Flushing:
      return from <= Phase::Streaming;
    case Phase::Lingering:
      return from == Phase::Flushing;
    case Phase::Closed:
      return from != Phase::Closed;
  }
  return false;
}

void Session::enter(Phase next) {
  // A refused transition is a bug in this file, not something a peer can cause.
  assert(allowed(phase_, next));
  phase_ = next;
}

void Session::start() { readMore(); }

void Session::reject(const std::string& message) { fatal(message); }

// ------------------------------------------------------------------- reading

void Session::readMore() {
  if (reading_ || phase_ == Phase::Closed) return;
  if (phase_ != Phase::Lingering) {
    if (!acceptingTraffic() || pendingCommandBytes_ >= limits_.maxPendingCommandBytes ||
        waitingForRate_) {
      return;
    }
    if (readBegin_ < readEnd_) return processBuffered();
  }
  sizeReadBuffer();
  reading_ = true;
  socket_.async_read_some(asio::buffer(readBuffer_),
                          [self = shared_from_this()](const asio::error_code& ec, std::size_t n) {
                            self->onRead(ec, n);
                          });
}

void Session::sizeReadBuffer() {
  std::size_t wanted = readBuffer_.size();
  if (lastReadBytes_ == readBuffer_.size()) wanted = std::min(wanted * 2, kMaxReadBuffer);
  if (lastReadBytes_ < kMinReadBuffer) wanted = kMinReadBuffer;
  // A new vector, not resize(): shrinking must give the memory back.
  if (wanted != readBuffer_.size()) readBuffer_ = std::vector<char>(wanted);
}

void Session::onRead(const asio::error_code& ec, std::size_t bytes) {
  reading_ = false;
  if (phase_ == Phase::Closed) return;
  if (phase_ == Phase::Lingering) {
    // Draining what the peer still sends, so that closing does not reset the
    // connection before it read our Error.
    if (ec) return close("closed after error");
    return readMore();
  }
  if (!acceptingTraffic()) return;
  if (ec) {
    if (ec == asio::error::eof && !reader_.atFrameBoundary()) {
      return fatal(reader_.truncationMessage());
    }
    return close(ec == asio::error::eof ? "disconnected" : ec.message());
  }
  readBegin_ = 0;
  readEnd_ = bytes;
  lastReadBytes_ = bytes;
  lastActive_ = Clock::now();
  processBuffered();
}

void Session::processBuffered() {
  // Stops early when the command cap is reached; the rest of the buffer waits
  // until commandsApplied() resumes reading.
  while (readBegin_ < readEnd_ && acceptingTraffic() &&
         pendingCommandBytes_ < limits_.maxPendingCommandBytes) {
    if (phase_ != Phase::AwaitingHello && !rateAllowsACommand()) return;
    const auto result =
        reader_.feed(std::span<const char>(readBuffer_.data() + readBegin_, readEnd_ - readBegin_));
    readBegin_ += result.consumed;
    if (result.status == wire::FrameReader::Status::Error) return fatal(reader_.error());
    if (result.status == wire::FrameReader::Status::Frame) handleFrame(reader_.frame());
  }
  if (readBegin_ == readEnd_) readMore();
}

void Session::handleFrame(std::string_view payload) {
  v1::ClientMessage message;
  if (!wire::parseFrame(payload, message)) {
    return fatal("a frame of " + std::to_string(payload.size()) +
                 " bytes does not parse as a ClientMessage");
  }
  if (phase_ == Phase::AwaitingHello) {
    if (!message.has_hello()) return fatal("the first message must be Hello");
    const auto& hello = message.hello();
    if (hello.protocol_version() != wire::kProtocolVersion) {
      return fatal("unsupported protocol version " + std::to_string(hello.protocol_version()) +
                   " (this server speaks " + std::to_string(wire::kProtocolVersion) + ")");
    }
    if (!v1::SnapshotEncoding_IsValid(hello.snapshot_encoding())) {
      return fatal("snapshot_encoding " + std::to_string(hello.snapshot_encoding()) +
                   " is not 0 (SNAPSHOT_ENCODING_PLAIN) or 1 (SNAPSHOT_ENCODING_QUANTIZED)");
    }
    quantized_ = hello.snapshot_encoding() == v1::SNAPSHOT_ENCODING_QUANTIZED;
    enter(Phase::Serving);
    // The name only labels log lines: short and printable.
    name_ = hello.client_name().substr(0, 64);
    for (char& c : name_) {
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    }
    host_.onHello(shared_from_this(), hello);
    return;
  }
  rate_.take(Clock::now());
  pendingCommandBytes_ += payload.size();
  host_.onCommand(shared_from_this(), std::move(message), payload.size());
}

bool Session::rateAllowsACommand() {
  const auto wait = rate_.untilAvailable(Clock::now());
  if (wait == Clock::duration::zero()) return true;
  // Past its rate, the client is slowed, not refused: its bytes stay in the
  // socket (and TCP stops it) until a command's worth of budget refilled,
  // so its commands are applied and answered in the order it sent them.
  waitingForRate_ = true;
  ++rateWaits_;
  rateTimer_.expires_after(wait);
  rateTimer_.async_wait([self = shared_from_this()](const asio::error_code& ec) {
    self->waitingForRate_ = false;
    if (!ec) self->readMore();
  });
  return false;
}

void Session::commandsApplied(std::size_t bytes) {
  // A client waiting for the replies to a backlog is busy, not idle.
  lastActive_ = Clock::now();
  const bool wasPaused = pendingCommandBytes_ >= limits_.maxPendingCommandBytes;
  pendingCommandBytes_ -= std::min(bytes, pendingCommandBytes_);
  if (wasPaused) readMore();
}

// ------------------------------------------------------------------- writing

void Session::send(const v1::ServerMessage& message) {
  if (phase_ == Phase::Closed) return;
  SharedFrame frame = wire::encodeSharedFrame(message);
  // A scene is the one reply that can be large: behind an unread backlog it
  // is answered by a short refusal instead, and the client stays.
  if (message.has_scene_data() && !replyFits(frame->size())) {
    frame =
        wire::encodeSharedFrame(sceneNotQueued(message.scene_data().request_id(), frame->size()));
  }
  push({std::move(frame), false});
}

bool Session::replyFits(std::size_t bytes) const {
  // One reply larger than the cap may wait beside the capped ones: a client
  // is never closed for the size of what it asked for.
  if (bytes > limits_.maxQueuedReplyBytes) return oversizedReplyBytes_ == 0;
  return queuedReplyBytes_ + bytes <= limits_.maxQueuedReplyBytes;
}

std::size_t& Session::replyBytesOf(std::size_t bytes) {
  return bytes > limits_.maxQueuedReplyBytes ? oversizedReplyBytes_ : queuedReplyBytes_;
}

v1::ServerMessage Session::sceneNotQueued(std::uint64_t requestId, std::size_t bytes) const {
  v1::ServerMessage refusal;
  auto* result = refusal.mutable_command_result();
  result->set_request_id(requestId);
  result->set_ok(false);
  result->set_error("save: the scene (" + std::to_string(bytes) +
                    " bytes) was not sent: " +
                    std::to_string(queuedReplyBytes_ + oversizedReplyBytes_) +
                    " bytes of earlier replies are still unread (at most " +
                    std::to_string(limits_.maxQueuedReplyBytes) +
                    " may wait); read them, then ask again");
  return refusal;
}

void Session::subscribe(SnapshotSource& source) {
  if (phase_ != Phase::Serving) return;
  enter(Phase::Streaming);
  snapshotSource_ = &source;
  lastSnapshot_ = Clock::now();
  push({nullptr, true});
}

void Session::offerSnapshot(std::uint64_t sequence, const SharedFrame& delta) {
  if (phase_ != Phase::Streaming) return;
  lastSnapshot_ = Clock::now();
  if (fullSnapshotRequested_) return;
  if (unsentSnapshot_) {
    // The client has not taken the previous snapshot yet: instead of queueing
    // both, the unsent one becomes a full snapshot, requested when the
    // socket is ready for it.
    for (std::size_t i = queue_.size(); i-- > lockedItems();) {
      if (queue_[i].snapshot) {
        queue_[i].frame = nullptr;
        break;
      }
    }
    // (The snapshot a new subscriber waits for is not a skip.)
    if (lastSnapshotSequence_) ++snapshotsSkipped_;
    return;
  }
  const bool chained = lastSnapshotSequence_ && *lastSnapshotSequence_ + 1 == sequence;
  if (chained) lastSnapshotSequence_ = sequence;
  push({chained ? delta : nullptr, true});
}

void Session::takeFullSnapshot(SharedFrame frame, std::uint64_t sequence) {
  fullSnapshotRequested_ = false;
  // An Error or a close since the request dropped the snapshot waiting for it.
  if (phase_ != Phase::Streaming || queue_.empty()) return;
  auto& front = queue_.front();
  if (!front.snapshot || front.frame) return;
  front.frame = std::move(frame);
  lastSnapshotSequence_ = sequence;
  writeMore();
}

void Session::push(Outgoing item) {
  if (!acceptingTraffic()) return;
  if (!item.snapshot && !replyFits(item.frame->size())) {
    return close("not reading its replies (" + std::to_string(queuedReplyBytes_ + item.frame->size()) +
                 " bytes queued)");
  }
  enqueue(std::move(item));
}

void Session::offerEvents(const SharedFrame& frame) {
  if (!acceptingTraffic()) return;
  if (!replyFits(frame->size())) {
    ++eventsDropped_;
    return;
  }
  enqueue({frame, false});
}

void Session::enqueue(Outgoing item) {
  if (item.snapshot) {
    unsentSnapshot_ = true;
  } else {
    replyBytesOf(item.frame->size()) += item.frame->size();
  }
  queue_.push_back(std::move(item));
  writeMore();
}

std::size_t Session::lockedItems() const {
  if (inFlight_ > 0) return inFlight_;
  return writeOffset_ > 0 ? 1 : 0;
}

bool Session::awaitingFullSnapshot() {
  const auto& front = queue_.front();
  if (!front.snapshot || front.frame) return false;
  // Requested only now that the socket is ready for it, so the frame is
  // written as soon as it comes and no newer broadcast replaces it unsent.
  if (!fullSnapshotRequested_) {
    fullSnapshotRequested_ = true;
    snapshotSource_->requestFullSnapshot(id_, quantized_);
  }
  return true;
}

void Session::writeMore() {
  if (inFlight_ > 0 || phase_ == Phase::Closed) return;
  if (queue_.empty()) {
    if (phase_ == Phase::Flushing) startLinger();
    return;
  }
  if (awaitingFullSnapshot()) return;
  std::vector<asio::const_buffer> buffers;
  const std::size_t available = std::min(queue_.size(), kMaxGather);
  buffers.reserve(available);
  std::size_t count = 0;
  // Gathers up to a full snapshot still to be requested: it waits for the
  // next call, when everything before it is written.
  for (; count < available && queue_[count].frame; ++count) {
    auto& item = queue_[count];
    if (item.snapshot) unsentSnapshot_ = false;
    const std::size_t skip = count == 0 ? writeOffset_ : 0;
    buffers.emplace_back(item.frame->data() + skip, item.frame->size() - skip);
  }
  inFlight_ = count;
  lastWriteProgress_ = Clock::now();
  socket_.async_write_some(buffers,
                           [self = shared_from_this()](const asio::error_code& ec, std::size_t n) {
                             self->inFlight_ = 0;
                             if (self->phase_ == Phase::Closed) return;
                             if (ec) return self->close(ec.message());
                             self->onWritten(n);
                           });
}

void Session::onWritten(std::size_t bytes) {
  lastWriteProgress_ = Clock::now();
  while (bytes > 0 && !queue_.empty()) {
    auto& front = queue_.front();
    const std::size_t remaining = front.frame->size() - writeOffset_;
    if (bytes < remaining) {
      writeOffset_ += bytes;
      break;
    }
    bytes -= remaining;
    writeOffset_ = 0;
    if (!front.snapshot) replyBytesOf(front.frame->size()) -= front.frame->size();
    queue_.pop_front();
  }
  writeMore();
}

// ------------------------------------------------------------------- closing

void Session::fatal(const std::string& message) {
  if (!acceptingTraffic()) return;
  logLine(label() + ": " + message);
  v1::ServerMessage error;
  error.mutable_error()->set_message(message);
  // Nothing else is worth sending: the error goes next, then the socket closes.
  queue_.erase(queue_.begin() + std::ptrdiff_t(lockedItems()), queue_.end());
  queuedReplyBytes_ = 0;
  oversizedReplyBytes_ = 0;
  for (const auto& item : queue_) {
    if (!item.snapshot) replyBytesOf(item.frame->size()) += item.frame->size();
  }
  unsentSnapshot_ = false;
  enter(Phase::Flushing);
  queue_.push_back({wire::encodeSharedFrame(error), false});
  replyBytesOf(queue_.back().frame->size()) += queue_.back().frame->size();
  writeMore();
}

void Session::startLinger() {
  enter(Phase::Lingering);
  lingerSince_ = Clock::now();
  asio::error_code ignored;
  socket_.shutdown(asio::ip::tcp::socket::shutdown_send, ignored);
  readMore();
}

void Session::checkTimeouts(Clock::time_point now) {
  if (phase_ == Phase::Closed) return;
  if (phase_ == Phase::Lingering) {
    if (now - lingerSince_ > kLingerTimeout) close("closed after error");
    return;
  }
  if (inFlight_ > 0 && now - lastWriteProgress_ > limits_.stallTimeout) {
    return close("stalled: accepted no data for " + seconds(limits_.stallTimeout));
  }
  if (phase_ == Phase::Flushing) return;
  if (phase_ == Phase::AwaitingHello && now - connectedAt_ > limits_.stallTimeout) {
    return fatal("no Hello within " + seconds(limits_.stallTimeout));
  }
  // A subscriber is busy while snapshots flow (the stall timeout drops it
  // when it stops reading them); one of a paused room that neither sends
  // nor gets anything holds the room open for nothing.
  if (pendingCommandBytes_ > 0) return;
  if (phase_ == Phase::Serving && now - lastActive_ > limits_.idleTimeout) {
    fatal("idle: sent nothing for " + seconds(limits_.idleTimeout) + " and subscribes to nothing");
  } else if (phase_ == Phase::Streaming &&
             now - std::max(lastActive_, lastSnapshot_) > limits_.idleTimeout) {
    fatal("idle: sent nothing and was sent no snapshot (its room is paused) for " +
          seconds(limits_.idleTimeout));
  }
}

bool Session::evictable(Clock::time_point now) const {
  return phase_ <= Phase::Serving && queue_.empty() && pendingCommandBytes_ == 0 &&
         now - lastActive_ >= kEvictableAfter;
}

void Session::evict(Clock::time_point now) {
  fatal("closed to make room for a new connection: sent nothing for " +
        seconds(now - lastActive_) + " while the server or this address was full");
}

void Session::close(const std::string& reason) {
  if (phase_ == Phase::Closed) return;
  enter(Phase::Closed);
  rateTimer_.cancel();
  log("closed: " + reason);
  asio::error_code ignored;
  socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  socket_.close(ignored);
  queue_.clear();
  host_.onClosed(*this);
}

}  // namespace impulse::server
