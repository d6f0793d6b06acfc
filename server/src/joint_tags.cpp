#include "impulse/server/joint_tags.h"

namespace impulse::server {

std::string JointTags::resolve(v1::ClientMessage& message, std::uint32_t client, const Simulation& simulation) {
  if (simulation.worldGeneration() != worldGeneration_) {
    // A replaced world starts its joint ids over: no tag names anything.
    worldGeneration_ = simulation.worldGeneration();
    joints_.clear();
  }
  const World& world = simulation.world();
  if (message.has_create_joint()) {
    const std::uint32_t tag = message.create_joint().tag();
    if (tag == 0) return {};
    if (const auto joint = liveJoint({client, tag}, world)) {
      return "create_joint: tag " + std::to_string(tag) + " already names joint " + std::to_string(*joint);
    }
    return {};
  }
  // Either command naming a joint by tag is given the joint's id instead.
  auto nameById = [&](auto& command, const char* name) {
    std::uint32_t id = command.joint_id();
    std::string refusal = resolveTag(id, command.joint_tag(), client, world, name);
    if (refusal.empty()) command.set_joint_id(id);
    return refusal;
  };
  if (message.has_update_joint()) return nameById(*message.mutable_update_joint(), "update_joint");
  if (message.has_remove_joint()) return nameById(*message.mutable_remove_joint(), "remove_joint");
  return {};
}

std::string JointTags::resolveTag(std::uint32_t& jointId, std::uint32_t tag, std::uint32_t client, const World& world,
                                  const char* command) {
  if (tag == 0) return {};
  const std::string named = std::string(command) + ": joint_tag " + std::to_string(tag);
  if (jointId != 0) return named + " and joint_id " + std::to_string(jointId) + " both given: name one";
  const auto joint = liveJoint({client, tag}, world);
  if (!joint) return named + " names no joint of this client";
  jointId = *joint;
  return {};
}

std::optional<std::uint32_t> JointTags::liveJoint(const Key& key, const World& world) {
  const auto it = joints_.find(key);
  if (it == joints_.end()) return std::nullopt;
  if (world.jointDescription(JointId{it->second})) return it->second;
  joints_.erase(it);
  return std::nullopt;
}

void JointTags::record(const v1::ClientMessage& message, const v1::ServerMessage& reply, std::uint32_t client,
                       const World& world) {
  if (!message.has_create_joint() || message.create_joint().tag() == 0) return;
  if (!reply.has_command_result() || !reply.command_result().ok()) return;
  joints_[{client, message.create_joint().tag()}] = reply.command_result().joint_id();
  sweep(world);
}

void JointTags::sweep(const World& world) {
  if (joints_.size() <= 2 * std::size_t(world.settings().maxBodies)) return;
  std::erase_if(joints_, [&](const auto& entry) { return !world.jointDescription(JointId{entry.second}); });
}

void JointTags::dropClient(std::uint32_t client) {
  std::erase_if(joints_, [&](const auto& entry) { return entry.first.first == client; });
}

}  // namespace impulse::server
