#include "impulse/server/server.h"

#include <malloc.h>

#include <algorithm>
#include <vector>

#include "impulse/server/log.h"
#include "impulse/server/room_bounds.h"
#include "impulse/server/room_name.h"

namespace impulse::server {

namespace {

constexpr auto kHousekeepingInterval = std::chrono::milliseconds(100);
constexpr auto kAcceptRetryDelay = std::chrono::milliseconds(100);
// malloc_trim walks the heap: at most this often, and only after closes.
constexpr auto kTrimInterval = std::chrono::seconds(2);

SessionLimits sessionLimits(const ServerOptions& options) {
  SessionLimits limits;
  limits.maxFrameBytes = options.maxFrameBytes;
  limits.maxPendingCommandBytes = std::max<std::size_t>(options.maxFrameBytes, 256 * 1024);
  limits.stallTimeout = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(options.stallTimeoutSeconds));
  limits.idleTimeout = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(options.idleTimeoutSeconds));
  limits.commandsPerSecond = options.maxCommandsPerSecond;
  return limits;
}

}  // namespace

Server::Server(asio::io_context& io, asio::thread_pool& steppers, const ServerOptions& options)
    : io_(io),
      options_(options),
      acceptor_(io),
      housekeepingTimer_(io),
      sessionLimits_(sessionLimits(options)),
      tokens_{options.token, options.adminToken},
      steppers_(steppers),
      engineWorkers_(steppers, workersPerRoom(options)),
      serverBodies_(std::make_shared<ServerBodies>(options.maxTotalBodies)) {
  const std::string defaultRoom(kDefaultRoom);
  rooms_[defaultRoom] = std::make_shared<Room>(defaultRoom, io, steppers_, engineWorkers_.taskSettings(), options_,
                                                *this, RoomBounds::defaults());
  const asio::ip::tcp::endpoint endpoint(asio::ip::make_address(options.bind), options.port);
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(asio::ip::tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
  if (options.healthPort) {
    health_ = std::make_unique<HealthEndpoint>(
        io, asio::ip::tcp::endpoint(endpoint.address(), *options.healthPort),
        [this] { return liveness(); }, [this] { return readiness(); });
  }
}

void Server::start() {
  lastTrim_ = Clock::now();
  logLine("serving preset " + std::to_string(options_.preset) + " at " +
          std::to_string(options_.tickHz) + " Hz" + (options_.paused ? ", paused" : "") +
          " in every room; rooms stepped on " + std::to_string(options_.roomThreads) +
          " thread(s)");
  accept();
  if (health_) {
    health_->start();
    const auto probes = health_->endpoint();
    logLine("health probes on port " + std::to_string(probes.port()) + " (GET /healthz, /readyz)");
  }
  for (const auto& [name, room] : rooms_) room->start();
  scheduleHousekeeping();
}

void Server::stop() {
  if (stopped_) return;
  stopped_ = true;
  logLine("shutting down");
  asio::error_code ignored;
  acceptor_.close(ignored);
  housekeepingTimer_.cancel();
  if (health_) health_->stop();
  for (const auto& [name, room] : rooms_) room->stop();
  std::vector<std::shared_ptr<Session>> sessions;
  for (const auto& [id, session] : sessions_) sessions.push_back(session);
  for (const auto& session : sessions) session->close("server shutting down");
}

// -------------------------------------------------------------------- rooms

std::variant<std::shared_ptr<Room>, std::string> Server::roomFor(const v1::Hello& hello,
                                                                 const std::string& address, bool admin) {
  if (std::string refusal = roomNameRefusal(hello.room()); !refusal.empty()) return refusal;
  const std::string name = roomNameOf(hello.room());
  RoomBoundsRequest bounds = roomBoundsFromHello(hello);
  if (!bounds.error.empty()) return std::move(bounds.error);
  if (bounds.bounds && !admin) {
    return "hello.room_min and room_max: only the admin role may give a room's bounds (leave them out to join "
           "with the server's)";
  }
  if (const auto it = rooms_.find(name); it != rooms_.end()) {
    const RoomBounds& held = it->second->bounds();
    if (bounds.bounds && *bounds.bounds != held) {
      return "room " + name + " exists with bounds " + describeBounds(held) +
             ": hello.room_min and room_max may only make a room (leave them out to join it)";
    }
    return it->second;
  }
  if (rooms_.size() >= std::size_t(options_.maxRooms)) {
    return "room limit reached: this server holds at most " + std::to_string(options_.maxRooms) +
           " rooms (--max-rooms); join an existing one (ListRooms) or another server";
  }
  const auto made =
      std::ranges::count_if(roomMaker_, [&](const auto& entry) { return entry.second == address; });
  if (made >= options_.maxRoomsPerAddress) {
    return "room limit for " + address + " reached: it made " + std::to_string(made) +
           " rooms that are still open (at most " + std::to_string(options_.maxRoomsPerAddress) +
           " per address, --max-rooms-per-address); join an existing one (ListRooms)";
  }
  auto room =
      std::make_shared<Room>(name, io_, steppers_, engineWorkers_.taskSettings(), options_, *this,
                             bounds.bounds.value_or(RoomBounds::defaults()));
  rooms_[name] = room;
  roomMaker_[name] = address;
  room->start();
  logLine("room " + name + " made (" + std::to_string(rooms_.size()) + " rooms)");
  return room;
}

std::shared_ptr<Room> Server::roomOf(const Session& session) const {
  const auto it = roomOfClient_.find(session.id());
  return it == roomOfClient_.end() ? nullptr : it->second;
}

ProbeStatus Server::liveness() const {
  const auto now = Clock::now();
  const auto stallAfter = std::chrono::duration<double>(options_.roomStallSeconds);
  for (const auto& [name, room] : rooms_) {
    const std::chrono::duration<double> since = room->sinceLastTick(now);
    if (since > stallAfter) {
      return {false, "stalled: room " + name + " finished no tick for " +
                         std::to_string(since.count()) + " s (--room-stall-seconds " +
                         std::to_string(options_.roomStallSeconds) + ")"};
    }
  }
  return {true, "ok"};
}

ProbeStatus Server::readiness() const {
  const std::string rooms = std::to_string(rooms_.size()) + " of " +
                            std::to_string(options_.maxRooms) + " rooms";
  if (stopped_) return {false, "stopping"};
  if (rooms_.size() >= std::size_t(options_.maxRooms)) return {false, "full: " + rooms};
  const auto overrunning = std::ranges::count_if(
      rooms_, [](const auto& entry) { return entry.second->overrunning(); });
  if (overrunning >= 2 * options_.roomThreads) {
    return {false, "busy: " + std::to_string(overrunning) +
                       " rooms overrunning their tick budget take the " +
                       std::to_string(options_.roomThreads) + " stepping thread(s); " + rooms};
  }
  if (overrunning > 0) {
    return {true, "ready: " + rooms + ", " + std::to_string(overrunning) + " overrunning"};
  }
  return {true, "ready: " + rooms};
}

void Server::listRooms(v1::RoomList& list) const {
  for (const auto& [name, room] : rooms_) *list.add_rooms() = room->info();
}

// ------------------------------------------------------------------ clients

void Server::accept() {
  acceptor_.async_accept([this](const asio::error_code& ec, asio::ip::tcp::socket socket) {
    if (stopped_) return;
    if (ec) {
      // Out of descriptors and the like: retry soon instead of spinning.
      logLine("accept failed: " + ec.message());
      auto retry = std::make_shared<asio::steady_timer>(io_, kAcceptRetryDelay);
      retry->async_wait([this, retry](const asio::error_code&) {
        if (!stopped_) accept();
      });
      return;
    }
    const std::uint32_t id = nextClientId_++;
    auto session = std::make_shared<Session>(std::move(socket), *this, id, sessionLimits_);
    const std::string refusal = admissionRefusal(*session);
    sessions_[id] = session;
    if (!refusal.empty()) {
      session->reject(refusal);
    } else {
      session->start();
    }
    accept();
  });
}

std::string Server::admissionRefusal(const Session& newcomer) {
  const auto now = Clock::now();
  std::size_t active = 0;
  std::size_t fromAddress = 0;
  Session* idlest = nullptr;
  Session* idlestFromAddress = nullptr;
  auto idler = [](Session* a, Session& b) {
    return a == nullptr || b.lastActive() < a->lastActive() ? &b : a;
  };
  for (const auto& [id, other] : sessions_) {
    if (!other->acceptingTraffic()) continue;
    ++active;
    const bool sameAddress = other->address() == newcomer.address();
    fromAddress += sameAddress ? 1 : 0;
    if (!other->evictable(now)) continue;
    idlest = idler(idlest, *other);
    if (sameAddress) idlestFromAddress = idler(idlestFromAddress, *other);
  }
  // A full server (or address) makes room by closing its idlest silent
  // connection, so clients that say nothing cannot keep anyone out.
  Session* victim = nullptr;
  if (fromAddress >= std::size_t(options_.maxClientsPerAddress)) {
    if (idlestFromAddress == nullptr) {
      return "too many connections from " + newcomer.address() + " (at most " +
             std::to_string(options_.maxClientsPerAddress) + " per address)";
    }
    victim = idlestFromAddress;
  } else if (active >= std::size_t(options_.maxClients)) {
    if (idlest == nullptr) {
      return "server is full (" + std::to_string(options_.maxClients) + " clients)";
    }
    victim = idlest;
  }
  if (victim != nullptr) victim->evict(now);
  return {};
}

void Server::onHello(const std::shared_ptr<Session>& session, const v1::Hello& hello) {
  const Admission admission = admit(tokens_, hello.token());
  if (!admission.error.empty()) return session->reject(admission.error);
  auto room = roomFor(hello, session->address(), admission.admin);
  if (const auto* refusal = std::get_if<std::string>(&room)) return session->reject(*refusal);
  session->setAdmin(admission.admin);
  const auto& joined = std::get<std::shared_ptr<Room>>(room);
  session->setRoom(joined->name());
  session->log(std::string("said hello") + (hello.want_snapshots() ? " (subscribed)" : ""));
  roomOfClient_[session->id()] = joined;
  joined->join(session, hello.want_snapshots());
}

void Server::onCommand(const std::shared_ptr<Session>& session, v1::ClientMessage&& message,
                       std::size_t bytes) {
  // Sessions pass commands on only after their Hello was accepted.
  if (const auto room = roomOf(*session)) room->enqueue(*session, std::move(message), bytes);
}

void Server::onClosed(Session& session) {
  if (const auto room = roomOf(session)) {
    room->leave(session);
    roomOfClient_.erase(session.id());
    if (room->empty() && room->name() != kDefaultRoom && !stopped_) {
      room->stop();
      rooms_.erase(room->name());
      roomMaker_.erase(room->name());
      logLine("room " + room->name() + " dropped: its last client left");
    }
  }
  ++closedSinceTrim_;
  sessions_.erase(session.id());
}

// -------------------------------------------------------------- housekeeping

void Server::scheduleHousekeeping() {
  housekeepingTimer_.expires_after(kHousekeepingInterval);
  housekeepingTimer_.async_wait([this](const asio::error_code& ec) {
    if (ec || stopped_) return;
    housekeeping();
    scheduleHousekeeping();
  });
}

void Server::housekeeping() {
  const auto now = Clock::now();
  releaseMemory(now);
  std::vector<std::shared_ptr<Session>> sessions;
  for (const auto& [id, session] : sessions_) sessions.push_back(session);
  for (const auto& session : sessions) session->checkTimeouts(now);
}

void Server::releaseMemory(Clock::time_point now) {
  if (closedSinceTrim_ == 0 || now - lastTrim_ < kTrimInterval) return;
  closedSinceTrim_ = 0;
  lastTrim_ = now;
  malloc_trim(0);
}

}  // namespace impulse::server
