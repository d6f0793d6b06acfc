#pragma once
/// Writes Snapshot.quantized_bodies (layout in docs/snapshots.md): body
/// states quantized and coded against a baseline that the encoder keeps
/// exactly as its clients decode it. Deltas advance the baseline; key frames
/// only read it, so one encoder serves every subscriber of a room.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "impulse/wire/bit_writer.h"
#include "impulse/wire/quantized_baseline.h"
#include "impulse/wire/quantized_layout.h"
#include "impulse/world.h"

namespace impulse::wire::quantized {

/// One snapshot's body lists, as its message carries them. Coding is fastest
/// with ids ascending and unique (as the server's are); other lists are
/// sorted first.
struct SnapshotLists {
  std::uint64_t tick = 0;
  Integration integration;
  std::span<const std::uint32_t> removed{};
  /// The ids in Snapshot.added: coded whole (every body, in a key frame).
  std::span<const std::uint32_t> added{};
  /// Bodies whose state may differ from the baseline's (a delta's only).
  std::span<const std::uint32_t> changed{};
};

class Encoder {
 public:
  /// The world's bodies now become the baseline, at `tick`.
  void reset(const World& world, std::uint64_t tick);
  /// No client holds the baseline any more: the next key frame resets it.
  void forget() { baseline_.valid = false; }
  bool valid() const { return baseline_.valid; }
  /// Counts baseline changes (for caching key frames).
  std::uint64_t generation() const { return generation_; }

  /// The changes as a delta against the baseline, which then holds the
  /// states the client decodes. Needs a valid baseline.
  std::string delta(const World& world, const SnapshotLists& lists);
  /// Every body in `lists.added` (a full snapshot's bodies): the baseline's
  /// state where it has one, so the next delta applies, else the world's.
  /// The baseline's tick is the frame's. Needs a valid baseline.
  std::string keyFrame(const World& world, const SnapshotLists& lists);

 private:
  /// How a delta codes each body, in id order (a key frame: every body whole).
  enum class Coding : std::uint8_t { Predicted, Corrected, Whole };
  struct Correction {
    RecordKind kind = 0;
    Residuals residuals{};
  };
  void startEntries();
  void addWhole(const State& state);
  /// Moves one baseline body `ticks` on: its prediction, corrected where
  /// the world says otherwise (asked only when it `mayHaveChanged`), and
  /// records how the delta codes it.
  void advance(State& state, const World& world, std::uint32_t id, bool mayHaveChanged,
               std::uint64_t ticks, const Integration& integration);
  /// The kinds table and residual orders that code this delta's records in
  /// the fewest bits.
  void chooseCorrectionCode();
  void writeHeader(bool key, std::uint64_t tick, const Integration& integration, std::uint64_t ticks,
                   std::size_t count);
  void writeCorrectionCode();
  void writeCorrection(const Correction& correction);
  void writeEntries();

  Baseline baseline_;
  std::uint64_t generation_ = 0;
  // One byte per body, and records only for the bodies that have one: an
  // awake world whose bodies move as predicted costs little to walk.
  std::vector<Coding> codings_;
  std::vector<Correction> corrections_;  ///< the Corrected bodies', in order
  std::vector<State> wholes_;            ///< the Whole bodies', in order
  std::vector<std::uint32_t> added_;
  std::vector<std::uint32_t> changed_;
  CorrectionCode code_;
  /// A kind's place in code_.kinds.
  std::array<std::uint8_t, kRecordKinds> rankOfKind_{};
  BitWriter bits_;
};

}  // namespace impulse::wire::quantized
