#include "preset_catalogue.h"

#include "impulse/world.h"

namespace impulse::viewer {

std::vector<PresetInfo> presetCatalogue() {
  std::vector<PresetInfo> presets;
  World scratch;
  for (int id = 0; id < kPresetCount; ++id) {
    if (auto info = loadPreset(scratch, id)) presets.push_back(std::move(*info));
  }
  return presets;
}

}  // namespace impulse::viewer
