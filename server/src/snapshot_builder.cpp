#include "impulse/server/snapshot_builder.h"

#include <google/protobuf/arena.h>

#include "impulse.pb.h"
#include "impulse/wire/convert.h"
#include "impulse/wire/field_convert.h"
#include "impulse/wire/framing.h"

namespace impulse::server {

namespace {

void fillMeta(const Simulation& simulation, bool full, v1::Snapshot* snapshot) {
  const SnapshotMeta meta = simulation.meta();
  snapshot->set_tick(meta.tick);
  snapshot->set_sim_time(meta.simTime);
  wire::toWire(simulation.world().gravity(), snapshot->mutable_gravity());
  snapshot->set_full(full);
  snapshot->set_paused(meta.paused);
}

google::protobuf::ArenaOptions arenaOptions() {
  google::protobuf::ArenaOptions options;
  options.start_block_size = 64 * 1024;
  options.max_block_size = 1024 * 1024;
  return options;
}

void addJoint(const World& world, JointId id, v1::Snapshot* snapshot) {
  if (const auto description = world.jointDescription(id)) {
    wire::toWire(*description, snapshot->add_joints_added());
  }
}

// A field the world no longer has (added and removed between snapshots) is
// not described: its id is in fields_removed.
void addField(const World& world, FieldId id, v1::Snapshot* snapshot) {
  const ForceField* field = world.field(id);
  if (field == nullptr) return;
  if (const auto def = describeField(*field)) wire::toWire(id, *def, snapshot->add_fields_added());
}

bool sameMeta(const SnapshotMeta& a, const SnapshotMeta& b) {
  return a.tick == b.tick && a.simTime == b.simTime && a.paused == b.paused;
}

}  // namespace

SnapshotBuilder::SnapshotBuilder(const Simulation& simulation) : simulation_(simulation) {}

SharedFrame SnapshotBuilder::delta(WorldChanges& changes) {
  if (changes.wasReplaced()) return full();
  const World& world = simulation_.world();
  // Thousands of small sub-messages: an arena makes their allocation cheap.
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  fillMeta(simulation_, false, snapshot);

  changes.normalise();
  for (const BodyId id : changes.removedIds()) snapshot->add_removed(id.value);
  for (const BodyId id : changes.leftWorldIds()) snapshot->add_left_world(id.value);
  for (const BodyId id : changes.addedIds()) {
    if (const auto description = world.bodyDescription(id)) {
      wire::toWire(*description, snapshot->add_added());
    }
  }
  for (const JointId id : changes.removedJointIds()) snapshot->add_joints_removed(id.value);
  for (const JointId id : changes.addedJointIds()) addJoint(world, id, snapshot);
  for (const FieldId id : changes.removedFieldIds()) snapshot->add_fields_removed(id.value);
  for (const FieldId id : changes.addedFieldIds()) addField(world, id, snapshot);
  snapshot->mutable_bodies()->Reserve(int(changes.changedIds().size()));
  for (const BodyId id : changes.changedIds()) {
    if (const auto state = world.bodyState(id)) wire::toWire(*state, snapshot->add_bodies());
  }
  return wire::encodeSharedFrame(message);
}

SharedFrame SnapshotBuilder::full() {
  const SnapshotMeta meta = simulation_.meta();
  if (cachedFull_ && cachedVersion_ == simulation_.version() && sameMeta(cachedMeta_, meta)) {
    return cachedFull_;
  }
  const World& world = simulation_.world();
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  fillMeta(simulation_, true, snapshot);
  wire::toWire(simulation_.preset(), snapshot->mutable_preset());
  const auto ids = world.bodyIds();
  snapshot->mutable_added()->Reserve(int(ids.size()));
  snapshot->mutable_bodies()->Reserve(int(ids.size()));
  for (const BodyId id : ids) {
    const auto description = world.bodyDescription(id);
    const auto state = world.bodyState(id);
    if (!description || !state) continue;
    wire::toWire(*description, snapshot->add_added());
    wire::toWire(*state, snapshot->add_bodies());
  }
  for (const JointId id : world.jointIds()) addJoint(world, id, snapshot);
  for (const FieldId id : world.fieldIds()) addField(world, id, snapshot);
  cachedFull_ = wire::encodeSharedFrame(message);
  cachedVersion_ = simulation_.version();
  cachedMeta_ = meta;
  return cachedFull_;
}

}  // namespace impulse::server
