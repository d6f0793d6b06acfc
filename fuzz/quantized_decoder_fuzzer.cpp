// libFuzzer target: the compact snapshot decoder every quantized client runs
// on what a server sends. The decoder starts from a key frame of a small
// world, then reads the input as a snapshot's quantized_bodies: the first
// byte says whether the snapshot is full and how many ids it adds. Checked:
// an error is named and forgets the baseline; a success reports finite
// states, one per body at most, and leaves a baseline with the coded count.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "impulse/wire/quantized_decoder.h"
#include "impulse/wire/quantized_encoder.h"
#include "impulse/world.h"

namespace {

namespace q = impulse::wire::quantized;

struct Primed {
  std::string keyFrame;
  std::vector<std::uint32_t> ids;
};

// A key frame of six falling circles, made once.
const Primed& primed() {
  static const Primed value = [] {
    impulse::World world;
    for (int i = 0; i < 6; ++i) {
      world.createCircle(impulse::Vec2(impulse::Real(i), impulse::Real(2 + i)), impulse::Real(0.3));
    }
    world.step(impulse::Real(1) / 60);
    Primed made;
    for (const impulse::BodyId id : world.bodyIds()) made.ids.push_back(id.value);
    q::Encoder encoder;
    encoder.reset(world, 1);
    q::SnapshotLists lists;
    lists.tick = 1;
    lists.integration = q::integrationOf(60, 4, world.gravity());
    lists.added = made.ids;
    made.keyFrame = encoder.keyFrame(world, lists);
    return made;
  }();
  return value;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const Primed& start = primed();
  q::Decoder decoder;
  std::vector<impulse::BodyState> moved;
  FUZZ_CHECK(!decoder.decode(start.keyFrame, true, {}, start.ids, moved));

  const bool full = (data[0] & 1) != 0;
  std::vector<std::uint32_t> added;
  for (unsigned i = 0; i < ((data[0] >> 1) & 7u); ++i) added.push_back(100 + i);
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  const auto error = decoder.decode(bytes, full, {}, added, moved);
  if (error) {
    FUZZ_CHECK(error->rfind("quantized_bodies: ", 0) == 0);
    FUZZ_CHECK(!decoder.baseline().valid && moved.empty());
    return 0;
  }
  FUZZ_CHECK(moved.size() <= decoder.baseline().bodies.size());
  for (const impulse::BodyState& state : moved) {
    FUZZ_CHECK(std::isfinite(state.position.x()) && std::isfinite(state.position.y()));
    FUZZ_CHECK(std::isfinite(state.angle) && std::isfinite(state.angularVelocity));
    FUZZ_CHECK(decoder.baseline().bodies.count(state.id.value) == 1);
  }
  return 0;
}
