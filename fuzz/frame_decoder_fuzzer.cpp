// libFuzzer target: the frame decoder the server runs on every byte a peer
// sends. The first input byte picks the piece size the stream arrives in (the
// decoder must not care), the rest is the stream. Checked: a frame never
// exceeds the cap, an error is final, every frame that parses survives a
// round trip through the encoder, and nothing a peer sends crashes or leaks.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "fuzz_check.h"
#include "quiet_protobuf.h"
#include "impulse.pb.h"
#include "impulse/wire/framing.h"

namespace {

constexpr std::size_t kMaxFrameBytes = 4096;

// Encodes a parsed message again and decodes it: the same message comes back.
void checkRoundTrip(const impulse::v1::ClientMessage& message) {
  const std::string frame = impulse::wire::encodeFrame(message);
  impulse::wire::FrameReader reader(frame.size() + 16);
  const auto result = reader.feed(std::span<const char>(frame.data(), frame.size()));
  FUZZ_CHECK(result.status == impulse::wire::FrameReader::Status::Frame);
  FUZZ_CHECK(result.consumed == frame.size());
  impulse::v1::ClientMessage again;
  FUZZ_CHECK(impulse::wire::parseFrame(reader.frame(), again));
  FUZZ_CHECK(again.SerializeAsString() == message.SerializeAsString());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t piece = std::size_t(data[0]) + 1;
  const char* stream = reinterpret_cast<const char*>(data + 1);
  const std::size_t length = size - 1;

  impulse::wire::FrameReader reader(kMaxFrameBytes);
  std::size_t offset = 0;
  bool failed = false;
  while (offset < length && !failed) {
    const std::size_t end = std::min(length, offset + piece);
    std::span<const char> chunk(stream + offset, end - offset);
    while (!chunk.empty()) {
      const auto result = reader.feed(chunk);
      FUZZ_CHECK(result.consumed <= chunk.size());
      chunk = chunk.subspan(result.consumed);
      if (result.status == impulse::wire::FrameReader::Status::Error) {
        FUZZ_CHECK(!reader.error().empty());
        failed = true;
        break;
      }
      if (result.status == impulse::wire::FrameReader::Status::NeedMore) {
        FUZZ_CHECK(chunk.empty());
        break;
      }
      FUZZ_CHECK(reader.frame().size() <= kMaxFrameBytes);
      impulse::v1::ClientMessage message;
      if (impulse::wire::parseFrame(reader.frame(), message)) checkRoundTrip(message);
    }
    offset = end;
  }
  if (failed) {
    // The stream cannot be resynchronised: every later feed fails the same way.
    const char more[1] = {0};
    FUZZ_CHECK(reader.feed(std::span<const char>(more, 1)).status ==
               impulse::wire::FrameReader::Status::Error);
  } else if (!reader.atFrameBoundary()) {
    FUZZ_CHECK(!reader.truncationMessage().empty());
  }
  return 0;
}
