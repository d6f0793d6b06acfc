#include "impulse/wire/quantized_encoder.h"

#include <algorithm>

namespace impulse::wire::quantized {

namespace {

bool contains(std::span<const std::uint32_t> sortedIds, std::uint32_t id) {
  return std::binary_search(sortedIds.begin(), sortedIds.end(), id);
}

State stateNow(const World& world, std::uint32_t id) {
  const auto state = world.bodyState(BodyId{id});
  return state ? quantize(*state) : State{};
}

// Bodies are coded in ascending id order whatever order the lists come in.
std::span<const std::uint32_t> sorted(std::span<const std::uint32_t> ids,
                                      std::vector<std::uint32_t>& scratch) {
  scratch.assign(ids.begin(), ids.end());
  std::sort(scratch.begin(), scratch.end());
  scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
  return scratch;
}

bool anyNonZero(const Residuals& residuals) {
  return std::any_of(residuals.begin(), residuals.end(), [](std::int64_t r) { return r != 0; });
}

void writeWhole(BitWriter& bits, const State& state) {
  bits.writeBit(state.awake);
  for (const auto* values : {&state.position, &state.velocity, &state.acceleration}) {
    for (const std::int64_t value : *values) bits.writeSigned(value);
  }
}

void writeCorrection(BitWriter& bits, const State& state, const Residuals& residuals) {
  bits.writeBit(state.awake);
  for (const std::int64_t residual : residuals) bits.writeSigned(residual);
}

}  // namespace

void Encoder::reset(const World& world, std::uint64_t tick) {
  baseline_.bodies.clear();
  for (const BodyId id : world.bodyIds()) baseline_.bodies[id.value] = stateNow(world, id.value);
  baseline_.tick = tick;
  baseline_.valid = true;
  ++generation_;
}

std::string Encoder::delta(const World& world, const SnapshotLists& lists) {
  const std::uint64_t ticks = lists.tick - baseline_.tick;
  const auto added = sorted(lists.added, added_);
  const auto changed = sorted(lists.changed, changed_);
  for (const std::uint32_t id : lists.removed) baseline_.bodies.erase(id);
  for (const std::uint32_t id : added) baseline_.bodies[id] = State{};

  entries_.clear();
  for (auto& [id, state] : baseline_.bodies) {
    Entry entry{.id = id};
    if (contains(added, id)) {
      entry.whole = true;
      state = stateNow(world, id);
    } else {
      const State predicted = predict(state, std::int64_t(ticks), lists.integration);
      const auto truth = state.awake || contains(changed, id)
                             ? world.bodyState(BodyId{id})
                             : std::nullopt;
      const State now = truth ? quantize(*truth) : predicted;
      entry.residuals = residualsBetween(predicted, now);
      entry.sent = anyNonZero(entry.residuals) || now.awake != predicted.awake;
      state = entry.sent ? corrected(predicted, entry.residuals, now.awake, state,
                                     std::int64_t(ticks), lists.integration)
                         : predicted;
    }
    entry.state = state;
    entries_.push_back(entry);
  }
  baseline_.tick = lists.tick;
  ++generation_;

  bits_.clear();
  writeHeader(false, lists.tick, lists.integration, ticks, entries_.size());
  writeEntries();
  return bits_.bytes();
}

std::string Encoder::keyFrame(const World& world, const SnapshotLists& lists) {
  entries_.clear();
  for (const std::uint32_t id : sorted(lists.added, added_)) {
    const auto known = baseline_.bodies.find(id);
    const State state = known != baseline_.bodies.end() ? known->second : stateNow(world, id);
    entries_.push_back({.id = id, .whole = true, .state = state});
  }
  bits_.clear();
  writeHeader(true, baseline_.tick, lists.integration, 0, entries_.size());
  writeEntries();
  return bits_.bytes();
}

void Encoder::writeHeader(bool key, std::uint64_t tick, const Integration& integration, std::uint64_t ticks,
                          std::size_t count) {
  bits_.writeBits(kFormatVersion, kFormatVersionBits);
  bits_.writeBit(key);
  bits_.writeExpGolomb(std::uint64_t(integration.tickHz));
  bits_.writeExpGolomb(std::uint64_t(integration.subSteps));
  for (const std::int64_t g : integration.gravity) bits_.writeSigned(g);
  bits_.writeExpGolomb(tick);
  if (!key) bits_.writeExpGolomb(ticks);
  bits_.writeExpGolomb(count);
}

// Delta-coded bodies come in runs, alternately not sent and sent, the first
// (not sent) possibly empty; each run's length is written where it starts.
void Encoder::writeEntries() {
  std::size_t runLeft = 0;
  bool runSent = true;
  bool firstRun = true;
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    const Entry& entry = entries_[k];
    if (entry.whole) {
      writeWhole(bits_, entry.state);
      continue;
    }
    while (runLeft == 0) {
      runSent = firstRun ? false : !runSent;
      for (std::size_t j = k; j < entries_.size(); ++j) {
        if (entries_[j].whole) continue;
        if (entries_[j].sent != runSent) break;
        ++runLeft;
      }
      bits_.writeExpGolomb(firstRun ? runLeft : runLeft - 1);
      firstRun = false;
    }
    --runLeft;
    if (entry.sent) writeCorrection(bits_, entry.state, entry.residuals);
  }
}

}  // namespace impulse::wire::quantized
