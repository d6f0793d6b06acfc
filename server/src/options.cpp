#include "impulse/server/options.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <vector>

#include "impulse/scenes/presets.h"
#include "impulse/server/access.h"
#include "impulse/wire/parse_number.h"

namespace impulse::server {

namespace {

struct Flag {
  std::string_view name;
  bool takesValue;
  std::string_view help;
  // Applies the value (the flag's own name is passed for messages); returns
  // an error message or "".
  std::function<std::string(ServerOptions&, std::string_view name, std::string_view value)> apply;
};

// Parses an integer in [min, max] into `out`, whatever its integer type.
template <class Int>
std::string intFlag(std::string_view name, std::string_view text, long long min, long long max,
                    Int& out) {
  const auto value = wire::parseNumber<long long>(text);
  if (!value || *value < min || *value > max) {
    return std::string(name) + " expects an integer in " + std::to_string(min) + ".." +
           std::to_string(max) + ", got '" + std::string(text) + "'";
  }
  out = static_cast<Int>(*value);
  return {};
}

std::string realFlag(std::string_view name, std::string_view text, double min, double max,
                     double& out) {
  const auto value = wire::parseNumber<double>(text);
  if (!value || !std::isfinite(*value) || *value < min || *value > max) {
    return std::string(name) + " expects a number in " + std::to_string(min) + ".." +
           std::to_string(max) + ", got '" + std::string(text) + "'";
  }
  out = *value;
  return {};
}

std::string secretFlag(std::string_view name, std::string_view text, std::string& out) {
  if (text.empty()) return std::string(name) + " expects a non-empty token";
  out = std::string(text);
  return {};
}

// Empty when the access settings are consistent (docs/protocol.md, Access).
std::string checkAccess(const ServerOptions& options) {
  if (!isLoopbackAddress(options.bind) && options.token.empty()) {
    return "refusing to bind " + options.bind +
           " without a token: give --token (or IMPULSE_TOKEN), or bind 127.0.0.1";
  }
  return {};
}

const std::vector<Flag>& flags() {
  static const std::vector<Flag> table = {
      {"--bind", true, "ADDR  address to listen on (default 127.0.0.1; 0.0.0.0 for all)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         if (v.empty()) return std::string(f) + " expects an address";
         o.bind = std::string(v);
         return std::string();
       }},
      {"--port", true, "N  TCP port (default 7777; 0 picks a free port)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 0, 65535, o.port);
       }},
      {"--tick-hz", true, "HZ  simulation ticks per second (default 60)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return realFlag(f, v, 1, 1000, o.tickHz);
       }},
      {"--snapshot-hz", true,
       "HZ  snapshots per second while running (default 30, at most tick-hz)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return realFlag(f, v, 0.1, 1000, o.snapshotHz);
       }},
      {"--substeps", true, "N  solver sub-steps per tick (default 4)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 64, o.subSteps);
       }},
      {"--preset", true, "N  scene loaded at start, 0-17 (default 0, the sandbox)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 0, kPresetCount - 1, o.preset);
       }},
      {"--paused", false, "start paused (advance with Step)",
       [](ServerOptions& o, std::string_view, std::string_view) {
         o.paused = true;
         return std::string();
       }},
      {"--max-clients", true, "N  simultaneous connections (default 64)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 10000, o.maxClients);
       }},
      {"--max-bodies", true, "N  bodies each room's world may hold (default 10000)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 200000, o.maxBodies);
       }},
      {"--max-input-delay", true,
       "N  ticks a command's for_tick may be ahead of (or behind) the room's tick (default 30)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 0, kMaxInputDelayTicks, o.maxInputDelayTicks);
       }},
      {"--max-total-bodies", true, "N  bodies all rooms together may hold (default 40000)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 10000000, o.maxTotalBodies);
       }},
      {"--max-fields", true, "N  force fields each room may hold (default 64)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 0, 10000, o.maxFields);
       }},
      {"--max-field-cost", true,
       "N  body interactions per step a room's fields may cost: gravitation n(n-1)/2, "
       "others n (default 1000000)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 0, 1'000'000'000'000LL, o.maxFieldCost);
       }},
      {"--max-frame-bytes", true, "N  largest accepted message (default 1048576)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 64, 64 << 20, o.maxFrameBytes);
       }},
      {"--idle-timeout", true,
       "SECONDS  drop a client that sends nothing for this long, unless snapshots flow to it "
       "(default 30)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return realFlag(f, v, 0.1, 86400, o.idleTimeoutSeconds);
       }},
      {"--max-clients-per-address", true, "N  simultaneous connections from one address (default 16)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 10000, o.maxClientsPerAddress);
       }},
      {"--max-commands-per-second", true,
       "N  commands per second per client, after a burst of 2 s worth (default 2000)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 1000000, o.maxCommandsPerSecond);
       }},
      {"--token", true, "T  clients must send Hello.token = T (or the admin token); env IMPULSE_TOKEN",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return secretFlag(f, v, o.token);
       }},
      {"--admin-token", true,
       "A  Hello.token = A gives the admin role, other clients are players; env IMPULSE_ADMIN_TOKEN",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return secretFlag(f, v, o.adminToken);
       }},
      {"--stall-timeout", true,
       "SECONDS  drop a client that accepts no data (or sends no Hello) for this long "
       "(default 10)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return realFlag(f, v, 0.1, 3600, o.stallTimeoutSeconds);
       }},
      {"--max-rooms", true, "N  rooms at once, 1-1000; a Hello naming a new room past it is refused (default 16)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 1000, o.maxRooms);
       }},
      {"--max-rooms-per-address", true,
       "N  rooms one address may have made and still hold, 1-1000 (default 4)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 1000, o.maxRoomsPerAddress);
       }},
      {"--health-port", true,
       "N  answer HTTP GET /healthz and /readyz on this port (0 picks a free one; default none)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         std::uint16_t port = 0;
         std::string error = intFlag(f, v, 0, 65535, port);
         if (error.empty()) o.healthPort = port;
         return error;
       }},
      {"--room-stall-seconds", true,
       "SECONDS  /healthz answers 503 once a room finished no tick for this long (default 10)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return realFlag(f, v, 0.01, 3600, o.roomStallSeconds);
       }},
      {"--room-threads", true, "N  threads stepping the rooms, 1-64 (default 2)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         return intFlag(f, v, 1, 64, o.roomThreads);
       }},
      {"--room-workers", true,
       "N  of those, the most one room's step works on at once, 1 to --room-threads "
       "(default --room-threads)",
       [](ServerOptions& o, std::string_view f, std::string_view v) {
         int workers = 0;
         std::string error = intFlag(f, v, 1, 64, workers);
         if (error.empty()) o.roomWorkers = workers;
         return error;
       }},
  };
  return table;
}

}  // namespace

