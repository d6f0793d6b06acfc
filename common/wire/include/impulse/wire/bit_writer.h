#pragma once
/// Bits appended most significant first into bytes: the writing half of the
/// compact snapshot codec (docs/snapshots.md).

#include <cstdint>
#include <string>

namespace impulse::wire {

class BitWriter {
 public:
  /// The low `count` bits of `value`, highest first (count 0..64).
  void writeBits(std::uint64_t value, int count);
  void writeBit(bool bit) { writeBits(bit ? 1 : 0, 1); }
  /// Order-0 Exp-Golomb: n zeros, then value + 1 in n + 1 bits. Small values
  /// are short (0: 1 bit, 1-2: 3 bits, 3-6: 5 bits). value < 2^63.
  void writeExpGolomb(std::uint64_t value);
  /// Exp-Golomb of order k: value >> k as above, then the low k bits of
  /// value (k 0..62). Suits values that are rarely below 2^k.
  void writeExpGolomb(std::uint64_t value, int order);
  /// The bits writeExpGolomb(value, order) takes.
  static int expGolombLength(std::uint64_t value, int order);
  /// Zigzag (0, -1, 1, -2, ... -> 0, 1, 2, 3, ...), then Exp-Golomb.
  /// |value| < 2^62.
  void writeSigned(std::int64_t value);

  std::size_t bitCount() const { return bitCount_; }
  /// The bytes written, the last one padded with zero bits.
  const std::string& bytes() const { return bytes_; }
  /// Empties the writer, keeping its capacity.
  void clear();

 private:
  std::string bytes_;
  std::size_t bitCount_ = 0;
};

}  // namespace impulse::wire
