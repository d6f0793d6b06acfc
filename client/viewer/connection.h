#pragma once
/// The viewer's link to impulse-server: connects in the background (the
/// window keeps drawing), reconnects after a loss with a growing pause, feeds
/// every applied snapshot to the interpolated world, pings for latency and
/// hands command replies back. Never blocks the frame loop.
///
/// The viewer works in its mirror's frame: positions relative to the room's
/// origin (Welcome.world_origin), floats precise however far the room lies
/// from (0, 0). Its commands leave, and replies and events arrive, converted
/// here from and to the wire's positions from (0, 0).
///
/// While prediction is on (docs/networked-play.md), the commands a
/// client::Predictor predicts go through it, stamped, and the viewer shows
/// the bodies they act on from its copy of the world.

#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "impulse/client/client.h"
#include "impulse/client/predictor.h"
#include "interpolated_world.h"
#include "link_state.h"

namespace impulse::viewer {

/// A reply to a command the viewer sent, with what the command was.
struct Reply {
  std::string what;
  v1::ServerMessage message;
};

class Connection {
 public:
  /// `now` gives local seconds (the frame loop's clock).
  Connection(client::ConnectOptions options, InterpolatedWorld& world,
             std::function<double()> now, bool predict = false);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  /// Once per frame: progresses connecting, receives everything available.
  void update();
  /// Sends a command when connected; false (nothing sent) otherwise.
  bool send(v1::ClientMessage message, std::string what);
  /// Replies received since the last call.
  std::vector<Reply> takeReplies();
  /// The Events messages received since the last call (after
  /// SubscribeEvents), oldest first; none while not connected.
  std::vector<v1::Events> takeEvents();
  /// Simulated seconds per tick (the server's Welcome), 0 while not connected.
  double tickSeconds() const;

  LinkState state() const { return state_; }
  bool connected() const { return state_ == LinkState::Connected; }
  /// The connected client (its mirror holds the latest world), or null.
  const client::Client* client() const { return client_.get(); }
  /// The link in words: "connected to HOST:PORT", "cannot connect to
  /// HOST:PORT (reason), retrying in 1 s" for a server never reached,
  /// "connection to HOST:PORT lost (reason), reconnecting in 1 s".
  std::string describe() const;
  double retryIn() const;
  /// The server's figures from a Pong that arrived since the last call.
  std::optional<v1::ServerStats> takeStats();
  double roundTripMs() const { return roundTripMs_; }
  double snapshotsPerSecond() const { return snapshotRate_; }
  /// Connections made so far (reconnects included).
  int connections() const { return connections_; }

  /// Prediction wanted: the predictor starts once the first round trip is
  /// measured (its lead covers it); off drops it.
  void setPredicting(bool wanted);
  bool predicting() const { return predicting_; }
  /// Once per frame, after the frame's commands were sent (so they show in
  /// it): starts the predictor when wanted and possible, then steps it by
  /// the room's ticks since the last frame. When the snapshots cannot keep
  /// a copy true (client::PredictionError, or a stream that already
  /// withholds states), prediction turns itself off and the viewer goes on
  /// from its interpolated picture: returns the message saying why, once.
  std::optional<std::string> advancePrediction();
  /// The running predictor, or null (off, not connected, no round trip yet).
  const client::Predictor* predictor() const { return predictor_.get(); }

 private:
  /// advancePrediction's work; throws what the predictor throws.
  void stepPrediction();
  /// Turns prediction off for `why`; the message saying so.
  std::string stopPrediction(const std::exception& why);
  void startConnecting();
  void adopt(std::unique_ptr<client::Client> client);
  void lose(const std::string& reason);
  void receive();
  void pingIfDue();

  client::ConnectOptions options_;
  InterpolatedWorld& world_;
  std::function<double()> now_;

  LinkState state_ = LinkState::Connecting;
  std::future<std::unique_ptr<client::Client>> pending_;
  std::unique_ptr<client::Client> client_;
  std::string lostReason_;
  double retryAt_ = 0;
  double backoff_ = 0.25;
  int connections_ = 0;

  std::map<std::uint64_t, std::string> awaiting_;
  std::vector<Reply> replies_;
  std::optional<std::uint64_t> pingId_;
  double pingSentAt_ = 0;
  double nextPing_ = 0;
  double roundTripMs_ = -1;
  double rateWindowStart_ = 0;
  int rateCount_ = 0;
  double snapshotRate_ = 0;
  std::optional<v1::ServerStats> stats_;

  bool predicting_ = false;
  std::unique_ptr<client::Predictor> predictor_;
  /// Local time the predictor's ticks are counted from, and how many it ran.
  double predictorStart_ = 0;
  std::uint64_t predictorTicks_ = 0;
};

}  // namespace impulse::viewer
