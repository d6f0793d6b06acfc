#include "impulse/client/client.h"

#include "impulse/client/commands.h"
#include "impulse/wire/parse_number.h"

namespace impulse::client {

namespace {

using SteadyClock = std::chrono::steady_clock;

std::uint64_t replyId(const v1::ServerMessage& message) {
  switch (message.message_case()) {
    case v1::ServerMessage::kCommandResult:
      return message.command_result().request_id();
    case v1::ServerMessage::kBodyInfo:
      return message.body_info().request_id();
    case v1::ServerMessage::kJointInfo:
      return message.joint_info().request_id();
    case v1::ServerMessage::kPong:
      return message.pong().request_id();
    case v1::ServerMessage::kRoomList:
      return message.room_list().request_id();
    case v1::ServerMessage::kSceneData:
      return message.scene_data().request_id();
    case v1::ServerMessage::kQueryResult:
      return message.query_result().request_id();
    default:
      return 0;
  }
}

}  // namespace

std::optional<std::pair<std::string, std::uint16_t>> parseHostPort(std::string_view text) {
  const auto colon = text.rfind(':');
  if (colon == std::string_view::npos || colon == 0) return std::nullopt;
  std::string_view host = text.substr(0, colon);
  const std::string_view portText = text.substr(colon + 1);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);
  }
  const auto port = wire::parseNumber<unsigned>(portText);
  if (!port || *port == 0 || *port > 65535) return std::nullopt;
  return std::make_pair(std::string(host), std::uint16_t(*port));
}

Client::Client(const ConnectOptions& options)
    : socket_(io_), reader_(options.maxFrameBytes), oneWayDelay_(options.addedRoundTrip / 2) {
  if (options.addedRoundTrip.count() < 0) {
    throw ConnectionError("ConnectOptions::addedRoundTrip " + std::to_string(options.addedRoundTrip.count()) +
                          " ms is negative");
  }
  const auto deadline = SteadyClock::now() + options.timeout;
  asio::error_code ec;
  asio::ip::tcp::resolver resolver(io_);
  const auto endpoints = resolver.resolve(options.host, std::to_string(options.port), ec);
  if (ec) throw ConnectionError("cannot resolve " + options.host + ": " + ec.message());

  const std::string target = options.host + ":" + std::to_string(options.port);
  ec = asio::error::host_not_found;
  for (const auto& entry : endpoints) {
    asio::error_code ignored;
    socket_.close(ignored);
    socket_.open(entry.endpoint().protocol(), ec);
    if (ec) continue;
    if (options.receiveBufferBytes > 0) {
      socket_.set_option(asio::socket_base::receive_buffer_size(options.receiveBufferBytes), ec);
    }
    bool done = false;
    socket_.async_connect(entry.endpoint(), [&](const asio::error_code& error) {
      ec = error;
      done = true;
    });
    io_.restart();
    io_.run_until(deadline);
    if (!done) throw ConnectionError("connecting to " + target + " timed out");
    if (!ec) break;
  }
  if (ec) throw ConnectionError("cannot connect to " + target + ": " + ec.message());
  io_.restart();
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);

  v1::ClientMessage hello;
  hello.mutable_hello()->set_protocol_version(options.protocolVersion);
  hello.mutable_hello()->set_client_name(options.name);
  hello.mutable_hello()->set_want_snapshots(options.wantSnapshots);
  hello.mutable_hello()->set_token(options.token);
  hello.mutable_hello()->set_room(options.room);
  hello.mutable_hello()->set_snapshot_encoding(options.snapshotEncoding);
  if (options.roomBounds) {
    auto* bounds = hello.mutable_hello();
    bounds->mutable_room_min()->set_x(options.roomBounds->min.x);
    bounds->mutable_room_min()->set_y(options.roomBounds->min.y);
    bounds->mutable_room_max()->set_x(options.roomBounds->max.x);
    bounds->mutable_room_max()->set_y(options.roomBounds->max.y);
  }
  send(std::move(hello));
  while (!welcome_.has_world_max()) {
    if (!receiveOne(deadline)) throw ConnectionError("no Welcome from " + target);
  }
  if (options.wantSnapshots) {
    while (mirror_.snapshotsApplied() == 0) {
      if (!receiveOne(deadline)) throw ConnectionError("no first snapshot from " + target);
    }
  }
}

