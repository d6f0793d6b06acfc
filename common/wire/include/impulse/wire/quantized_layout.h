#pragma once
/// What the encoder and the decoder of Snapshot.quantized_bodies must agree
/// on beyond the model (docs/snapshots.md, "Bit layout"): the version, and
/// how a delta codes its correction records.

#include <array>
#include <cstdint>
#include <vector>

#include "impulse/wire/quantized_state.h"

namespace impulse::wire::quantized {

/// The layout's version, the first 4 bits of every quantized_bodies.
inline constexpr std::uint64_t kFormatVersion = 2;
inline constexpr int kFormatVersionBits = 4;

/// A correction record's kind: its awake flag (bit 6) and which of its six
/// residuals are non-zero (bit 5 for x down to bit 0 for angular velocity).
using RecordKind = std::uint8_t;
inline constexpr int kRecordKindBits = 7;
inline constexpr std::size_t kRecordKinds = std::size_t(1) << kRecordKindBits;

inline RecordKind recordKind(bool awake, const Residuals& residuals) {
  unsigned kind = awake ? 1u << 6 : 0u;
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    if (residuals[i] != 0) kind |= 1u << (5 - i);
  }
  return RecordKind(kind);
}
inline bool kindAwake(RecordKind kind) { return (kind >> 6) & 1; }
inline bool kindSendsResidual(RecordKind kind, std::size_t i) { return (kind >> (5 - i)) & 1; }

/// Residual i's non-zero values are coded with Exp-Golomb of this order
/// (0..7), chosen per delta: a snapshot of large corrections spends fewer
/// bits on their magnitude prefixes.
inline constexpr int kOrderBits = 3;
inline constexpr int kMaxOrder = (1 << kOrderBits) - 1;

/// How one delta codes its correction records: the kinds it uses, most
/// frequent first (a record names its kind by its place here, so the
/// commonest costs 1 bit), and the Exp-Golomb order of each residual.
struct CorrectionCode {
  std::vector<RecordKind> kinds;
  std::array<int, 6> orders{};
};

/// A non-zero residual folded to 0, 1, 2, ...: 1, -1, 2, -2, 3, ... (zero
/// needs no code: the kind says which residuals are zero).
inline std::uint64_t foldNonZero(std::int64_t residual) {
  return residual > 0 ? 2 * std::uint64_t(residual - 1) : 2 * std::uint64_t(-residual) - 1;
}
inline std::int64_t unfoldNonZero(std::uint64_t folded) {
  const auto magnitude = std::int64_t(folded / 2) + 1;
  return folded % 2 == 0 ? magnitude : -magnitude;
}

}  // namespace impulse::wire::quantized
