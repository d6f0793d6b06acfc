#include "impulse/wire/quantized_encoder.h"

#include <algorithm>
#include <functional>

namespace impulse::wire::quantized {

namespace {

State stateNow(const World& world, std::uint32_t id) {
  const auto state = world.bodyState(BodyId{id});
  return state ? quantize(*state, world.origin()) : State{};
}

// Bodies are coded in ascending id order whatever order the lists come in;
// lists already ascending (the server's) are used as they are.
std::span<const std::uint32_t> ascending(std::span<const std::uint32_t> ids,
                                         std::vector<std::uint32_t>& scratch) {
  if (std::adjacent_find(ids.begin(), ids.end(), std::greater_equal<>()) == ids.end()) return ids;
  scratch.assign(ids.begin(), ids.end());
  std::sort(scratch.begin(), scratch.end());
  scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
  return scratch;
}

// Membership in an ascending list, asked in ascending order: one pass over
// the list for a whole snapshot instead of a search per body.
class AscendingIds {
 public:
  explicit AscendingIds(std::span<const std::uint32_t> ids) : ids_(ids) {}
  bool contains(std::uint32_t id) {
    while (next_ < ids_.size() && ids_[next_] < id) ++next_;
    return next_ < ids_.size() && ids_[next_] == id;
  }

 private:
  std::span<const std::uint32_t> ids_;
  std::size_t next_ = 0;
};

void writeWhole(BitWriter& bits, const State& state) {
  bits.writeBit(state.awake);
  for (const auto* values : {&state.position, &state.velocity, &state.acceleration}) {
    for (const std::int64_t value : *values) bits.writeSigned(value);
  }
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
  const auto added = ascending(lists.added, added_);
  for (const std::uint32_t id : lists.removed) baseline_.bodies.erase(id);
  for (const std::uint32_t id : added) baseline_.bodies[id] = State{};

  AscendingIds isAdded(added);
  AscendingIds isChanged(ascending(lists.changed, changed_));
  startEntries();
  for (auto& [id, state] : baseline_.bodies) {
    if (isAdded.contains(id)) {
      state = stateNow(world, id);
      addWhole(state);
    } else {
      const bool mayHaveChanged = isChanged.contains(id) || state.awake;
      advance(state, world, id, mayHaveChanged, ticks, lists.integration);
    }
  }
  baseline_.tick = lists.tick;
  ++generation_;

  chooseCorrectionCode();
  bits_.clear();
  writeHeader(false, lists.tick, lists.integration, ticks, codings_.size());
  writeCorrectionCode();
  writeEntries();
  return bits_.bytes();
}

std::string Encoder::keyFrame(const World& world, const SnapshotLists& lists) {
  startEntries();
  for (const std::uint32_t id : ascending(lists.added, added_)) {
    const auto known = baseline_.bodies.find(id);
    addWhole(known != baseline_.bodies.end() ? known->second : stateNow(world, id));
  }
  bits_.clear();
  writeHeader(true, baseline_.tick, lists.integration, 0, codings_.size());
  writeEntries();
  return bits_.bytes();
}

void Encoder::startEntries() {
  codings_.clear();
  corrections_.clear();
  wholes_.clear();
}

void Encoder::addWhole(const State& state) {
  codings_.push_back(Coding::Whole);
  wholes_.push_back(state);
}

void Encoder::advance(State& state, const World& world, std::uint32_t id, bool mayHaveChanged,
                      std::uint64_t ticks, const Integration& integration) {
  const State predicted = predict(state, std::int64_t(ticks), integration);
  const auto truth = mayHaveChanged ? world.bodyState(BodyId{id}) : std::nullopt;
  const State now = truth ? quantize(*truth, world.origin()) : predicted;
  const Residuals residuals = residualsBetween(predicted, now);
  const RecordKind kind = recordKind(now.awake, residuals);
  if (kind == recordKind(predicted.awake, Residuals{})) {
    state = predicted;
    codings_.push_back(Coding::Predicted);
    return;
  }
  state = corrected(predicted, residuals, now.awake, state, std::int64_t(ticks), integration);
  codings_.push_back(Coding::Corrected);
  corrections_.push_back({kind, residuals});
}

void Encoder::chooseCorrectionCode() {
  std::array<std::size_t, kRecordKinds> uses{};
  // Per residual, the bits its non-zero values would take at each order.
  std::array<std::array<std::uint64_t, kMaxOrder + 1>, 6> bitsAtOrder{};
  for (const Correction& correction : corrections_) {
    ++uses[correction.kind];
    for (std::size_t i = 0; i < correction.residuals.size(); ++i) {
      if (correction.residuals[i] == 0) continue;
      const std::uint64_t folded = foldNonZero(correction.residuals[i]);
      for (int order = 0; order <= kMaxOrder; ++order) {
        bitsAtOrder[i][std::size_t(order)] += std::uint64_t(BitWriter::expGolombLength(folded, order));
      }
    }
  }
  code_.kinds.clear();
  for (std::size_t kind = 0; kind < kRecordKinds; ++kind) {
    if (uses[kind] > 0) code_.kinds.push_back(RecordKind(kind));
  }
  std::stable_sort(code_.kinds.begin(), code_.kinds.end(),
                   [&](RecordKind a, RecordKind b) { return uses[a] > uses[b]; });
  for (std::size_t rank = 0; rank < code_.kinds.size(); ++rank) {
    rankOfKind_[code_.kinds[rank]] = std::uint8_t(rank);
  }
  for (std::size_t i = 0; i < bitsAtOrder.size(); ++i) {
    const auto& bits = bitsAtOrder[i];
    code_.orders[i] = int(std::min_element(bits.begin(), bits.end()) - bits.begin());
  }
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

void Encoder::writeCorrectionCode() {
  bits_.writeExpGolomb(code_.kinds.size());
  for (const RecordKind kind : code_.kinds) bits_.writeBits(kind, kRecordKindBits);
  for (const int order : code_.orders) bits_.writeBits(std::uint64_t(order), kOrderBits);
}

void Encoder::writeCorrection(const Correction& correction) {
  bits_.writeExpGolomb(rankOfKind_[correction.kind]);
  for (std::size_t i = 0; i < correction.residuals.size(); ++i) {
    if (kindSendsResidual(correction.kind, i)) {
      bits_.writeExpGolomb(foldNonZero(correction.residuals[i]), code_.orders[i]);
    }
  }
}

// Delta-coded bodies come in runs, alternately not sent and sent, the first
// (not sent) possibly empty; each run's length is written where it starts.
void Encoder::writeEntries() {
  auto nextCorrection = corrections_.begin();
  auto nextWhole = wholes_.begin();
  std::size_t runLeft = 0;
  bool runSent = true;
  bool firstRun = true;
  for (std::size_t k = 0; k < codings_.size(); ++k) {
    if (codings_[k] == Coding::Whole) {
      writeWhole(bits_, *nextWhole++);
      continue;
    }
    while (runLeft == 0) {
      runSent = firstRun ? false : !runSent;
      const Coding runCoding = runSent ? Coding::Corrected : Coding::Predicted;
      for (std::size_t j = k; j < codings_.size(); ++j) {
        if (codings_[j] == Coding::Whole) continue;  // whole records sit inside runs
        if (codings_[j] != runCoding) break;
        ++runLeft;
      }
      bits_.writeExpGolomb(firstRun ? runLeft : runLeft - 1);
      firstRun = false;
    }
    --runLeft;
    if (codings_[k] == Coding::Corrected) writeCorrection(*nextCorrection++);
  }
}

}  // namespace impulse::wire::quantized
