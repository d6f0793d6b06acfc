#include "impulse/wire/bit_writer.h"

#include <bit>

namespace impulse::wire {

void BitWriter::writeBits(std::uint64_t value, int count) {
  for (int i = count - 1; i >= 0; --i) {
    if (bitCount_ % 8 == 0) bytes_.push_back('\0');
    if ((value >> i) & 1) bytes_.back() = char(std::uint8_t(bytes_.back()) | (0x80u >> (bitCount_ % 8)));
    ++bitCount_;
  }
}

void BitWriter::writeExpGolomb(std::uint64_t value) {
  const std::uint64_t shifted = value + 1;
  const int width = std::bit_width(shifted);
  writeBits(0, width - 1);
  writeBits(shifted, width);
}

void BitWriter::writeSigned(std::int64_t value) {
  const std::uint64_t zigzag =
      value < 0 ? (std::uint64_t(-(value + 1)) << 1) | 1 : std::uint64_t(value) << 1;
  writeExpGolomb(zigzag);
}

void BitWriter::clear() {
  bytes_.clear();
  bitCount_ = 0;
}

}  // namespace impulse::wire
