#include "impulse/server/access.h"

#include <algorithm>

namespace impulse::server {

namespace {

// Compares without returning early, so the time taken does not tell an
// attacker how many leading characters of a guess were right.
bool sameSecret(std::string_view a, std::string_view b) {
  unsigned char difference = a.size() == b.size() ? 0 : 1;
  const std::size_t n = std::max(a.size(), b.size());
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char x = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
    const unsigned char y = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
    difference |= static_cast<unsigned char>(x ^ y);
  }
  return difference == 0;
}

std::string notCreatedBy(std::string_view command, const char* kind, std::uint32_t id) {
  return std::string(command) + ": refused for the player role: " + kind + " " +
         std::to_string(id) + " was not created by this client (players act on their own " + kind +
         "s only)";
}

bool ownedBy(const std::unordered_map<std::uint32_t, std::uint32_t>& owners, std::uint32_t id,
             std::uint32_t client) {
  const auto it = owners.find(id);
  return it != owners.end() && it->second == client;
}

}  // namespace

Admission admit(const AccessTokens& tokens, std::string_view offered) {
  const bool isAdmin = !tokens.adminToken.empty() && sameSecret(offered, tokens.adminToken);
  if (!tokens.token.empty() && !isAdmin && !sameSecret(offered, tokens.token)) {
    return {offered.empty() ? "this server requires a token (Hello.token)"
                            : "Hello.token is not valid for this server",
            false};
  }
  return {{}, tokens.adminToken.empty() || isAdmin};
}

bool isLoopbackAddress(std::string_view address) {
  return address == "localhost" || address == "::1" || address.starts_with("127.");
}

std::string Ownership::playerRefusal(const CommandRow& row, const v1::ClientMessage& message,
                                     std::uint32_t client) const {
  const std::string_view command = row.name;
  switch (row.role) {
    case CommandRole::Anyone:
      return {};
    case CommandRole::Admin:
      return std::string(command) +
             ": refused for the player role (it changes everyone's world: the admin role, "
             "Hello.token = the admin token, is needed)";
    case CommandRole::Owner:
      break;
  }
  // Body 0 (the world, which a player may pin its own bodies to) is not a target.
  const CommandTargets targets = row.targets(message);
  for (const std::uint32_t body : targets.bodies) {
    if (!ownedBy(ownerOf_, body, client)) return notCreatedBy(command, "body", body);
  }
  for (const std::uint32_t joint : targets.joints) {
    if (!ownedBy(jointOwnerOf_, joint, client)) return notCreatedBy(command, "joint", joint);
  }
  return {};
}

void Ownership::recordOutcome(const CommandRow& row, const v1::ClientMessage& message,
                              const v1::ServerMessage& reply, std::uint32_t client,
                              const Simulation& simulation) {
  if (simulation.worldGeneration() != worldGeneration_) {
    worldGeneration_ = simulation.worldGeneration();
    ownerOf_.clear();
    jointOwnerOf_.clear();
  }
  if (!reply.has_command_result() || !reply.command_result().ok()) return;
  const World& world = simulation.world();
  // What a command creates is named in its result.
  const auto& result = reply.command_result();
  if (result.body_id() != 0) ownerOf_[result.body_id()] = client;
  if (result.joint_id() != 0) jointOwnerOf_[result.joint_id()] = client;
  // What it removed is forgotten now: a freed id may come back once its generation wraps.
  if (row.role == CommandRole::Owner) {
    const CommandTargets targets = row.targets(message);
    for (const std::uint32_t body : targets.bodies) {
      if (!world.isValid(BodyId{body})) ownerOf_.erase(body);
    }
    for (const std::uint32_t joint : targets.joints) {
      if (!world.jointDescription(JointId{joint})) jointOwnerOf_.erase(joint);
    }
  }
  sweep(world);
}

void Ownership::sweep(const World& world) {
  const std::size_t limit = 2 * std::size_t(world.settings().maxBodies);
  if (ownerOf_.size() > limit) {
    std::erase_if(ownerOf_, [&](const auto& entry) { return !world.isValid(BodyId{entry.first}); });
  }
  if (jointOwnerOf_.size() > limit) {
    std::erase_if(jointOwnerOf_, [&](const auto& entry) {
      return !world.jointDescription(JointId{entry.first});
    });
  }
}

}  // namespace impulse::server
