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
#include "impulse/world.h"

namespace impulse::wire::quantized {

/// One snapshot's body lists, as its message carries them (ids ascending).
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
  struct Entry {
    std::uint32_t id = 0;
    bool whole = false;  // an absolute record (added bodies)
    bool sent = false;   // a correction record (delta-coded bodies)
    State state{};
    Residuals residuals{};
  };
  void writeHeader(bool key, std::uint64_t tick, const Integration& integration, std::uint64_t ticks,
                   std::size_t count);
  void writeEntries();

  Baseline baseline_;
  std::uint64_t generation_ = 0;
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> added_;
  std::vector<std::uint32_t> changed_;
  BitWriter bits_;
};

}  // namespace impulse::wire::quantized