Client::~Client() {
  asio::error_code ignored;
  socket_.shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  socket_.close(ignored);
}

void Client::throwIfFailed() const {
  if (!failure_.empty()) throw ConnectionError(failure_);
}

std::uint64_t Client::send(v1::ClientMessage message) {
  throwIfFailed();
  const std::uint64_t id = nextRequestId_++;
  message.set_request_id(id);
  std::string frame = wire::encodeFrame(message);
  if (oneWayDelay_.count() == 0) {
    writeFrame(frame);
  } else {
    delayedFrames_.emplace_back(SteadyClock::now() + oneWayDelay_, std::move(frame));
    writeDueFrames();
  }
  return id;
}

void Client::writeFrame(const std::string& frame) {
  asio::error_code ec;
  asio::write(socket_, asio::buffer(frame), ec);
  if (ec) {
    failure_ = "sending failed: " + ec.message();
    throwIfFailed();
  }
}

void Client::writeDueFrames() {
  const auto now = SteadyClock::now();
  while (!delayedFrames_.empty() && delayedFrames_.front().first <= now) {
    writeFrame(delayedFrames_.front().second);
    delayedFrames_.pop_front();
  }
}

SteadyClock::time_point Client::nextDue(SteadyClock::time_point deadline) const {
  if (!delayedFrames_.empty()) deadline = std::min(deadline, delayedFrames_.front().first);
  if (!inbox_.empty()) deadline = std::min(deadline, inbox_.front().due);
  return deadline;
}

bool Client::receivedDue(SteadyClock::time_point now) const {
  return !inbox_.empty() && inbox_.front().due <= now;
}

void Client::startRead() {
  if (reading_ || !failure_.empty()) return;
  reading_ = true;
  socket_.async_read_some(asio::buffer(buffer_), [this](const asio::error_code& ec, std::size_t n) {
    reading_ = false;
    if (ec) {
      failure_ = ec == asio::error::eof ? "the server closed the connection" : ec.message();
      return;
    }
    std::span<const char> data(buffer_.data(), n);
    while (!data.empty()) {
      const auto result = reader_.feed(data);
      data = data.subspan(result.consumed);
      if (result.status == wire::FrameReader::Status::Error) {
        failure_ = "bad frame from the server: " + reader_.error();
        return;
      }
      if (result.status == wire::FrameReader::Status::Frame) {
        v1::ServerMessage message;
        if (!wire::parseFrame(reader_.frame(), message)) {
          failure_ = "a frame from the server does not parse";
          return;
        }
        inbox_.push_back({std::move(message), reader_.frame().size(), SteadyClock::now() + oneWayDelay_});
      }
    }
  });
}

bool Client::receiveOne(SteadyClock::time_point deadline) {
  while (true) {
    writeDueFrames();
    if (receivedDue(SteadyClock::now())) break;
    throwIfFailed();
    startRead();
    if (io_.stopped()) io_.restart();
    if (SteadyClock::now() >= deadline) {
      io_.poll();
      if (!receivedDue(SteadyClock::now())) {
        throwIfFailed();
        return false;
      }
    } else {
      // Wakes for a delayed frame coming due, too.
      io_.run_one_until(nextDue(deadline));
    }
  }
  Received received = std::move(inbox_.front());
  inbox_.pop_front();
  handle(std::move(received.message), received.bytes);
  throwIfFailed();
  return true;
}

