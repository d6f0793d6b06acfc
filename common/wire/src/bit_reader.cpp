#include "impulse/wire/bit_reader.h"

namespace impulse::wire {

std::uint64_t BitReader::readBits(int count) {
  if (failed_ || std::size_t(count) > bitsLeft()) {
    failed_ = true;
    return 0;
  }
  std::uint64_t value = 0;
  for (int i = 0; i < count; ++i, ++position_) {
    const unsigned byte = std::uint8_t(bytes_[position_ / 8]);
    value = (value << 1) | ((byte >> (7 - position_ % 8)) & 1);
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

std::int64_t BitReader::readSigned() {
  const std::uint64_t zigzag = readExpGolomb();
  const auto magnitude = std::int64_t(zigzag >> 1);
  return (zigzag & 1) ? -magnitude - 1 : magnitude;
}

}  // namespace impulse::wire
