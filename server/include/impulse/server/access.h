#pragma once
/// Access (docs/protocol.md): tokens at Hello, the admin and player roles, and
/// which bodies a player created.
///
/// Without tokens every client is admin (the loopback default). With an admin
/// token configured, clients that did not present it are players: they may
/// spawn, push and remove only the bodies they created, join them with
/// joints (and change or remove only the joints they created), query and ping;
/// world-wide commands (clear, presets, scenes, pause, step, gravity, fields)
/// are refused.

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>

#include "impulse.pb.h"
#include "impulse/server/commands.h"
#include "impulse/server/simulation.h"
#include "impulse/world.h"

namespace impulse::server {

struct AccessTokens {
  /// Required in every Hello when not empty.
  std::string token;
  /// Grants the admin role when not empty; without it every client is admin.
  std::string adminToken;
};

/// A Hello's outcome: an error to close the connection with, or the role.
struct Admission {
  std::string error;
  bool admin = false;
};

Admission admit(const AccessTokens& tokens, std::string_view offered);

/// True for an address the loopback default may bind ("127.x", "::1", "localhost").
bool isLoopbackAddress(std::string_view address);

/// Bodies and joints created by player clients, by id. What a player may do
/// follows from the command's row of the command table (its role column):
/// Admin commands are refused, Owner commands only on what the player
/// created, Anyone commands allowed; a command without a row never gets here.
class Ownership {
 public:
  /// Why a player may not run this command (empty when it may).
  std::string playerRefusal(const CommandRow& row, const v1::ClientMessage& message,
                            std::uint32_t client) const;
  /// After a command was applied: remembers what a client created and
  /// forgets what left the world; forgets everything once the world was
  /// replaced (its ids start over). Bounded by the world's body limit.
  void recordOutcome(const CommandRow& row, const v1::ClientMessage& message,
                     const v1::ServerMessage& reply, std::uint32_t client, const Simulation& simulation);

 private:
  /// Forgets bodies and joints the world no longer has (they also leave by
  /// falling out of the world, or with their bodies), once the maps could
  /// outgrow the body limit.
  void sweep(const World& world);

  std::unordered_map<std::uint32_t, std::uint32_t> ownerOf_;
  std::unordered_map<std::uint32_t, std::uint32_t> jointOwnerOf_;
  /// The world the owners were recorded in (Simulation::worldGeneration).
  std::uint64_t worldGeneration_ = 0;
};

}  // namespace impulse::server
