#include "dashes.h"

#include <algorithm>
#include <cmath>

namespace impulse::viewer {

void dashesAlong(std::span<const PixelPoint> path, bool closed, float dash, float gap,
                 std::vector<PixelPoint>& out) {
  out.clear();
  if (path.size() < 2 || dash <= 0 || gap < 0) return;
  // Where in the dash-gap period the next edge starts.
  float phase = 0;
  const std::size_t edges = closed ? path.size() : path.size() - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const PixelPoint a = path[i];
    const PixelPoint b = path[(i + 1) % path.size()];
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    const auto at = [&](float s) {
      return PixelPoint{a.x + (b.x - a.x) * s / length, a.y + (b.y - a.y) * s / length};
    };
    float s = 0;
    while (s < length) {
      if (phase < dash) {
        const float end = std::min(length, s + dash - phase);
        out.push_back(at(s));
        out.push_back(at(end));
        phase += end - s;
        s = end;
      } else {
        const float end = std::min(length, s + dash + gap - phase);
        phase += end - s;
        s = end;
      }
      if (phase >= dash + gap) phase = 0;
    }
  }
}

}  // namespace impulse::viewer
