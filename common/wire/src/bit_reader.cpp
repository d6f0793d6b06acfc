#include "impulse/wire/bit_reader.h"

#include <algorithm>

namespace impulse::wire {

std::uint64_t BitReader::readBits(int count) {
  if (failed_ || std::size_t(count) > bitsLeft()) {
    failed_ = true;
    return 0;
  }
  // A byte at a time: the rest of the current byte, then whole ones.
  std::uint64_t value = 0;
  while (count > 0) {
    const int used = int(position_ % 8);
    const int take = std::min(8 - used, count);
    const unsigned byte = std::uint8_t(bytes_[position_ / 8]);
    value = (value << take) | ((byte >> (8 - used - take)) & ((1u << take) - 1));
    count -= take;
    position_ += std::size_t(take);
  }
  return value;
}

std::uint64_t BitReader::readExpGolomb() {
  // The writer never sends a value of 2^63 or more: 63 zeros or more is hostile.
  int zeros = 0;
  while (!failed_ && !readBit()) {
    if (++zeros > 62) failed_ = true;
  }
  if (failed_) return 0;
  const std::uint64_t shifted = (std::uint64_t(1) << zeros) | readBits(zeros);
  return failed_ ? 0 : shifted - 1;
}

std::uint64_t BitReader::readExpGolomb(int order) {
  const std::uint64_t high = readExpGolomb();
  // Values of 2^63 or more are never written either.
  if (order > 0 && (high >> (63 - order)) != 0) failed_ = true;
  const std::uint64_t low = readBits(order);
  return failed_ ? 0 : (high << order) | low;
}

std::int64_t BitReader::readSigned() {
  const std::uint64_t zigzag = readExpGolomb();
  const auto magnitude = std::int64_t(zigzag >> 1);
  return (zigzag & 1) ? -magnitude - 1 : magnitude;
}

}  // namespace impulse::wire
