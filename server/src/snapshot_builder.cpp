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
  snapshot->set_time_scale(meta.timeScale);
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

// What every delta carries whatever its encoding: removals, added bodies
// and joints.
void addChangeLists(const World& world, const WorldChanges& changes, v1::Snapshot* snapshot) {
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
}

std::vector<std::uint32_t> addedIds(const v1::Snapshot& snapshot) {
  std::vector<std::uint32_t> ids;
  ids.reserve(std::size_t(snapshot.added_size()));
  for (const auto& descriptor : snapshot.added()) ids.push_back(descriptor.id());
  return ids;
}

bool sameMeta(const SnapshotMeta& a, const SnapshotMeta& b) {
  return a.tick == b.tick && a.simTime == b.simTime && a.paused == b.paused &&
         a.timeScale == b.timeScale;
}

// A full snapshot's meta, preset, descriptors and joints: all but the states.
void addWholeWorld(const Simulation& simulation, v1::Snapshot* snapshot) {
  const World& world = simulation.world();
  fillMeta(simulation, true, snapshot);
  wire::toWire(simulation.preset(), snapshot->mutable_preset());
  const auto ids = world.bodyIds();
  snapshot->mutable_added()->Reserve(int(ids.size()));
  for (const BodyId id : ids) {
    if (const auto description = world.bodyDescription(id)) {
      wire::toWire(*description, snapshot->add_added());
    }
  }
  for (const JointId id : world.jointIds()) addJoint(world, id, snapshot);
  for (const FieldId id : world.fieldIds()) addField(world, id, snapshot);
}

// The integration the prediction follows (docs/snapshots.md).
wire::quantized::Integration quantizedIntegration(const Simulation& simulation) {
  const World& world = simulation.world();
  return wire::quantized::integrationOf(simulation.tickHz(), world.settings().subSteps,
                                        world.gravity());
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
  addChangeLists(world, changes, snapshot);
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
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  const World& world = simulation_.world();
  addWholeWorld(simulation_, snapshot);
  snapshot->mutable_bodies()->Reserve(snapshot->added_size());
  for (const auto& descriptor : snapshot->added()) {
    wire::toWire(*world.bodyState(BodyId{descriptor.id()}), snapshot->add_bodies());
  }
  cachedFull_ = wire::encodeSharedFrame(message);
  cachedVersion_ = simulation_.version();
  cachedMeta_ = meta;
  return cachedFull_;
}

// --------------------------------------------------------- quantized snapshots

void SnapshotBuilder::startQuantized() {
  encoder_.reset(simulation_.world(), simulation_.tick());
}

SharedFrame SnapshotBuilder::quantizedDelta(WorldChanges& changes) {
  if (changes.wasReplaced() || !encoder_.valid()) {
    startQuantized();
    return quantizedFull();
  }
  changes.normalise();
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  fillMeta(simulation_, false, snapshot);
  addChangeLists(simulation_.world(), changes, snapshot);
  changedIds_.clear();
  for (const BodyId id : changes.changedIds()) changedIds_.push_back(id.value);
  const auto added = addedIds(*snapshot);
  snapshot->set_quantized_bodies(encoder_.delta(
      simulation_.world(), {.tick = simulation_.tick(),
                            .integration = quantizedIntegration(simulation_),
                            .removed = {snapshot->removed().data(), std::size_t(snapshot->removed_size())},
                            .added = added,
                            .changed = changedIds_}));
  return wire::encodeSharedFrame(message);
}

SharedFrame SnapshotBuilder::quantizedFull() {
  if (!encoder_.valid()) startQuantized();
  const SnapshotMeta meta = simulation_.meta();
  if (cachedKey_ && cachedKeyVersion_ == simulation_.version() && sameMeta(cachedKeyMeta_, meta) &&
      cachedKeyGeneration_ == encoder_.generation()) {
    return cachedKey_;
  }
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  addWholeWorld(simulation_, snapshot);
  const auto added = addedIds(*snapshot);
  snapshot->set_quantized_bodies(encoder_.keyFrame(
      simulation_.world(), {.tick = simulation_.tick(),
                            .integration = quantizedIntegration(simulation_),
                            .added = added}));
  cachedKey_ = wire::encodeSharedFrame(message);
  cachedKeyVersion_ = simulation_.version();
  cachedKeyGeneration_ = encoder_.generation();
  cachedKeyMeta_ = meta;
  return cachedKey_;
}

}  // namespace impulse::server
