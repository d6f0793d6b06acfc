#include "impulse/wire/quantized_decoder.h"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace impulse::wire::quantized {

namespace {

struct Header {
  bool key = false;
  Integration integration;
  std::uint64_t tick = 0;
  std::uint64_t ticks = 0;
  std::uint64_t count = 0;
};

bool withinLimit(std::int64_t value, std::int64_t limit) { return std::abs(value) <= limit; }

std::optional<std::string> readHeader(BitReader& bits, Header& header) {
  const std::uint64_t version = bits.readBits(kFormatVersionBits);
  header.key = bits.readBit();
  const std::uint64_t tickHz = bits.readExpGolomb();
  const std::uint64_t subSteps = bits.readExpGolomb();
  std::array<std::int64_t, 2> gravity{};
  for (std::int64_t& g : gravity) g = bits.readSigned();
  header.tick = bits.readExpGolomb();
  if (!header.key) header.ticks = bits.readExpGolomb();
  header.count = bits.readExpGolomb();
  if (bits.failed()) return "quantized_bodies: the header is cut short";
  if (version != kFormatVersion) {
    return "quantized_bodies: layout version " + std::to_string(version) + ", expected " +
           std::to_string(kFormatVersion);
  }
  if (tickHz < 1 || tickHz > std::uint64_t(kMaxTickHz)) {
    return "quantized_bodies: tick rate " + std::to_string(tickHz) + " Hz is outside 1.." +
           std::to_string(kMaxTickHz);
  }
  if (subSteps < 1 || subSteps > std::uint64_t(kMaxSubSteps)) {
    return "quantized_bodies: " + std::to_string(subSteps) + " substeps is outside 1.." +
           std::to_string(kMaxSubSteps);
  }
  if (!withinLimit(gravity[0], kAccelerationLimit) || !withinLimit(gravity[1], kAccelerationLimit)) {
    return "quantized_bodies: gravity out of range";
  }
  if (header.ticks > header.tick) return "quantized_bodies: the baseline is before tick 0";
  header.integration = {
      .tickHz = std::int64_t(tickHz), .subSteps = std::int64_t(subSteps), .gravity = gravity};
  return std::nullopt;
}

std::optional<std::string> readCorrectionCode(BitReader& bits, CorrectionCode& code) {
  const std::uint64_t kinds = bits.readExpGolomb();
  if (bits.failed() || kinds > kRecordKinds) return "quantized_bodies: a kinds table cut short or too long";
  code.kinds.resize(std::size_t(kinds));
  for (RecordKind& kind : code.kinds) kind = RecordKind(bits.readBits(kRecordKindBits));
  for (int& order : code.orders) order = int(bits.readBits(kOrderBits));
  if (bits.failed()) return "quantized_bodies: the correction code is cut short";
  return std::nullopt;
}

bool readWhole(BitReader& bits, State& state) {
  state.awake = bits.readBit();
  for (auto* values : {&state.position, &state.velocity}) {
    for (std::int64_t& value : *values) value = bits.readSigned();
  }
  for (std::int64_t& value : state.acceleration) value = bits.readSigned();
  auto fits = [](const auto& values, std::int64_t limit) {
    return std::all_of(values.begin(), values.end(),
                       [limit](std::int64_t v) { return withinLimit(v, limit); });
  };
  return !bits.failed() && fits(state.position, kValueLimit) &&
         fits(state.velocity, kValueLimit) && fits(state.acceleration, kAccelerationLimit);
}

}  // namespace

bool Decoder::readCorrection(BitReader& bits, const State& before, std::int64_t ticks,
                             const Integration& integration, State& state) const {
  const std::uint64_t rank = bits.readExpGolomb();
  if (bits.failed() || rank >= code_.kinds.size()) return false;
  const RecordKind kind = code_.kinds[std::size_t(rank)];
  Residuals residuals{};
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    if (!kindSendsResidual(kind, i)) continue;
    residuals[i] = unfoldNonZero(bits.readExpGolomb(code_.orders[i]));
    if (bits.failed() || !withinLimit(residuals[i], kValueLimit / kQuanta[i])) return false;
  }
  state = corrected(predict(before, ticks, integration), residuals, kindAwake(kind), before, ticks,
                    integration);
  auto fits = [](const auto& values) {
    return std::all_of(values.begin(), values.end(),
                       [](std::int64_t v) { return withinLimit(v, kValueLimit); });
  };
  return fits(state.position) && fits(state.velocity);
}

