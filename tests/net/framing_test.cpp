// Delimited framing: compatible with protobuf's own delimited format, split
// anywhere, and refusing oversized or malformed length headers before
// allocating anything.
#include "impulse/wire/framing.h"

#include <google/protobuf/io/zero_copy_stream_impl_lite.h>
#include <google/protobuf/util/delimited_message_util.h>
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "impulse.pb.h"

namespace impulse::wire {
namespace {

v1::ClientMessage sampleMessage(std::uint64_t id) {
  v1::ClientMessage message;
  message.set_request_id(id);
  auto* spawn = message.mutable_spawn_polygon();
  for (int i = 0; i < 5; ++i) {
    auto* v = spawn->add_vertices();
    v->set_x(0.25 * i + double(id));
    v->set_y(-1.5 * i);
  }
  spawn->mutable_options()->set_material(v1::RUBBER);
  return message;
}

// Feeds `stream` in pieces of the given sizes (cycled) and collects frames.
std::vector<std::string> readAll(FrameReader& reader, const std::string& stream,
                                 const std::vector<std::size_t>& pieces) {
  std::vector<std::string> frames;
  std::size_t offset = 0;
  std::size_t piece = 0;
  while (offset < stream.size()) {
    const std::size_t size = std::min(pieces[piece++ % pieces.size()], stream.size() - offset);
    std::span<const char> chunk(stream.data() + offset, size);
    offset += size;
    while (!chunk.empty()) {
      const auto result = reader.feed(chunk);
      EXPECT_NE(result.status, FrameReader::Status::Error) << reader.error();
      if (result.status == FrameReader::Status::Error) return frames;
      chunk = chunk.subspan(result.consumed);
      if (result.status == FrameReader::Status::Frame) frames.emplace_back(reader.frame());
    }
  }
  return frames;
}

FrameReader::Result feedString(FrameReader& reader, const std::string& bytes) {
  return reader.feed(std::span<const char>(bytes.data(), bytes.size()));
}

TEST(Framing, EncodedFrameMatchesProtobufDelimitedFormat) {
  const auto message = sampleMessage(7);
  std::string theirs;
  {
    google::protobuf::io::StringOutputStream stream(&theirs);
    ASSERT_TRUE(google::protobuf::util::SerializeDelimitedToZeroCopyStream(message, &stream));
  }
  EXPECT_EQ(encodeFrame(message), theirs);
}

TEST(Framing, ProtobufParsesOurFramesBackToBack) {
  std::string stream;
  for (std::uint64_t id = 1; id <= 3; ++id) appendFrame(stream, sampleMessage(id));
  google::protobuf::io::ArrayInputStream input(stream.data(), int(stream.size()));
  for (std::uint64_t id = 1; id <= 3; ++id) {
    v1::ClientMessage parsed;
    bool clean_eof = false;
    ASSERT_TRUE(
        google::protobuf::util::ParseDelimitedFromZeroCopyStream(&parsed, &input, &clean_eof));
    EXPECT_EQ(parsed.request_id(), id);
    EXPECT_EQ(parsed.spawn_polygon().vertices_size(), 5);
  }
}

TEST(Framing, ReassemblesFramesSplitAtEveryByteBoundary) {
  std::string stream;
  std::vector<std::string> expected;
  for (std::uint64_t id = 1; id <= 20; ++id) {
    expected.push_back(sampleMessage(id).SerializeAsString());
    appendFrame(stream, sampleMessage(id));
  }
  for (std::size_t piece : {1, 2, 3, 7, 64, 100000}) {
    FrameReader reader;
    EXPECT_EQ(readAll(reader, stream, {piece}), expected) << "piece size " << piece;
    EXPECT_TRUE(reader.atFrameBoundary());
  }
  std::mt19937 random(42);
  std::vector<std::size_t> pieces;
  for (int i = 0; i < 50; ++i) pieces.push_back(1 + random() % 40);
  FrameReader reader;
  EXPECT_EQ(readAll(reader, stream, pieces), expected);
}

TEST(Framing, EmptyMessageIsAZeroLengthFrame) {
  v1::ClientMessage empty;
  const std::string frame = encodeFrame(empty);
  ASSERT_EQ(frame, std::string(1, '\0'));
  FrameReader reader;
  const auto result = feedString(reader, frame);
  EXPECT_EQ(result.status, FrameReader::Status::Frame);
  EXPECT_EQ(result.consumed, 1u);
  EXPECT_TRUE(reader.frame().empty());
}

TEST(Framing, FrameAtTheCapIsAcceptedAndOneByteMoreIsRefused) {
  constexpr std::size_t kCap = 1000;
  {
    FrameReader reader(kCap);
    const std::string stream = encodeVarint(kCap) + std::string(kCap, 'x');
    const auto result = feedString(reader, stream);
    EXPECT_EQ(result.status, FrameReader::Status::Frame);
    EXPECT_EQ(reader.frame().size(), kCap);
  }
  {
    FrameReader reader(kCap);
    const auto result = feedString(reader, encodeVarint(kCap + 1));
    EXPECT_EQ(result.status, FrameReader::Status::Error);
    EXPECT_NE(reader.error().find("exceeds the limit of 1000 bytes"), std::string::npos)
        << reader.error();
  }
}

TEST(Framing, HugeLengthIsRefusedFromItsFirstBytes) {
  // Refused as soon as the partial value passes the cap (the low 28 bits are
  // set), so nothing is allocated and the rest of the header is never needed.
  const std::string header = encodeVarint((std::uint64_t(1) << 62) | 0xfffffff);
  FrameReader reader;
  const auto result = feedString(reader, header.substr(0, 4));
  EXPECT_EQ(result.status, FrameReader::Status::Error);
  EXPECT_NE(reader.error().find("exceeds the limit"), std::string::npos) << reader.error();
}

TEST(Framing, VarintLongerThanTenBytesIsRefused) {
  // Zero-valued continuation bytes keep the value under any cap, so only the
  // length rule can catch this.
  const std::string header = std::string(10, char(0x80)) + char(0x00);
  FrameReader reader;
  const auto result = feedString(reader, header);
  EXPECT_EQ(result.status, FrameReader::Status::Error);
  EXPECT_NE(reader.error().find("longer than 10 bytes"), std::string::npos) << reader.error();
}

TEST(Framing, NonCanonicalTenByteVarintIsStillAFrameLength) {
  // 3 encoded with padding bytes: legal protobuf, so legal here.
  std::string header = {char(0x83)};
  header += std::string(8, char(0x80));
  header += char(0x00);
  ASSERT_EQ(header.size(), 10u);
  FrameReader reader;
  const auto result = feedString(reader, header + "abc");
  EXPECT_EQ(result.status, FrameReader::Status::Frame) << reader.error();
  EXPECT_EQ(reader.frame(), "abc");
}

TEST(Framing, ErrorIsSticky) {
  FrameReader reader(10);
  EXPECT_EQ(feedString(reader, encodeVarint(11)).status, FrameReader::Status::Error);
  const auto again = feedString(reader, encodeVarint(1) + "a");
  EXPECT_EQ(again.status, FrameReader::Status::Error);
  EXPECT_EQ(again.consumed, 0u);
}

TEST(Framing, TruncationIsDescribed) {
  FrameReader reader;
  EXPECT_TRUE(reader.atFrameBoundary());
  EXPECT_EQ(feedString(reader, encodeVarint(100) + std::string(40, 'y')).status,
            FrameReader::Status::NeedMore);
  EXPECT_FALSE(reader.atFrameBoundary());
  EXPECT_EQ(reader.truncationMessage(), "stream ended inside a frame: 40 of 100 bytes received");

  FrameReader header_only;
  EXPECT_EQ(feedString(header_only, std::string(1, char(0x81))).status,
            FrameReader::Status::NeedMore);
  EXPECT_EQ(header_only.truncationMessage(), "stream ended inside a frame length");
}

TEST(Framing, ParseFrameRejectsGarbage) {
  v1::ClientMessage message;
  // Field 1 declared as a length-delimited field that runs past the end.
  EXPECT_FALSE(parseFrame(std::string("\x0a\x7f", 2), message));
  EXPECT_TRUE(parseFrame(sampleMessage(3).SerializeAsString(), message));
  EXPECT_EQ(message.request_id(), 3u);
}

}  // namespace
}  // namespace impulse::wire
