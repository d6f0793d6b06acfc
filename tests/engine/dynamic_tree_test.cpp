#include "impulse/dynamic_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

namespace impulse {
namespace {

AABB makeBox(Real x, Real y, Real halfWidth, Real halfHeight) {
  return {Vec2(x - halfWidth, y - halfHeight), Vec2(x + halfWidth, y + halfHeight)};
}

// Random boxes in a 100 m square, from a fixed seed.
class BoxSource {
 public:
  explicit BoxSource(unsigned seed) : rng_(seed) {}
  AABB box() {
    std::uniform_real_distribution<Real> position(0, 100);
    std::uniform_real_distribution<Real> half(Real(0.1), Real(2));
    return makeBox(position(rng_), position(rng_), half(rng_), half(rng_));
  }
  // Mostly jitter that stays inside the ancestors' boxes, sometimes a jump.
  AABB moved(const AABB& box) {
    std::uniform_real_distribution<Real> jitter(Real(-0.01), Real(0.01));
    std::uniform_real_distribution<Real> jump(-3, 3);
    std::bernoulli_distribution jumps(0.3);
    auto& step = jumps(rng_) ? jump : jitter;
    const Vec2 delta(step(rng_), step(rng_));
    return {box.lower + delta, box.upper + delta};
  }
  std::mt19937& rng() { return rng_; }

