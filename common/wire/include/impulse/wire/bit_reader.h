#pragma once
/// Bits read most significant first from bytes: the reading half of the
/// compact snapshot codec. Reading past the end, or an Exp-Golomb code longer
/// than 63 bits, marks the reader failed and yields zeros from then on, so a
/// decoder can read on and check `failed()` where it must.

#include <cstdint>
#include <string_view>

namespace impulse::wire {

class BitReader {
 public:
  explicit BitReader(std::string_view bytes) : bytes_(bytes) {}

  std::uint64_t readBits(int count);
  bool readBit() { return readBits(1) != 0; }
  std::uint64_t readExpGolomb();
  /// Exp-Golomb of order k (BitWriter::writeExpGolomb); 2^63 or more fails.
  std::uint64_t readExpGolomb(int order);
  std::int64_t readSigned();

  bool failed() const { return failed_; }
  std::size_t bitsLeft() const { return bytes_.size() * 8 - position_; }

 private:
  std::string_view bytes_;
  std::size_t position_ = 0;
  bool failed_ = false;
};

}  // namespace impulse::wire
