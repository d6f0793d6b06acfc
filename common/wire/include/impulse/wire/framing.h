#pragma once
/// Varint-delimited framing: protobuf's standard delimited format (each
/// message preceded by its byte length as a base-128 varint), read
/// incrementally from a byte stream with a frame size cap.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace google::protobuf {
class MessageLite;
}

namespace impulse::wire {

/// The protocol version this code speaks (Hello/Welcome.protocol_version).
inline constexpr std::uint32_t kProtocolVersion = 1;
/// Default cap on one frame's payload (docs/protocol.md: 1 MiB).
inline constexpr std::size_t kDefaultMaxFrameBytes = std::size_t(1) << 20;
/// A base-128 varint of a 64-bit value never needs more bytes than this.
inline constexpr int kMaxVarintBytes = 10;

/// Decodes frames from a stream fed in arbitrary pieces. Memory use is bounded
/// by the cap: the payload buffer is sized from the length header only after
/// the length was checked against it.
///
/// Usage: feed() the bytes received; it consumes them up to the end of one
/// frame at most. On Frame, frame() holds the payload until the next feed();
/// feed the unconsumed rest again. On Error the stream cannot be resynced:
/// error() says why and every later feed() fails the same way.
class FrameReader {
 public:
  enum class Status { NeedMore, Frame, Error };
  struct Result {
    Status status = Status::NeedMore;
    std::size_t consumed = 0;
  };

  explicit FrameReader(std::size_t maxFrameBytes = kDefaultMaxFrameBytes);

  Result feed(std::span<const char> bytes);
  /// Payload of the frame completed by the last feed() that returned Frame.
  std::string_view frame() const { return body_; }
  const std::string& error() const { return error_; }
  /// True when no partial frame is buffered: the stream may end here.
  bool atFrameBoundary() const;
  /// Describes the partial frame a stream that ended now would cut off.
  std::string truncationMessage() const;
  std::size_t maxFrameBytes() const { return maxFrameBytes_; }

 private:
  Result fail(std::string message);

  std::size_t maxFrameBytes_;
  std::uint64_t length_ = 0;
  int headerBytes_ = 0;
  bool inBody_ = false;
  bool frameReady_ = false;
  std::string body_;
  std::size_t received_ = 0;
  std::string error_;
};

/// Appends `message` as one frame (varint length, then the bytes) to `out`.
void appendFrame(std::string& out, const google::protobuf::MessageLite& message);
/// `message` as one frame.
std::string encodeFrame(const google::protobuf::MessageLite& message);
/// One frame, serialised once, to be shared by every connection that sends it.
std::shared_ptr<const std::string> encodeSharedFrame(const google::protobuf::MessageLite& message);
/// The varint encoding of `value` (for tests and hand-built frames).
std::string encodeVarint(std::uint64_t value);

/// Parses one frame payload. False when the bytes are not a valid message.
bool parseFrame(std::string_view payload, google::protobuf::MessageLite& message);

}  // namespace impulse::wire
