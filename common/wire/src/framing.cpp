#include "impulse/wire/framing.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/message_lite.h>

#include <algorithm>
#include <limits>

namespace impulse::wire {

namespace {

// A payload buffer that grew for one large frame is released afterwards, so
// an idle connection holds little memory.
constexpr std::size_t kRetainedBufferBytes = 64 * 1024;

}  // namespace

FrameReader::FrameReader(std::size_t maxFrameBytes) : maxFrameBytes_(maxFrameBytes) {}

FrameReader::Result FrameReader::fail(std::string message) {
  error_ = std::move(message);
  body_.clear();
  body_.shrink_to_fit();
  return {Status::Error, 0};
}

FrameReader::Result FrameReader::feed(std::span<const char> bytes) {
  if (!error_.empty()) return {Status::Error, 0};
  if (frameReady_) {
    frameReady_ = false;
    if (body_.capacity() > kRetainedBufferBytes) {
      body_ = std::string();
    } else {
      body_.clear();
    }
  }

  std::size_t used = 0;
  while (!inBody_) {
    if (used == bytes.size()) return {Status::NeedMore, used};
    const auto byte = static_cast<std::uint8_t>(bytes[used++]);
    const int shift = 7 * headerBytes_;
    ++headerBytes_;
    if (headerBytes_ == kMaxVarintBytes && byte > 1) {
      // The tenth byte may only carry bit 63; anything else is not a 64-bit
      // varint (a continuation bit here makes it longer than 10 bytes).
      return fail((byte & 0x80) != 0 ? "frame length varint is longer than 10 bytes"
                                     : "frame length varint overflows 64 bits");
    }
    length_ |= std::uint64_t(byte & 0x7f) << shift;
    // Later bytes only add higher bits, so a partial length over the cap is
    // already over it.
    if (length_ > maxFrameBytes_) {
      return fail((byte & 0x80) != 0
                      ? "frame length exceeds the limit of " + std::to_string(maxFrameBytes_) +
                            " bytes"
                      : "frame of " + std::to_string(length_) + " bytes exceeds the limit of " +
                            std::to_string(maxFrameBytes_) + " bytes");
    }
    if ((byte & 0x80) == 0) {
      inBody_ = true;
      received_ = 0;
      // Grown as bytes arrive, not sized from the header: a peer that
      // announces a large frame and sends little holds little memory.
      body_.clear();
    }
  }

  const std::size_t take = std::min(bytes.size() - used, std::size_t(length_) - received_);
  body_.append(bytes.data() + used, take);
  received_ += take;
  used += take;
  if (received_ < length_) return {Status::NeedMore, used};

  inBody_ = false;
  frameReady_ = true;
  headerBytes_ = 0;
  length_ = 0;
  received_ = 0;
  return {Status::Frame, used};
}

bool FrameReader::atFrameBoundary() const { return headerBytes_ == 0 && !inBody_; }

std::string FrameReader::truncationMessage() const {
  if (inBody_) {
    return "stream ended inside a frame: " + std::to_string(received_) + " of " +
           std::to_string(length_) + " bytes received";
  }
  if (headerBytes_ > 0) return "stream ended inside a frame length";
  return {};
}

void appendFrame(std::string& out, const google::protobuf::MessageLite& message) {
  using google::protobuf::io::CodedOutputStream;
  const std::size_t size = message.ByteSizeLong();
  const std::size_t header = CodedOutputStream::VarintSize64(size);
  const std::size_t start = out.size();
  out.resize(start + header + size);
  auto* p = reinterpret_cast<std::uint8_t*>(out.data() + start);
  p = CodedOutputStream::WriteVarint64ToArray(size, p);
  message.SerializeWithCachedSizesToArray(p);
}

std::string encodeFrame(const google::protobuf::MessageLite& message) {
  std::string out;
  appendFrame(out, message);
  return out;
}

std::shared_ptr<const std::string> encodeSharedFrame(const google::protobuf::MessageLite& message) {
  return std::make_shared<const std::string>(encodeFrame(message));
}

std::string encodeVarint(std::uint64_t value) {
  std::string out;
  do {
    std::uint8_t byte = value & 0x7f;
    value >>= 7;
    if (value != 0) byte |= 0x80;
    out.push_back(static_cast<char>(byte));
  } while (value != 0);
  return out;
}

bool parseFrame(std::string_view payload, google::protobuf::MessageLite& message) {
  if (payload.size() > std::size_t(std::numeric_limits<int>::max())) return false;
  return message.ParseFromArray(payload.data(), static_cast<int>(payload.size()));
}

}  // namespace impulse::wire
