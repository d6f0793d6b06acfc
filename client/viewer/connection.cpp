#include "connection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "impulse/client/commands.h"
#include "impulse/client/number_format.h"
#include "impulse/wire/wire_positions.h"

namespace impulse::viewer {

namespace {

// Often enough for the live step-time plot.
constexpr double kPingInterval = 0.25;
constexpr double kMaxBackoff = 2.0;
// Connecting gives up after this; a dead host must not delay the retry loop.
constexpr std::chrono::milliseconds kConnectTimeout{3000};

}  // namespace

Connection::Connection(client::ConnectOptions options, InterpolatedWorld& world,
                       std::function<double()> now, bool predict)
    : options_(std::move(options)), world_(world), now_(std::move(now)), predicting_(predict) {
  options_.wantSnapshots = true;
  options_.timeout = std::min(options_.timeout, kConnectTimeout);
  startConnecting();
}

// The pending future's destructor waits for a connection attempt in flight
// (bounded by kConnectTimeout).
Connection::~Connection() = default;

void Connection::startConnecting() {
  state_ = LinkState::Connecting;
  pending_ = std::async(std::launch::async, [options = options_] {
    return std::make_unique<client::Client>(options);
  });
}

std::string Connection::describe() const {
  const std::string target = options_.host + ":" + std::to_string(options_.port);
  const std::string retry = client::formatNumber(retryIn(), 1) + " s";
  switch (state_) {
    case LinkState::Connected: return "connected to " + target;
    case LinkState::Connecting:
      return (connections_ == 0 ? "connecting to " : "reconnecting to ") + target + "...";
    case LinkState::Lost: break;
  }
  if (connections_ == 0) {
    return "cannot connect to " + target + " (" + lostReason_ + "), retrying in " + retry;
  }
  return "connection to " + target + " lost (" + lostReason_ + "), reconnecting in " + retry;
}

std::optional<v1::ServerStats> Connection::takeStats() { return std::exchange(stats_, {}); }

double Connection::retryIn() const { return std::max(0.0, retryAt_ - now_()); }

void Connection::adopt(std::unique_ptr<client::Client> client) {
  predictor_.reset();
  client_ = std::move(client);
  state_ = LinkState::Connected;
  backoff_ = 0.25;
  ++connections_;
  const double hz = client_->welcome().snapshot_hz();
  world_.reset(hz > 0 ? 1.0 / hz : 1.0 / 30.0);
  world_.seed(client_->mirror(), now_());
  client_->onSnapshot([this](const v1::Snapshot& snapshot, std::size_t) {
    world_.onSnapshot(client_->mirror(), snapshot, now_());
    ++rateCount_;
  });
  nextPing_ = now_();
  rateWindowStart_ = now_();
  rateCount_ = 0;
}

void Connection::lose(const std::string& reason) {
  std::fprintf(stderr, "impulse-viewer: %s\n", reason.c_str());
  predictor_.reset();
  client_.reset();
  awaiting_.clear();
  pingId_.reset();
  roundTripMs_ = -1;
  snapshotRate_ = 0;
  // The client's messages name the address ("cannot connect to H:P: reason");
  // the line shown names it already, so only the reason after it is kept.
  const auto colon = reason.rfind(": ");
  lostReason_ = colon == std::string::npos ? reason : reason.substr(colon + 2);
  state_ = LinkState::Lost;
  retryAt_ = now_() + backoff_;
  backoff_ = std::min(kMaxBackoff, backoff_ * 2);
}

void Connection::update() {
  if (state_ == LinkState::Connecting) {
    if (pending_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    try {
      adopt(pending_.get());
    } catch (const std::exception& error) {
      lose(error.what());
    }
  }
  if (state_ == LinkState::Lost) {
    if (now_() >= retryAt_) startConnecting();
    return;
  }
  try {
    receive();
    pingIfDue();
  } catch (const client::ConnectionError& error) {
    lose(error.what());
  }
}

void Connection::receive() {
  client_->poll();
  for (auto it = awaiting_.begin(); it != awaiting_.end();) {
    auto reply = client_->awaitReply(it->first, std::chrono::milliseconds(0));
    if (!reply) {
      ++it;
      continue;
    }
    // The viewer works in its mirror's frame, around the room's origin.
    wire::shiftPositions(*reply, -client_->mirror().origin());
    replies_.push_back({std::move(it->second), std::move(*reply)});
    it = awaiting_.erase(it);
  }
  if (pingId_) {
    if (auto pong = client_->awaitReply(*pingId_, std::chrono::milliseconds(0))) {
      roundTripMs_ = (now_() - pingSentAt_) * 1000;
      if (pong->has_pong() && pong->pong().has_stats()) stats_ = pong->pong().stats();
      pingId_.reset();
    }
  }
  const double now = now_();
  if (now - rateWindowStart_ >= 1.0) {
    snapshotRate_ = rateCount_ / (now - rateWindowStart_);
    rateCount_ = 0;
    rateWindowStart_ = now;
  }
}

void Connection::pingIfDue() {
  const double now = now_();
  if (pingId_ || now < nextPing_) return;
  pingSentAt_ = now;
  pingId_ = client_->send(client::ping(std::uint64_t(now * 1e6)));
  nextPing_ = now + kPingInterval;
}

void Connection::setPredicting(bool wanted) {
  predicting_ = wanted;
  if (!wanted) predictor_.reset();
}

std::optional<std::string> Connection::advancePrediction() {
  try {
    stepPrediction();
    return std::nullopt;
  } catch (const client::PredictionError& error) {
    return stopPrediction(error);
  } catch (const std::invalid_argument& error) {
    // The predictor refused to start from this stream (client::Predictor's constructor).
    return stopPrediction(error);
  }
}

std::string Connection::stopPrediction(const std::exception& why) {
  setPredicting(false);
  return std::string("Prediction off: ") + why.what();
}

void Connection::stepPrediction() {
  if (!predicting_ || !client_) return;
  const v1::Welcome& welcome = client_->welcome();
  if (!predictor_) {
    if (roundTripMs_ < 0) return;
    // The round trip in ticks, a tick for the snapshot interval and two for
    // jitter (docs/networked-play.md, "Prediction").
    const double roundTripTicks = std::ceil(roundTripMs_ / 1000 * welcome.tick_hz());
    const auto lead = std::uint32_t(std::clamp(roundTripTicks + 3, 1.0, double(welcome.max_input_delay_ticks())));
    predictor_ = std::make_unique<client::Predictor>(*client_, client::PredictionOptions{.leadTicks = lead});
    predictorStart_ = now_();
    predictorTicks_ = 0;
  }
  // The room's ticks run at tick_hz times its time scale; a long frame
  // (a dragged window) catches up at most a few ticks.
  constexpr std::uint64_t kMostTicksPerFrame = 8;
  const double rate = welcome.tick_hz() * client_->mirror().timeScale();
  const auto due = std::uint64_t(std::max(0.0, (now_() - predictorStart_) * rate));
  if (due > predictorTicks_ + kMostTicksPerFrame) predictorTicks_ = due - kMostTicksPerFrame;
  for (; predictorTicks_ < due; ++predictorTicks_) predictor_->advance();
}

bool Connection::send(v1::ClientMessage message, std::string what) {
  if (state_ != LinkState::Connected) return false;
  try {
    // From the viewer's frame (its mirror's) to the wire's, from (0, 0).
    wire::shiftPositions(message, client_->mirror().origin());
    const bool predicted = predictor_ && client::Predictor::predicts(message);
    const std::uint64_t id = predicted ? predictor_->send(std::move(message)) : client_->send(std::move(message));
    awaiting_.emplace(id, std::move(what));
    return true;
  } catch (const client::ConnectionError& error) {
    lose(error.what());
    return false;
  }
}

std::vector<Reply> Connection::takeReplies() { return std::exchange(replies_, {}); }

std::vector<v1::Events> Connection::takeEvents() {
  if (!connected()) return {};
  std::vector<v1::Events> events = client_->takeEvents();
  for (v1::Events& each : events) wire::shiftPositions(each, -client_->mirror().origin());
  return events;
}

double Connection::tickSeconds() const {
  const double hz = connected() ? client_->welcome().tick_hz() : 0;
  return hz > 0 ? 1 / hz : 0;
}

}  // namespace impulse::viewer
