#include "impulse/wire/bit_writer.h"

#include <algorithm>
#include <bit>

namespace impulse::wire {

void BitWriter::writeBits(std::uint64_t value, int count) {
  // A byte at a time: the rest of the last byte, then whole ones.
  while (count > 0) {
    const int used = int(bitCount_ % 8);
    if (used == 0) bytes_.push_back('\0');
    const int room = 8 - used;
    const int take = std::min(room, count);
    const unsigned bits = unsigned(value >> (count - take)) & ((1u << take) - 1);
    bytes_.back() = char(std::uint8_t(bytes_.back()) | (bits << (room - take)));
    count -= take;
    bitCount_ += std::size_t(take);
  }
}

void BitWriter::writeExpGolomb(std::uint64_t value) {
  const std::uint64_t shifted = value + 1;
  const int width = std::bit_width(shifted);
  writeBits(0, width - 1);
  writeBits(shifted, width);
}

void BitWriter::writeExpGolomb(std::uint64_t value, int order) {
  writeExpGolomb(value >> order);
  writeBits(value, order);
}

int BitWriter::expGolombLength(std::uint64_t value, int order) {
  return 2 * std::bit_width((value >> order) + 1) - 1 + order;
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