std::optional<std::string> Decoder::decode(std::string_view bytes, bool full,
                                           std::span<const std::uint32_t> removed,
                                           std::span<const std::uint32_t> added,
                                           std::vector<BodyState>& moved) {
  moved.clear();
  BitReader bits(bytes);
  Header header;
  auto error = readHeader(bits, header);
  if (!error && header.key != full) {
    error = "quantized_bodies: a key frame must come in a full snapshot, and only there";
  }
  if (!error && !header.key && !baseline_.valid) {
    error = "quantized_bodies: a delta before any key frame";
  }
  if (!error && !header.key && baseline_.tick != header.tick - header.ticks) {
    error = "quantized_bodies: coded against tick " + std::to_string(header.tick - header.ticks) +
            " but the last one decoded was tick " + std::to_string(baseline_.tick);
  }
  if (!error) {
    if (header.key) baseline_.bodies.clear();
    for (const std::uint32_t id : removed) baseline_.bodies.erase(id);
    whole_.assign(added.begin(), added.end());
    std::sort(whole_.begin(), whole_.end());
    whole_.erase(std::unique(whole_.begin(), whole_.end()), whole_.end());
    for (const std::uint32_t id : whole_) baseline_.bodies[id] = State{};
    if (baseline_.bodies.size() != header.count) {
      error = "quantized_bodies: codes " + std::to_string(header.count) + " bodies, the client has " +
              std::to_string(baseline_.bodies.size());
    }
  }
  if (!error && !header.key) error = readCorrectionCode(bits, code_);
  if (!error) {
    error = decodeEntries(bits, std::int64_t(header.ticks), header.integration, whole_, moved);
  }
  if (error) {
    forget();
    moved.clear();
    return error;
  }
  baseline_.tick = header.tick;
  baseline_.valid = true;
  return std::nullopt;
}

std::optional<std::string> Decoder::decodeEntries(BitReader& bits, std::int64_t ticks,
                                                  const Integration& integration,
                                                  std::span<const std::uint32_t> whole,
                                                  std::vector<BodyState>& moved) {
  std::size_t deltaLeft = baseline_.bodies.size() - whole.size();
  std::uint64_t runLeft = 0;
  bool runSent = true;
  bool firstRun = true;
  for (auto& [id, state] : baseline_.bodies) {
    if (std::binary_search(whole.begin(), whole.end(), id)) {
      if (!readWhole(bits, state)) {
        return "quantized_bodies: body " + std::to_string(id) + ": a whole state cut short or out of range";
      }
      moved.push_back(dequantize(BodyId{id}, state, origin_));
      continue;
    }
    while (runLeft == 0) {
      runSent = firstRun ? false : !runSent;
      const std::uint64_t length = bits.readExpGolomb();
      runLeft = firstRun ? length : length + 1;
      firstRun = false;
      if (bits.failed() || runLeft > deltaLeft) {
        return "quantized_bodies: a run of " + std::to_string(runLeft) + " bodies where " +
               std::to_string(deltaLeft) + " are left";
      }
    }
    --runLeft;
    --deltaLeft;
    const State before = state;
    if (runSent && !readCorrection(bits, before, ticks, integration, state)) {
      return "quantized_bodies: body " + std::to_string(id) + ": a correction cut short or out of range";
    }
    if (!runSent) state = predict(before, ticks, integration);
    if (runSent || before.awake) moved.push_back(dequantize(BodyId{id}, state, origin_));
  }
  return std::nullopt;
}

}  // namespace impulse::wire::quantized