 private:
  std::mt19937 rng_;
};

struct Leaf {
  std::int32_t node;
  AABB box;
};

int heightLimit(int leafCount) {
  return static_cast<int>(3 * std::log2(static_cast<double>(leafCount))) + 2;
}

// `count` random leaves, user values 0, 1, ...
std::vector<Leaf> addRandomLeaves(DynamicTree& tree, BoxSource& source, int count) {
  std::vector<Leaf> leaves;
  for (int i = 0; i < count; ++i) {
    const AABB box = source.box();
    leaves.push_back({tree.createProxy(box, i), box});
  }
  return leaves;
}

std::vector<std::int32_t> queried(const DynamicTree& tree, const AABB& box) {
  std::vector<std::int32_t> found;
  tree.query(box, [&](std::int32_t node) {
    found.push_back(node);
    return true;
  });
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<std::int32_t> bruteForce(const std::vector<Leaf>& leaves, const AABB& box) {
  std::vector<std::int32_t> found;
  for (const Leaf& leaf : leaves) {
    if (leaf.box.overlaps(box)) found.push_back(leaf.node);
  }
  std::sort(found.begin(), found.end());
  return found;
}

void expectQueriesMatchBruteForce(const DynamicTree& tree, const std::vector<Leaf>& leaves,
                                  BoxSource& source) {
  int nonEmpty = 0;
  for (int i = 0; i < 200; ++i) {
    const AABB box = source.box().expanded(3);
    const std::vector<std::int32_t> expected = bruteForce(leaves, box);
    ASSERT_EQ(queried(tree, box), expected);
    nonEmpty += expected.empty() ? 0 : 1;
  }
  // The comparison must exercise real hits, not only empty sets.
  EXPECT_GT(nonEmpty, 100);
}

TEST(DynamicTree, EmptyTreeIsValidAndQueriesNothing) {
  DynamicTree tree;
  EXPECT_TRUE(tree.isValid());
  EXPECT_EQ(tree.height(), 0);
  EXPECT_EQ(tree.leafCount(), 0);
  EXPECT_TRUE(queried(tree, makeBox(0, 0, 1000, 1000)).empty());
}

TEST(DynamicTree, StaysValidAndShallow_UnderRandomInsertMoveRemove) {
  DynamicTree tree;
  BoxSource source(7);
  std::vector<Leaf> leaves = addRandomLeaves(tree, source, 1000);
  ASSERT_TRUE(tree.isValid());
  EXPECT_EQ(tree.leafCount(), 1000);
  EXPECT_LE(tree.height(), heightLimit(1000));

  for (int round = 0; round < 20; ++round) {
    for (Leaf& leaf : leaves) {
      leaf.box = source.moved(leaf.box);
      tree.moveProxy(leaf.node, leaf.box);
    }
    ASSERT_TRUE(tree.isValid()) << "round " << round;
    EXPECT_LE(tree.height(), heightLimit(1000)) << "round " << round;
  }

  std::shuffle(leaves.begin(), leaves.end(), source.rng());
  for (std::size_t i = 0; i < 500; ++i) tree.destroyProxy(leaves[i].node);
  leaves.erase(leaves.begin(), leaves.begin() + 500);
  ASSERT_TRUE(tree.isValid());
  EXPECT_EQ(tree.leafCount(), 500);
  EXPECT_LE(tree.height(), heightLimit(500));
  for (const Leaf& leaf : leaves) {
    EXPECT_EQ(tree.box(leaf.node).lower, leaf.box.lower);
    EXPECT_EQ(tree.box(leaf.node).upper, leaf.box.upper);
  }
}

TEST(DynamicTree, StaysShallow_WhenBoxesArriveSortedAlongALine) {
  // Sorted input degrades an unbalanced tree into a list.
  DynamicTree tree;
  for (int i = 0; i < 1000; ++i) tree.createProxy(makeBox(Real(i), 0, Real(0.4), Real(0.4)), i);
  ASSERT_TRUE(tree.isValid());
  EXPECT_LE(tree.height(), heightLimit(1000));
}

TEST(DynamicTree, StaysShallow_WhenBoxesAreIdenticalOrNested) {
  // The area heuristic alone would pair each new box with the root here and
  // build a list.
  DynamicTree identical;
  DynamicTree nested;
  for (int i = 0; i < 1000; ++i) {
    identical.createProxy(makeBox(0, 0, 1, 1), i);
    nested.createProxy(makeBox(0, 0, Real(1 + i), Real(1 + i)), i);
  }
  ASSERT_TRUE(identical.isValid());
  ASSERT_TRUE(nested.isValid());
  EXPECT_LE(identical.height(), heightLimit(1000));
  EXPECT_LE(nested.height(), heightLimit(1000));
}

TEST(DynamicTree, QueryReturnsExactlyTheOverlappingLeaves) {
  DynamicTree tree;
  BoxSource source(11);
  std::vector<Leaf> leaves = addRandomLeaves(tree, source, 1000);
  expectQueriesMatchBruteForce(tree, leaves, source);

  for (Leaf& leaf : leaves) {
    leaf.box = source.moved(leaf.box);
    tree.moveProxy(leaf.node, leaf.box);
  }
  std::vector<Leaf> kept;
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    if (i % 2 == 0) {
      tree.destroyProxy(leaves[i].node);
    } else {
      kept.push_back(leaves[i]);
    }
  }
  expectQueriesMatchBruteForce(tree, kept, source);
}

using LeafPair = std::pair<std::int32_t, std::int32_t>;

// Every two leaves whose boxes overlap, smaller node first, sorted.
std::vector<LeafPair> overlappingPairs(const std::vector<Leaf>& leaves) {
  std::vector<LeafPair> pairs;
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    for (std::size_t j = i + 1; j < leaves.size(); ++j) {
      if (!leaves[i].box.overlaps(leaves[j].box)) continue;
      pairs.emplace_back(std::min(leaves[i].node, leaves[j].node), std::max(leaves[i].node, leaves[j].node));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// What the walks of the tree split into at least `count` parts find, in
// the order found (smaller node first in each pair).
std::vector<LeafPair> walkedPairs(const DynamicTree& tree, std::size_t count, std::size_t* partCount = nullptr) {
  std::vector<DynamicTree::NodePair> parts;
  tree.splitLeafPairs(count, parts);
  if (partCount != nullptr) *partCount = parts.size();
  std::vector<LeafPair> pairs;
  for (const DynamicTree::NodePair& part : parts) {
    tree.forEachLeafPair(part, [&](std::int32_t a, std::int32_t b) { pairs.emplace_back(std::min(a, b), std::max(a, b)); });
  }
  return pairs;
}

TEST(DynamicTree, WalksInAnyNumberOfParts_FindEachOverlappingPairOnce) {
  DynamicTree tree;
  BoxSource source(23);
  std::vector<Leaf> leaves = addRandomLeaves(tree, source, 1500);
  for (Leaf& leaf : leaves) {
    leaf.box = source.moved(leaf.box);
    tree.enlargeProxy(leaf.node, leaf.box);
  }
  tree.rebuild();
  const std::vector<LeafPair> expected = overlappingPairs(leaves);
  ASSERT_GT(expected.size(), 1000U);  // a crowd, not a handful
  for (const std::size_t count : {std::size_t(1), std::size_t(3), std::size_t(16), std::size_t(64), std::size_t(5000)}) {
    std::size_t parts = 0;
    std::vector<LeafPair> found = walkedPairs(tree, count, &parts);
    // As many parts as asked for, while the tree has them to give (1 500
    // leaves have at least 64; not 5 000, as a leaf against a subtree is
    // one part).
    if (count <= 64) {
      EXPECT_GE(parts, count) << count;
    }
    EXPECT_GT(parts, 0U);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << "a pair found twice, " << count;
    EXPECT_EQ(found, expected) << count;
  }
  // The same tree splits and walks the same way.
  EXPECT_EQ(walkedPairs(tree, 16), walkedPairs(tree, 16));
}

TEST(DynamicTree, WalksOfTinyTrees) {
  DynamicTree tree;
  EXPECT_TRUE(walkedPairs(tree, 8).empty());
  const std::int32_t first = tree.createProxy(makeBox(0, 0, 1, 1), 0);
  EXPECT_TRUE(walkedPairs(tree, 8).empty());
  const std::int32_t second = tree.createProxy(makeBox(1.5, 0, 1, 1), 1);
  tree.createProxy(makeBox(9, 0, 1, 1), 2);
  EXPECT_EQ(walkedPairs(tree, 1), (std::vector<LeafPair>{{std::min(first, second), std::max(first, second)}}));
  EXPECT_EQ(walkedPairs(tree, 8), (std::vector<LeafPair>{{std::min(first, second), std::max(first, second)}}));
}

TEST(DynamicTree, ShiftedTree_StaysValid_HoldsEachBoxMoved_AndQueriesExactly) {
  DynamicTree tree;
  BoxSource source(23);
  std::vector<Leaf> leaves = addRandomLeaves(tree, source, 1000);
  const Vec2d offset(-40.25, 25.5);
  tree.shift(offset);
  // isValid checks every inner node's copies of its children's boxes too.
  ASSERT_TRUE(tree.isValid());
  const Vec2 move(Real(offset.x()), Real(offset.y()));
  for (Leaf& leaf : leaves) {
    const AABB moved{leaf.box.lower - move, leaf.box.upper - move};
    ASSERT_TRUE(tree.box(leaf.node).contains(moved));
    leaf.box = tree.box(leaf.node);
  }
  expectQueriesMatchBruteForce(tree, leaves, source);
}

TEST(DynamicTree, QueryStopsWhenVisitReturnsFalse) {
  DynamicTree tree;
  for (int i = 0; i < 10; ++i) tree.createProxy(makeBox(0, 0, 1, 1), i);
  int visits = 0;
  tree.query(makeBox(0, 0, 1, 1), [&](std::int32_t) {
    ++visits;
    return visits < 3;
  });
  EXPECT_EQ(visits, 3);
}

TEST(DynamicTree, QueryOrderIsIdenticalForIdenticalHistories) {
  auto visitOrder = [] {
    DynamicTree tree;
    BoxSource source(5);
    std::vector<std::int32_t> nodes;
    for (int i = 0; i < 300; ++i) nodes.push_back(tree.createProxy(source.box(), i));
    for (std::int32_t node : nodes) tree.moveProxy(node, source.moved(tree.box(node)));
    std::vector<std::int32_t> order;
    tree.query(makeBox(50, 50, 30, 30), [&](std::int32_t node) {
      order.push_back(tree.userValue(node));
      return true;
    });
    return order;
  };
  const std::vector<std::int32_t> first = visitOrder();
  EXPECT_GT(first.size(), 10U);
  EXPECT_EQ(first, visitOrder());
}

TEST(DynamicTree, NodeIndicesStayStable_AndFreedNodesAreReused) {
  DynamicTree tree;
  const std::int32_t a = tree.createProxy(makeBox(0, 0, 1, 1), 10);
  const std::int32_t b = tree.createProxy(makeBox(5, 0, 1, 1), 20);
  const std::int32_t c = tree.createProxy(makeBox(10, 0, 1, 1), 30);

  tree.moveProxy(a, makeBox(20, 20, 1, 1));
  tree.destroyProxy(b);
  EXPECT_EQ(tree.userValue(a), 10);
  EXPECT_EQ(tree.userValue(c), 30);
  EXPECT_EQ(tree.box(a).lower, Vec2(19, 19));
  EXPECT_EQ(tree.box(c).lower, Vec2(9, -1));

  // Three leaves and two internal nodes were ever live at once: a new leaf and
  // its parent fit in the freed nodes without growing the array.
  const std::int32_t d = tree.createProxy(makeBox(5, 0, 1, 1), 40);
  EXPECT_LT(d, 5);
  EXPECT_NE(d, a);
  EXPECT_NE(d, c);
  EXPECT_EQ(tree.userValue(d), 40);
  EXPECT_TRUE(tree.isValid());
  EXPECT_EQ(queried(tree, makeBox(5, 0, 0.5f, 0.5f)), std::vector<std::int32_t>{d});
}

// Many leaves moving at once: enlarged in place, then one rebuild.
void moveAllInBulk(DynamicTree& tree, std::vector<Leaf>& leaves, BoxSource& source) {
  for (Leaf& leaf : leaves) {
    leaf.box = source.moved(leaf.box);
    tree.enlargeProxy(leaf.node, leaf.box);
  }
  tree.rebuild();
}

TEST(DynamicTree, EnlargedAndRebuilt_StaysValidExactAndShallow_LeavesKeepTheirNodes) {
  DynamicTree tree;
  BoxSource source(17);
  std::vector<Leaf> leaves = addRandomLeaves(tree, source, 1000);
  for (int round = 0; round < 20; ++round) {
    moveAllInBulk(tree, leaves, source);
    ASSERT_TRUE(tree.isValid()) << "round " << round;
    EXPECT_LE(tree.height(), heightLimit(1000)) << "round " << round;
  }
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    ASSERT_EQ(tree.userValue(leaves[i].node), std::int32_t(i));
    ASSERT_EQ(tree.box(leaves[i].node).lower, leaves[i].box.lower);
  }
  expectQueriesMatchBruteForce(tree, leaves, source);
  // Single changes still work on a rebuilt tree.
  for (std::size_t i = 0; i < 100; ++i) tree.destroyProxy(leaves[i].node);
  leaves.erase(leaves.begin(), leaves.begin() + 100);
  for (int i = 0; i < 100; ++i) {
    const AABB box = source.box();
    leaves.push_back({tree.createProxy(box, 1000 + i), box});
  }
  ASSERT_TRUE(tree.isValid());
  expectQueriesMatchBruteForce(tree, leaves, source);
}

TEST(DynamicTree, RebuildJoinsOnlyWhatAMoveGrew) {
  DynamicTree tree;
  BoxSource source(23);
  std::vector<Leaf> leaves = addRandomLeaves(tree, source, 1000);
  EXPECT_EQ(tree.rebuild(), 0);
  // Two leaves jump across the world: the paths above them come apart into
  // their side subtrees, about two per level.
  for (Leaf* leaf : {&leaves[10], &leaves[500]}) {
    leaf->box = makeBox(Real(-50), Real(-50), 1, 1);
    tree.enlargeProxy(leaf->node, leaf->box);
  }
  const int joined = tree.rebuild();
  EXPECT_GT(joined, 2);
  EXPECT_LE(joined, 4 * heightLimit(1000));
  ASSERT_TRUE(tree.isValid());
  EXPECT_EQ(queried(tree, makeBox(-50, -50, 0.5f, 0.5f)), (std::vector<std::int32_t>{leaves[10].node, leaves[500].node}));
  EXPECT_EQ(tree.rebuild(), 0);
}

TEST(DynamicTree, RebuildStaysShallow_WhenBoxesAreIdenticalOrOnALine) {
  DynamicTree identical;
  DynamicTree line;
  std::vector<std::int32_t> identicalNodes, lineNodes;
  for (int i = 0; i < 1000; ++i) {
    identicalNodes.push_back(identical.createProxy(makeBox(0, 0, 1, 1), i));
    lineNodes.push_back(line.createProxy(makeBox(Real(i), 0, Real(0.4), Real(0.4)), i));
  }
  for (int i = 0; i < 1000; ++i) {
    identical.enlargeProxy(identicalNodes[std::size_t(i)], makeBox(0, 0, 2, 2));
    line.enlargeProxy(lineNodes[std::size_t(i)], makeBox(Real(i) * Real(1.001), 0, Real(0.4), Real(0.4)));
  }
  identical.rebuild();
  line.rebuild();
  ASSERT_TRUE(identical.isValid());
  ASSERT_TRUE(line.isValid());
  EXPECT_LE(identical.height(), heightLimit(1000));
  EXPECT_LE(line.height(), heightLimit(1000));
}

TEST(DynamicTree, RebuiltTreesOfIdenticalHistoriesAreIdentical) {
  auto history = [] {
    DynamicTree tree;
    BoxSource source(29);
    std::vector<Leaf> leaves = addRandomLeaves(tree, source, 300);
    for (int round = 0; round < 5; ++round) moveAllInBulk(tree, leaves, source);
    return tree.state();
  };
  const DynamicTree::State first = history();
  const DynamicTree::State second = history();
  ASSERT_EQ(first.root, second.root);
  ASSERT_EQ(first.nodes.size(), second.nodes.size());
  for (std::size_t i = 0; i < first.nodes.size(); ++i) {
    EXPECT_EQ(first.nodes[i].parent, second.nodes[i].parent) << i;
    EXPECT_EQ(first.nodes[i].child1, second.nodes[i].child1) << i;
    EXPECT_EQ(first.nodes[i].box.lower, second.nodes[i].box.lower) << i;
  }
}

void expectSameNodes(const DynamicTree::State& a, const DynamicTree::State& b) {
  ASSERT_EQ(a.root, b.root);
  ASSERT_EQ(a.freeList, b.freeList);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].parent, b.nodes[i].parent) << i;
    EXPECT_EQ(a.nodes[i].child1, b.nodes[i].child1) << i;
    EXPECT_EQ(a.nodes[i].child2, b.nodes[i].child2) << i;
    EXPECT_EQ(a.nodes[i].userValue, b.nodes[i].userValue) << i;
    EXPECT_EQ(a.nodes[i].height, b.nodes[i].height) << i;
    EXPECT_EQ(a.nodes[i].box.lower, b.nodes[i].box.lower) << i;
    EXPECT_EQ(a.nodes[i].box.upper, b.nodes[i].box.upper) << i;
  }
}

