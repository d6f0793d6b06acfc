#include "impulse/server/snapshot_builder.h"

#include <google/protobuf/arena.h>

#include <algorithm>

#include "impulse.pb.h"
#include "impulse/wire/convert.h"
#include "impulse/wire/framing.h"

namespace impulse::server {

namespace {

void sortUnique(std::vector<BodyId>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

void fillMeta(const World& world, const SnapshotMeta& meta, bool full, v1::Snapshot* snapshot) {
  snapshot->set_tick(meta.tick);
  snapshot->set_sim_time(meta.simTime);
  wire::toWire(world.gravity(), snapshot->mutable_gravity());
  snapshot->set_full(full);
  snapshot->set_paused(meta.paused);
}

google::protobuf::ArenaOptions arenaOptions() {
  google::protobuf::ArenaOptions options;
  options.start_block_size = 64 * 1024;
  options.max_block_size = 1024 * 1024;
  return options;
}

bool sameMeta(const SnapshotMeta& a, const SnapshotMeta& b) {
  return a.tick == b.tick && a.simTime == b.simTime && a.paused == b.paused;
}

}  // namespace

SnapshotBuilder::SnapshotBuilder(const World& world) : world_(world) {}

void SnapshotBuilder::markDirty() {
  pending_ = true;
  ++version_;
}

void SnapshotBuilder::bodyAdded(BodyId id) {
  added_.push_back(id);
  markDirty();
}

void SnapshotBuilder::bodyRemoved(BodyId id) {
  // Listed even if added since the last broadcast: a client that joined in
  // between got the body in its full snapshot.
  removed_.push_back(id);
  markDirty();
}

void SnapshotBuilder::bodyLeftWorld(BodyId id) {
  leftWorld_.push_back(id);
  bodyRemoved(id);
}

void SnapshotBuilder::bodyChanged(BodyId id) {
  changed_.push_back(id);
  compactChanged();
  markDirty();
}

void SnapshotBuilder::stepped(std::span<const BodyId> moved) {
  changed_.insert(changed_.end(), moved.begin(), moved.end());
  compactChanged();
  markDirty();
}

void SnapshotBuilder::compactChanged() {
  // Several steps between broadcasts repeat the same ids; keep the list
  // bounded by the body count however many steps pass.
  const std::size_t limit = 4 * std::max<std::size_t>(std::size_t(world_.bodyCount()), 256);
  if (changed_.size() > limit) sortUnique(changed_);
}

void SnapshotBuilder::worldChanged() { markDirty(); }

void SnapshotBuilder::worldReplaced(const PresetInfo& preset) {
  preset_ = preset;
  replaced_ = true;
  added_.clear();
  removed_.clear();
  leftWorld_.clear();
  changed_.clear();
  markDirty();
}

void SnapshotBuilder::discardPending() {
  added_.clear();
  removed_.clear();
  leftWorld_.clear();
  changed_.clear();
  replaced_ = false;
  pending_ = false;
}

SharedFrame SnapshotBuilder::takeDelta(const SnapshotMeta& meta) {
  if (replaced_) {
    discardPending();
    return full(meta);
  }
  // Thousands of small sub-messages: an arena makes their allocation cheap.
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  fillMeta(world_, meta, false, snapshot);

  sortUnique(removed_);
  for (const BodyId id : removed_) snapshot->add_removed(id.value);
  for (const BodyId id : leftWorld_) snapshot->add_left_world(id.value);

  sortUnique(added_);
  for (const BodyId id : added_) {
    if (const auto description = world_.bodyDescription(id)) {
      wire::toWire(*description, snapshot->add_added());
    }
  }

  changed_.insert(changed_.end(), added_.begin(), added_.end());
  sortUnique(changed_);
  snapshot->mutable_bodies()->Reserve(int(changed_.size()));
  for (const BodyId id : changed_) {
    if (const auto state = world_.bodyState(id)) wire::toWire(*state, snapshot->add_bodies());
  }

  discardPending();
  return wire::encodeSharedFrame(message);
}

SharedFrame SnapshotBuilder::full(const SnapshotMeta& meta) {
  if (cachedFull_ && cachedVersion_ == version_ && sameMeta(cachedMeta_, meta)) return cachedFull_;
  google::protobuf::Arena arena(arenaOptions());
  auto& message = *google::protobuf::Arena::CreateMessage<v1::ServerMessage>(&arena);
  auto* snapshot = message.mutable_snapshot();
  fillMeta(world_, meta, true, snapshot);
  wire::toWire(preset_, snapshot->mutable_preset());
  const auto ids = world_.bodyIds();
  snapshot->mutable_added()->Reserve(int(ids.size()));
  snapshot->mutable_bodies()->Reserve(int(ids.size()));
  for (const BodyId id : ids) {
    const auto description = world_.bodyDescription(id);
    const auto state = world_.bodyState(id);
    if (!description || !state) continue;
    wire::toWire(*description, snapshot->add_added());
    wire::toWire(*state, snapshot->add_bodies());
  }
  cachedFull_ = wire::encodeSharedFrame(message);
  cachedVersion_ = version_;
  cachedMeta_ = meta;
  return cachedFull_;
}

}  // namespace impulse::server