void Client::handle(v1::ServerMessage&& message, std::size_t frameBytes) {
  switch (message.message_case()) {
    case v1::ServerMessage::kWelcome:
      welcome_ = message.welcome();
      mirror_.setOrigin({welcome_.world_origin().x(), welcome_.world_origin().y()});
      return;
    case v1::ServerMessage::kSnapshot: {
      std::string error;
      if (!mirror_.apply(message.snapshot(), &error)) {
        failure_ = "malformed snapshot: " + error;
        return;
      }
      if (const std::uint32_t withheld = message.snapshot().states_withheld(); withheld > 0) {
        withheld_ = {withheld_.snapshots + 1, message.snapshot().tick(), withheld};
      }
      if (snapshotCallback_) snapshotCallback_(message.snapshot(), frameBytes);
      lastSnapshot_ = std::move(*message.mutable_snapshot());
      return;
    }
    case v1::ServerMessage::kEvents:
      if (eventsCallback_) eventsCallback_(message.events());
      if (events_.size() == kMaxKeptEvents) events_.pop_front();
      events_.push_back(std::move(*message.mutable_events()));
      return;
    case v1::ServerMessage::kError:
      failure_ = "server error: " + message.error().message();
      return;
    default:
      remember(message);
      replies_[replyId(message)] = std::move(message);
      return;
  }
}

void Client::remember(const v1::ServerMessage& reply) {
  if (!reply.has_command_result()) return;
  const v1::CommandResult& result = reply.command_result();
  if (result.body_id() == 0 && result.joint_id() == 0) return;
  created_[result.request_id()] = Created{result.body_id(), result.joint_id()};
  if (created_.size() > kKeptCreations) created_.erase(created_.begin());
}

std::optional<Client::Created> Client::created(std::uint64_t requestId) const {
  const auto it = created_.find(requestId);
  return it == created_.end() ? std::nullopt : std::optional(it->second);
}

std::optional<v1::ServerMessage> Client::awaitReply(std::uint64_t requestId, Duration timeout) {
  const auto deadline = SteadyClock::now() + timeout;
  while (true) {
    if (const auto it = replies_.find(requestId); it != replies_.end()) {
      auto reply = std::move(it->second);
      replies_.erase(it);
      return reply;
    }
    if (!receiveOne(deadline)) return std::nullopt;
  }
}

v1::ServerMessage Client::request(v1::ClientMessage message, Duration timeout) {
  const auto id = send(std::move(message));
  auto reply = awaitReply(id, timeout);
  if (!reply) {
    throw ConnectionError("no reply to request " + std::to_string(id) + " within " +
                          std::to_string(timeout.count()) + " ms");
  }
  return std::move(*reply);
}

std::optional<v1::Snapshot> Client::awaitSnapshot(Duration timeout) {
  const auto deadline = SteadyClock::now() + timeout;
  const auto target = mirror_.snapshotsApplied() + 1;
  while (mirror_.snapshotsApplied() < target) {
    if (!receiveOne(deadline)) return std::nullopt;
  }
  return lastSnapshot_;
}

std::size_t Client::poll(Duration timeout) {
  const auto deadline = SteadyClock::now() + timeout;
  std::size_t handled = 0;
  while (receiveOne(deadline)) ++handled;
  return handled;
}

std::vector<v1::Events> Client::takeEvents() {
  std::vector<v1::Events> taken(std::make_move_iterator(events_.begin()), std::make_move_iterator(events_.end()));
  events_.clear();
  return taken;
}

v1::Pong Client::ping(Duration timeout, bool wantStateHash) {
  const auto now = std::chrono::duration_cast<std::chrono::microseconds>(
      std::chrono::system_clock::now().time_since_epoch());
  auto reply = request(client::ping(std::uint64_t(now.count()), wantStateHash), timeout);
  if (!reply.has_pong()) throw ConnectionError("Ping was not answered by a Pong");
  return reply.pong();
}

}  // namespace impulse::client
