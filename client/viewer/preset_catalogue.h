#pragma once
/// The presets the scene picker offers, with their titles and explanations
/// as the presets themselves write them (each built once in a scratch
/// world when the viewer starts), so the picker never holds a copy that
/// could go stale.

#include <vector>

#include "impulse/scenes/presets.h"

namespace impulse::viewer {

/// Every preset, 0 to kPresetCount - 1, in order.
std::vector<PresetInfo> presetCatalogue();

}  // namespace impulse::viewer