// A rebuild whose jobs run on threads of their own, all at once, or one
// after another from the last: the tree of a rebuild on one thread, node
// for node (so queries meet leaves in the same order, and later proxies get
// the same nodes).
TEST(DynamicTree, RebuildInJobs_OnThreadsOrBackwards_GivesTheTreeOfOneThread) {
  auto onThreads = [](int jobCount, auto&& job) {
    std::vector<std::thread> threads;
    for (int index = 0; index < jobCount; ++index) threads.emplace_back([&job, index] { job(index); });
    for (std::thread& thread : threads) thread.join();
  };
  auto backwards = [](int jobCount, auto&& job) {
    for (int index = jobCount - 1; index >= 0; --index) job(index);
  };
  DynamicTree oneThread, threaded, reversed;
  std::vector<Leaf> leaves[3];
  BoxSource sources[3] = {BoxSource(31), BoxSource(31), BoxSource(31)};
  DynamicTree* trees[3] = {&oneThread, &threaded, &reversed};
  for (int t = 0; t < 3; ++t) leaves[t] = addRandomLeaves(*trees[t], sources[t], 3000);
  int mostJobs = 0;
  for (int round = 0; round < 5; ++round) {
    for (int t = 0; t < 3; ++t) {
      for (Leaf& leaf : leaves[t]) {
        leaf.box = sources[t].moved(leaf.box);
        trees[t]->enlargeProxy(leaf.node, leaf.box);
      }
    }
    oneThread.rebuild();
    threaded.rebuild([&](int jobCount, auto&& job) {
      mostJobs = std::max(mostJobs, jobCount);
      onThreads(jobCount, job);
    });
    reversed.rebuild(backwards);
    ASSERT_TRUE(threaded.isValid()) << "round " << round;
    expectSameNodes(oneThread.state(), threaded.state());
    expectSameNodes(oneThread.state(), reversed.state());
  }
  EXPECT_GT(mostJobs, 1);
  expectQueriesMatchBruteForce(threaded, leaves[1], sources[1]);
}

TEST(DynamicTree, RemovingEveryLeafLeavesAnEmptyValidTree) {
  DynamicTree tree;
  BoxSource source(3);
  std::vector<std::int32_t> nodes;
  for (int i = 0; i < 100; ++i) nodes.push_back(tree.createProxy(source.box(), i));
  for (std::int32_t node : nodes) {
    tree.destroyProxy(node);
    ASSERT_TRUE(tree.isValid());
  }
  EXPECT_EQ(tree.leafCount(), 0);
  EXPECT_EQ(tree.height(), 0);
  EXPECT_TRUE(queried(tree, makeBox(50, 50, 100, 100)).empty());
}

}  // namespace
}  // namespace impulse
