#include "impulse/server/snapshot_builder.h"

#include <google/protobuf/arena.h>

#include "impulse.pb.h"
#include "impulse/wire/convert.h"
#include "impulse/wire/field_convert.h"
#include "impulse/wire/framing.h"
#include "impulse/wire/wire_positions.h"

namespace impulse::server {

namespace {

void fillMeta(const Simulation& simulation, const AppliedStamps& stamps, bool full, v1::Snapshot* snapshot) {
  const SnapshotMeta meta = simulation.meta();
  for (const auto& [client, requestId] : stamps) {
    auto* stamp = snapshot->add_applied_stamps();
    stamp->set_client_id(client);
    stamp->set_request_id(requestId);
  }
  snapshot->set_tick(meta.tick);
  snapshot->set_sim_time(meta.simTime);
  wire::toWire(simulation.world().gravity(), snapshot->mutable_gravity());
  snapshot->set_full(full);
  snapshot->set_paused(meta.paused);
  snapshot->set_time_scale(meta.timeScale);
}

// Positions leave the room from (0, 0), as the wire carries them
// (wire_positions.h); the quantized states code theirs so themselves.
SharedFrame encodeSnapshot(v1::ServerMessage& message, const World& world) {
  wire::shiftPositions(*message.mutable_snapshot(), world.origin());
  return wire::encodeSharedFrame(message);
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

void addDescriptor(const World& world, BodyId id, v1::Snapshot* snapshot) {
  if (const auto description = world.bodyDescription(id)) wire::toWire(*description, snapshot->add_added());
}

void addState(const World& world, std::uint32_t id, v1::Snapshot* snapshot) {
  if (const auto state = world.bodyState(BodyId{id})) wire::toWire(*state, snapshot->add_bodies());
}

// The joints and fields a delta carries (personal ones list bodies their own way).
void addJointAndFieldChanges(const World& world, const WorldChanges& changes, v1::Snapshot* snapshot) {
  for (const JointId id : changes.removedJointIds()) snapshot->add_joints_removed(id.value);
  for (const JointId id : changes.addedJointIds()) addJoint(world, id, snapshot);
  for (const FieldId id : changes.removedFieldIds()) snapshot->add_fields_removed(id.value);
  for (const FieldId id : changes.addedFieldIds()) addField(world, id, snapshot);
}

// What every delta carries whatever its encoding: removals, added bodies
// and joints.
void addChangeLists(const World& world, const WorldChanges& changes, v1::Snapshot* snapshot) {
  for (const BodyId id : changes.removedIds()) snapshot->add_removed(id.value);
  for (const BodyId id : changes.leftWorldIds()) snapshot->add_left_world(id.value);
  for (const BodyId id : changes.addedIds()) addDescriptor(world, id, snapshot);
  addJointAndFieldChanges(world, changes, snapshot);
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

// A full snapshot's meta and preset.
void addFullMeta(const Simulation& simulation, const AppliedStamps& stamps, v1::Snapshot* snapshot) {
  fillMeta(simulation, stamps, true, snapshot);
  wire::toWire(simulation.preset(), snapshot->mutable_preset());
}

// A full snapshot's meta, preset, joints and fields: all but the bodies.
void addWorldButBodies(const Simulation& simulation, const AppliedStamps& stamps, v1::Snapshot* snapshot) {
  const World& world = simulation.world();
  addFullMeta(simulation, stamps, snapshot);
  for (const JointId id : world.jointIds()) addJoint(world, id, snapshot);
  for (const FieldId id : world.fieldIds()) addField(world, id, snapshot);
}

// A personal snapshot's joints and fields: the ones its area holds.
void addLinks(const World& world, const LinkChanges& joints, const LinkChanges& fields, v1::Snapshot* snapshot) {
  for (const std::uint32_t id : joints.removed) snapshot->add_joints_removed(id);
  for (const std::uint32_t id : joints.described) addJoint(world, JointId{id}, snapshot);
  for (const std::uint32_t id : fields.removed) snapshot->add_fields_removed(id);
  for (const std::uint32_t id : fields.described) addField(world, FieldId{id}, snapshot);
}

// A full snapshot's meta, preset, descriptors and joints: all but the states.
void addWholeWorld(const Simulation& simulation, const AppliedStamps& stamps, v1::Snapshot* snapshot) {
  const World& world = simulation.world();
  addWorldButBodies(simulation, stamps, snapshot);
  const auto ids = world.bodyIds();
  snapshot->mutable_added()->Reserve(int(ids.size()));
  for (const BodyId id : ids) addDescriptor(world, id, snapshot);
}


// The integration the prediction follows (docs/snapshots.md).
wire::quantized::Integration quantizedIntegration(const Simulation& simulation) {
  const World& world = simulation.world();
  return wire::quantized::integrationOf(simulation.tickHz(), world.settings().subSteps,
                                        world.gravity());
}

}  // namespace

SnapshotBuilder::SnapshotBuilder(const Simulation& simulation) : simulation_(simulation) {}

void SnapshotBuilder::stampProcessed(std::uint32_t client, std::uint64_t requestId) {
  appliedStamps_[client] = requestId;
  ++stampsVersion_;
}

void SnapshotBuilder::forgetClient(std::uint32_t client) {
  if (appliedStamps_.erase(client) > 0) ++stampsVersion_;
}

SharedFrame SnapshotBuilder::delta(WorldChanges& changes) {
  if (changes.wasReplaced()) return full();
  const World& world = simulation_.world();
  // Thousands of small sub-messages: an arena makes their allocation cheap.
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  fillMeta(simulation_, appliedStamps_, false, snapshot);

  changes.normalise();
  addChangeLists(world, changes, snapshot);
  snapshot->mutable_bodies()->Reserve(int(changes.changedIds().size()));
  for (const BodyId id : changes.changedIds()) {
    if (const auto state = world.bodyState(id)) wire::toWire(*state, snapshot->add_bodies());
  }
  return encodeSnapshot(message, simulation_.world());
}

SharedFrame SnapshotBuilder::full() {
  const SnapshotMeta meta = simulation_.meta();
  if (cachedFull_ && cachedVersion_ == simulation_.version() && sameMeta(cachedMeta_, meta) &&
      cachedStampsVersion_ == stampsVersion_) {
    return cachedFull_;
  }
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  const World& world = simulation_.world();
  addWholeWorld(simulation_, appliedStamps_, snapshot);
  snapshot->mutable_bodies()->Reserve(snapshot->added_size());
  for (const auto& descriptor : snapshot->added()) {
    wire::toWire(*world.bodyState(BodyId{descriptor.id()}), snapshot->add_bodies());
  }
  cachedFull_ = encodeSnapshot(message, simulation_.world());
  cachedVersion_ = simulation_.version();
  cachedStampsVersion_ = stampsVersion_;
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
  fillMeta(simulation_, appliedStamps_, false, snapshot);
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
  return encodeSnapshot(message, simulation_.world());
}

SharedFrame SnapshotBuilder::quantizedFull() {
  if (!encoder_.valid()) startQuantized();
  const SnapshotMeta meta = simulation_.meta();
  if (cachedKey_ && cachedKeyVersion_ == simulation_.version() && sameMeta(cachedKeyMeta_, meta) &&
      cachedKeyGeneration_ == encoder_.generation() && cachedKeyStampsVersion_ == stampsVersion_) {
    return cachedKey_;
  }
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  addWholeWorld(simulation_, appliedStamps_, snapshot);
  const auto added = addedIds(*snapshot);
  snapshot->set_quantized_bodies(encoder_.keyFrame(
      simulation_.world(), {.tick = simulation_.tick(),
                            .integration = quantizedIntegration(simulation_),
                            .added = added}));
  cachedKey_ = encodeSnapshot(message, simulation_.world());
  cachedKeyVersion_ = simulation_.version();
  cachedKeyGeneration_ = encoder_.generation();
  cachedKeyStampsVersion_ = stampsVersion_;
  cachedKeyMeta_ = meta;
  return cachedKey_;
}

// ---------------------------------------------------------- personal snapshots

void SnapshotBuilder::updatePlaces(const WorldChanges& changes) {
  if (placesCurrent_) {
    places_.update(simulation_.world(), changes);
  } else {
    places_.rebuild(simulation_.world());
  }
  placesCurrent_ = true;
}

void SnapshotBuilder::refreshPlaces() {
  // Between broadcasts no shape change is known yet: reaches stay as they
  // are until the next broadcast's changes say otherwise.
  if (placesCurrent_) {
    places_.update(simulation_.world(), WorldChanges{});
  } else {
    places_.rebuild(simulation_.world());
  }
}

SharedFrame SnapshotBuilder::personalDelta(PersonalStream& stream, const WorldChanges& changes) {
  if (stream.startsOver() || changes.wasReplaced()) return personalFull(stream);
  const World& world = simulation_.world();
  const auto allowance = stream.allowance(simulation_.tick(), simulation_.tickHz());
  // The smallest state message is about this many bytes: no more than the
  // allowance over it can be sent, so no more need ranking.
  constexpr double kSmallestStateBytes = 16;
  const std::size_t maxRanked = allowance ? std::size_t(std::max(*allowance, 0.0) / kSmallestStateBytes) : 0;
  const PersonalDelta& plan = stream.planDelta(places_, changes, simulation_.tick(), maxRanked);
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  fillMeta(simulation_, appliedStamps_, false, snapshot);
  for (const std::uint32_t id : plan.removed) snapshot->add_removed(id);
  for (const std::uint32_t id : plan.leftWorld) snapshot->add_left_world(id);
  for (const std::uint32_t id : plan.leftArea) snapshot->add_left_area(id);
  for (const std::uint32_t id : plan.described) addDescriptor(world, BodyId{id}, snapshot);
  addLinks(world, plan.joints, plan.fields, snapshot);
  for (const std::uint32_t id : plan.states) addState(world, id, snapshot);
  stream.markSent(addRankedStates(plan, allowance, snapshot));
  snapshot->set_states_withheld(std::uint32_t(stream.withheldCount()));
  snapshot->set_oldest_withheld_ticks(stream.oldestWithheldTicks(simulation_.tick()));
  SharedFrame frame = encodeSnapshot(message, simulation_.world());
  stream.charge(frame->size());
  return frame;
}

std::size_t SnapshotBuilder::addRankedStates(const PersonalDelta& plan, std::optional<double> allowance,
                                             v1::Snapshot* snapshot) {
  if (!allowance) return 0;
  // Sizes add up field by field: a state's bytes plus its tag and length.
  double bytes = double(snapshot->ByteSizeLong());
  std::size_t sent = 0;
  for (const std::uint32_t id : plan.ranked) {
    const auto state = simulation_.world().bodyState(BodyId{id});
    if (!state) continue;
    auto* wireState = snapshot->add_bodies();
    wire::toWire(*state, wireState);
    bytes += double(wireState->ByteSizeLong() + 2);
    if (bytes > *allowance) {
      snapshot->mutable_bodies()->RemoveLast();
      break;
    }
    ++sent;
  }
  return sent;
}

SharedFrame SnapshotBuilder::personalFull(PersonalStream& stream) {
  const World& world = simulation_.world();
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  addFullMeta(simulation_, appliedStamps_, snapshot);
  const auto& ids = stream.planFull(places_);
  addLinks(world, {.described = stream.knownJoints()}, {.described = stream.knownFields()}, snapshot);
  snapshot->mutable_added()->Reserve(int(ids.size()));
  snapshot->mutable_bodies()->Reserve(int(ids.size()));
  for (const std::uint32_t id : ids) addDescriptor(world, BodyId{id}, snapshot);
  for (const std::uint32_t id : ids) addState(world, id, snapshot);
  SharedFrame frame = encodeSnapshot(message, simulation_.world());
  // Paid for like a delta: the budget refills from this tick on.
  stream.allowance(simulation_.tick(), simulation_.tickHz());
  stream.charge(frame->size());
  return frame;
}

}  // namespace impulse::server