ParsedOptions parseOptions(std::span<const std::string_view> args, const ServerOptions& defaults) {
  ServerOptions options = defaults;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string_view arg = args[i];
    if (arg == "--help" || arg == "-h") return {std::nullopt, true, {}};
    std::optional<std::string_view> inlineValue;
    if (const auto eq = arg.find('='); eq != std::string_view::npos) {
      inlineValue = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
    }
    const Flag* flag = nullptr;
    for (const auto& candidate : flags()) {
      if (candidate.name == arg) flag = &candidate;
    }
    if (flag == nullptr) {
      return {std::nullopt, false, "unknown option '" + std::string(args[i]) + "' (see --help)"};
    }
    std::string_view value;
    if (flag->takesValue) {
      if (inlineValue) {
        value = *inlineValue;
      } else if (i + 1 < args.size()) {
        value = args[++i];
      } else {
        return {std::nullopt, false, std::string(arg) + " needs a value"};
      }
    } else if (inlineValue) {
      return {std::nullopt, false, std::string(arg) + " takes no value"};
    }
    if (auto error = flag->apply(options, flag->name, value); !error.empty()) {
      return {std::nullopt, false, error};
    }
  }
  if (options.snapshotHz > options.tickHz) {
    return {std::nullopt, false, "--snapshot-hz may not exceed --tick-hz"};
  }
  if (options.roomWorkers && *options.roomWorkers > options.roomThreads) {
    return {std::nullopt, false,
            "--room-workers " + std::to_string(*options.roomWorkers) + " exceeds --room-threads " +
                std::to_string(options.roomThreads) + ": a room works on the stepping threads only"};
  }
  if (std::string error = checkAccess(options); !error.empty()) return {std::nullopt, false, error};
  return {options, false, {}};
}

int workersPerRoom(const ServerOptions& options) { return options.roomWorkers.value_or(options.roomThreads); }

ServerOptions optionsFromEnvironment() {
  ServerOptions options;
  if (const char* token = std::getenv("IMPULSE_TOKEN")) options.token = token;
  if (const char* admin = std::getenv("IMPULSE_ADMIN_TOKEN")) options.adminToken = admin;
  return options;
}

std::string usage() {
  std::string text =
      "usage: impulse-server [options]\n"
      "Serves one Impulse world over TCP (protocol: docs/server.md).\n"
      "The first line on stdout is 'listening on ADDR:PORT'; logs go to stderr.\n\n";
  for (const auto& flag : flags()) {
    text += "  ";
    text += flag.name;
    text += ' ';
    text += flag.help;
    text += '\n';
  }
  text += "  --help  this text\n";
  return text;
}

}  // namespace impulse::server
