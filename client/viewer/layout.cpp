#include "layout.h"

#include <algorithm>

namespace impulse::viewer {

namespace {

constexpr float kMinPanelWidth = 230;
constexpr float kMaxPanelWidth = 340;

}  // namespace

WindowLayout layoutWindow(int windowWidth, int windowHeight) {
  const float w = float(std::max(windowWidth, 1));
  const float h = float(std::max(windowHeight, 1));
  // In a very narrow window the scene still keeps half of the width.
  const float panel = std::min(std::clamp(w * 0.27f, kMinPanelWidth, kMaxPanelWidth), w / 2);
  return {PixelRect{0, 0, w - panel, h}, PixelRect{w - panel, 0, panel, h}};
}

}  // namespace impulse::viewer
