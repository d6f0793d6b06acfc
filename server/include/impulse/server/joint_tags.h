#pragma once
/// Joints named by their client's own tags (CreateJoint.tag; UpdateJoint and
/// RemoveJoint name one by joint_tag). A predicting client moves a drag's
/// mouse joint before the reply naming its id has come back
/// (docs/networked-play.md, "Prediction"); the room resolves the tag when
/// the command is applied, so a stamped UpdateJoint finds the joint its
/// CreateJoint, stamped earlier, made.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "impulse.pb.h"
#include "impulse/server/simulation.h"

namespace impulse::server {

class JointTags {
 public:
  /// Just before `message` is applied: empty when it may go on, its tag
  /// (if any) turned into the joint id it stands for; else the refusal (a
  /// tag the client's live joint already has, joint_id and joint_tag both
  /// given, a tag no live joint of the client has), `message` unchanged.
  std::string resolve(v1::ClientMessage& message, std::uint32_t client, const Simulation& simulation);
  /// After a command was applied: a tagged CreateJoint's joint is
  /// remembered under its tag.
  void record(const v1::ClientMessage& message, const v1::ServerMessage& reply, std::uint32_t client,
              const World& world);
  /// Forgets a client's tags (it left).
  void dropClient(std::uint32_t client);

 private:
  using Key = std::pair<std::uint32_t, std::uint32_t>;  // client, tag
  /// The live joint a client's tag names; a dead one is forgotten.
  std::optional<std::uint32_t> liveJoint(const Key& key, const World& world);
  /// The tag a joint-naming command gives instead of its id, refused when
  /// it gives both; nothing when it names no tag.
  std::string resolveTag(std::uint32_t& jointId, std::uint32_t tag, std::uint32_t client, const World& world,
                         const char* command);
  /// Forgets the tags of joints gone, once they could outgrow the world's
  /// body limit (a tag is freed by its joint leaving in any way).
  void sweep(const World& world);

  std::map<Key, std::uint32_t> joints_;
  /// The world the tags were recorded in (Simulation::worldGeneration).
  std::uint64_t worldGeneration_ = 0;
};

}  // namespace impulse::server
