// The scene loader against any bytes (issue 30): a scene is loaded or
// refused with a reason and the world left as it was; a loaded world is
// sane, and reloads from its own save bit for bit, before and after a few
// steps ("a world always reloads its own save").
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "quiet_protobuf.h"
#include "world_invariants.h"
#include "impulse/server/simulation.h"
#include "impulse/wire/scene_convert.h"

namespace {

using impulse::server::Simulation;

// A small world, so that inputs of a few KiB reach its slot limits.
Simulation makeSimulation() {
  impulse::server::SimulationSettings settings;
  settings.maxBodies = 64;
  settings.paused = true;
  return Simulation(settings);
}

void checkReloadsItsOwnSave(Simulation& simulation) {
  const std::string saved = impulse::wire::saveScene(simulation.world());
  FUZZ_CHECK(simulation.loadScene(saved).ok());
  FUZZ_CHECK(impulse::wire::saveScene(simulation.world()) == saved);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Simulation simulation = makeSimulation();
  const std::string before = impulse::wire::saveScene(simulation.world());
  const auto loaded =
      simulation.loadScene(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!loaded.ok()) {
    FUZZ_CHECK(!loaded.error.empty());
    FUZZ_CHECK(impulse::wire::saveScene(simulation.world()) == before);
    return 0;
  }
  checkWorldSane(simulation.world());
  checkReloadsItsOwnSave(simulation);
  for (int i = 0; i < 4; ++i) simulation.step();
  checkWorldSane(simulation.world());
  checkReloadsItsOwnSave(simulation);
  return 0;
}
