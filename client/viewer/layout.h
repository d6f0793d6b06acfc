#pragma once
/// Where things go in the window: the scene viewport on the left, the side
/// panel (every text and widget) on the right. Nothing of the panel is ever
/// drawn inside the scene viewport.

#include "view_transform.h"

namespace impulse::viewer {

struct WindowLayout {
  PixelRect scene;
  PixelRect panel;
};

/// The panel takes about a quarter of the width, within readable bounds.
WindowLayout layoutWindow(int windowWidth, int windowHeight);

}  // namespace impulse::viewer
