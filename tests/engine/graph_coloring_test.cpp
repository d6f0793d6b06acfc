// The solver's shared graph colouring: constraints of one colour never share
// an awake body, static bodies never block, and the sort keeps row order.

#include "graph_coloring.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

namespace impulse {
namespace {

TEST(GraphColoring, NoTwoConstraintsOfAColourShareAnAwakeBody) {
  // A chain 1-2-3-4 plus a fan around body 1, and links to the static dummy.
  std::vector<std::pair<int, int>> links = {{1, 2}, {2, 3}, {3, 4}, {1, 3}, {1, 4}, {0, 1}, {0, 2}, {0, 1}};
  GraphColoring coloring;
  coloring.reset(5);
  std::vector<std::set<int>> bodiesOf(GraphColoring::kColorCount);
  for (auto [a, b] : links) {
    int color = coloring.take(a, b);
    ASSERT_LT(color, GraphColoring::kOverflow);
    for (int body : {a, b}) {
      if (body == 0) continue;
      EXPECT_TRUE(bodiesOf[color].insert(body).second) << "body " << body << " twice in colour " << color;
    }
  }
}

TEST(GraphColoring, StaticDummyNeverBlocks) {
  GraphColoring coloring;
  coloring.reset(2);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(coloring.take(0, 0), 0);
}

TEST(GraphColoring, BodyInMoreThanSixtyFourConstraints_Overflows) {
  GraphColoring coloring;
  coloring.reset(2);
  for (int i = 0; i < GraphColoring::kColorCount; ++i) EXPECT_EQ(coloring.take(1, 0), i);
  EXPECT_EQ(coloring.take(0, 1), GraphColoring::kOverflow);
}

TEST(GraphColoring, SortByColour_IsStableWithOverflowLast) {
  std::vector<std::int32_t> colorOf = {2, 0, GraphColoring::kOverflow, 0, 2, 1};
  std::vector<std::int32_t> order;
  ColorStarts start = sortByColor(colorOf, order);
  EXPECT_EQ(order, (std::vector<std::int32_t>{1, 3, 5, 0, 4, 2}));
  EXPECT_EQ(start[0], 0);
  EXPECT_EQ(start[1], 2);
  EXPECT_EQ(start[2], 3);
  EXPECT_EQ(start[3], 5);
  EXPECT_EQ(start[GraphColoring::kOverflow], 5);
  EXPECT_EQ(start[GraphColoring::kOverflow + 1], 6);
}

}  // namespace
}  // namespace impulse
