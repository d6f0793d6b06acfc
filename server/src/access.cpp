#include "impulse/server/access.h"

#include <algorithm>

#include "impulse/server/commands.h"

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

// The body a remove_body, apply_impulse or set_velocity acts on.
std::uint32_t targetBody(const v1::ClientMessage& message) {
  if (message.has_set_velocity()) return message.set_velocity().body_id();
  return message.has_remove_body() ? message.remove_body().body_id()
                                   : message.apply_impulse().body_id();
}

// The joint an update_joint or remove_joint acts on.
std::uint32_t targetJoint(const v1::ClientMessage& message) {
  return message.has_update_joint() ? message.update_joint().joint_id()
                                    : message.remove_joint().joint_id();
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

std::string Ownership::playerRefusal(const v1::ClientMessage& message, std::uint32_t client) const {
  const std::string_view command = commandName(message);
  if (changesEveryonesWorld(message)) {
    return std::string(command) +
           ": refused for the player role (it changes everyone's world: the admin role, "
           "Hello.token = the admin token, is needed)";
  }
  if (message.has_remove_body() || message.has_apply_impulse() || message.has_set_velocity()) {
    return ownershipRefusal(command, targetBody(message), client);
  }
  if (message.has_create_joint()) {
    // Body 0 is the world, which a player may pin its own bodies to.
    const auto& joint = message.create_joint();
    std::string refusal = ownershipRefusal(command, joint.body_a(), client);
    if (refusal.empty() && joint.body_b() != 0) {
      refusal = ownershipRefusal(command, joint.body_b(), client);
    }
    return refusal;
  }
  if (message.has_update_joint() || message.has_remove_joint()) {
    return jointRefusal(command, targetJoint(message), client);
  }
  return {};
}

std::string Ownership::ownershipRefusal(std::string_view command, std::uint32_t body,
                                        std::uint32_t client) const {
  const auto it = ownerOf_.find(body);
  if (it != ownerOf_.end() && it->second == client) return {};
  return std::string(command) + ": refused for the player role: body " + std::to_string(body) +
         " was not created by this client (players act on their own bodies only)";
}

std::string Ownership::jointRefusal(std::string_view command, std::uint32_t joint,
                                    std::uint32_t client) const {
  const auto it = jointOwnerOf_.find(joint);
  if (it != jointOwnerOf_.end() && it->second == client) return {};
  return std::string(command) + ": refused for the player role: joint " + std::to_string(joint) +
         " was not created by this client (players act on their own joints only)";
}

void Ownership::recordOutcome(const v1::ClientMessage& message, const v1::ServerMessage& reply,
                              std::uint32_t client, const World& world) {
  if (!reply.has_command_result() || !reply.command_result().ok()) return;
  if (message.has_spawn_circle() || message.has_spawn_polygon()) {
    ownerOf_[reply.command_result().body_id()] = client;
  } else if (message.has_remove_body()) {
    ownerOf_.erase(message.remove_body().body_id());
  } else if (message.has_create_joint()) {
    jointOwnerOf_[reply.command_result().joint_id()] = client;
  } else if (message.has_remove_joint()) {
    jointOwnerOf_.erase(message.remove_joint().joint_id());
  } else if (message.has_clear() || message.has_load_preset()) {
    ownerOf_.clear();
    jointOwnerOf_.clear();
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
