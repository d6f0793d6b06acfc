#pragma once
/// Reads Snapshot.quantized_bodies (layout in docs/snapshots.md) against the
/// baseline the previous ones left, for a client. Hostile bytes get an error
/// that says what was wrong, never a crash; after an error the baseline is
/// forgotten until the next key frame.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/body.h"
#include "impulse/wire/bit_reader.h"
#include "impulse/wire/quantized_baseline.h"
#include "impulse/wire/quantized_layout.h"

namespace impulse::wire::quantized {

class Decoder {
 public:
  /// One snapshot: `full` and its `removed` and `added` ids as the message
  /// carries them. On success `moved` holds the state of every body that may
  /// have moved (the corrected and the extrapolated ones) and the result is
  /// empty; otherwise it holds the error.
  std::optional<std::string> decode(std::string_view bytes, bool full,
                                    std::span<const std::uint32_t> removed,
                                    std::span<const std::uint32_t> added,
                                    std::vector<BodyState>& moved);
  /// States come out with positions relative to `origin` (the room's,
  /// Welcome.world_origin); (0, 0) until set.
  void setOrigin(const Vec2d& origin) { origin_ = origin; }
  /// A snapshot without quantized states replaced the world.
  void forget() { baseline_ = Baseline{}; }
  const Baseline& baseline() const { return baseline_; }

 private:
  std::optional<std::string> decodeEntries(BitReader& bits, std::int64_t ticks,
                                           const Integration& integration,
                                           std::span<const std::uint32_t> whole,
                                           std::vector<BodyState>& moved);
  bool readCorrection(BitReader& bits, const State& before, std::int64_t ticks,
                      const Integration& integration, State& state) const;

  Baseline baseline_;
  std::vector<std::uint32_t> whole_;
  /// The correction code of the delta being decoded.
  CorrectionCode code_;
  Vec2d origin_ = Vec2d::Zero();
};

}  // namespace impulse::wire::quantized
