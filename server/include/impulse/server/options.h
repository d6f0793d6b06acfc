#pragma once
/// Command-line options of impulse-server.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace impulse::server {

/// The largest --max-input-delay: ten seconds at the default 60 Hz.
inline constexpr int kMaxInputDelayTicks = 600;

struct ServerOptions {
  std::string bind = "127.0.0.1";
  /// 0 asks the system for a free port.
  std::uint16_t port = 7777;
  double tickHz = 60;
  double snapshotHz = 30;
  int subSteps = 4;
  int preset = 0;
  bool paused = false;
  int maxClients = 64;
  int maxBodies = 10000;
  /// How far ahead of (or behind) the room's tick a command's for_tick may
  /// be (docs/networked-play.md): half a second at the default 60 Hz.
  int maxInputDelayTicks = 30;
  /// Bodies all rooms together may hold (server_bodies.h).
  int maxTotalBodies = 40000;
  /// Force fields per room, and the body interactions per step they may
  /// cost together (field_budget.h).
  int maxFields = 64;
  std::uint64_t maxFieldCost = 1'000'000;
  std::size_t maxFrameBytes = std::size_t(1) << 20;
  /// A client with unsent data that accepts no byte for this long is
  /// disconnected; so is one that has not said Hello by then.
  double stallTimeoutSeconds = 10;
  /// A client past Hello that sends nothing for this long is disconnected,
  /// unless it subscribes and snapshots flow to it (its room runs).
  double idleTimeoutSeconds = 30;
  /// Simultaneous connections from one IP address.
  int maxClientsPerAddress = 16;
  /// Per-client command rate; a burst of two seconds' worth is allowed (a
  /// tool spawning a few thousand bodies at once). Past it a command is
  /// answered with an error at once and not applied.
  int maxCommandsPerSecond = 2000;
  /// Access (docs/protocol.md): required in Hello when set; required to bind
  /// anything but loopback.
  std::string token;
  /// Grants the admin role; without it every client is admin.
  std::string adminToken;
  /// Rooms (docs/protocol.md): at most this many at once; a Hello naming a new
  /// room past it is refused. --max-bodies is per room.
  int maxRooms = 16;
  /// Rooms one IP address may have made and still hold at once.
  int maxRoomsPerAddress = 4;
  /// Threads stepping the rooms (each room on one thread at a time).
  int roomThreads = 2;
  /// Of those, the most one room's step may work on (the engine's workers:
  /// the room's own thread and idle ones); unset: all of them.
  std::optional<int> roomWorkers;
  /// The HTTP health probes' port on the bind address (health_endpoint.h);
  /// none without --health-port, 0 picks a free one.
  std::optional<std::uint16_t> healthPort;
  /// /healthz fails once a room finished no tick for this long.
  double roomStallSeconds = 10;
};

/// Outcome of parsing: options, a request for help, or an error message.
struct ParsedOptions {
  std::optional<ServerOptions> options;
  bool help = false;
  std::string error;
};

/// Parses the arguments after the program name over `defaults`. Accepts
/// `--flag value` and `--flag=value`; every value is range-checked. A bind
/// address other than loopback without a token is refused.
ParsedOptions parseOptions(std::span<const std::string_view> args,
                           const ServerOptions& defaults = {});

/// Defaults taken from the environment: IMPULSE_TOKEN, IMPULSE_ADMIN_TOKEN.
ServerOptions optionsFromEnvironment();

/// Stepping threads one room's step may work on (--room-workers).
int workersPerRoom(const ServerOptions& options);

/// The --help text.
std::string usage();

}  // namespace impulse::server
