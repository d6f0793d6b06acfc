// Material colours: every pair of the eight materials (docs/product.md's five and
// issue 15's STONE, GLASS, FOAM) tells apart at a glance, and none is the
// sleep outline's violet.
#include "palette.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace impulse::viewer {
namespace {

int largestChannelGap(Colour a, Colour b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

TEST(Palette, EveryTwoMaterialsDifferByAtLeast40InSomeChannel) {
  auto name = [](int index) { return materialProperties(*materialFromIndex(index)).name; };
  for (int i = 0; i < kMaterialCount; ++i) {
    const Colour a = materialColour(*materialFromIndex(i));
    EXPECT_GE(largestChannelGap(a, palette::kSleep), 40) << name(i);
    for (int j = i + 1; j < kMaterialCount; ++j) {
      const Colour b = materialColour(*materialFromIndex(j));
      EXPECT_GE(largestChannelGap(a, b), 40) << name(i) << " and " << name(j);
    }
  }
}

}  // namespace
}  // namespace impulse::viewer
