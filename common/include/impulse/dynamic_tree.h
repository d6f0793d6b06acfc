#pragma once
/// Dynamic AABB tree (bounding volume hierarchy), nodes in one contiguous
/// array. Single changes insert and remove leaves, balanced by rotations;
/// many leaves moving together are enlarged in place and the part of the
/// tree above them rebuilt in one go (split at the middle, as Box2D v3).

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "impulse/math.h"

namespace impulse {

class DynamicTree {
 public:
  static constexpr std::int32_t kNull = -1;

  /// Inserts a leaf holding `box` as is (callers fatten it). Returns the node index.
  std::int32_t createProxy(const AABB& box, std::int32_t userValue);
  void destroyProxy(std::int32_t node);
  /// Removes and re-inserts the leaf with a new box.
  void moveProxy(std::int32_t node, const AABB& box);
  /// Gives the leaf a new box without restructuring: its ancestors are
  /// marked for rebuild(), which must follow before any query (their boxes
  /// may not hold the leaf until then). For many moving leaves, a short walk
  /// up from each and one rebuild cost less than re-inserting each, and
  /// leave a better tree for the queries that follow.
  void enlargeProxy(std::int32_t node, const AABB& box);
  /// enlargeProxy in two halves, for many leaves at once: setLeafBox writes
  /// only the leaf, markForRebuild only its ancestors' marks (both side by
  /// side for distinct leaves).
  void setLeafBox(std::int32_t node, const AABB& box) { nodes_[node].box = box; }
  void markForRebuild(std::int32_t node);
  /// Starts loading the node's parent, the first node markForRebuild reads.
  void fetchParent(std::int32_t node) const {
    const std::int32_t parent = nodes_[node].parent;
    if (parent != kNull) __builtin_prefetch(&nodes_[parent]);
  }
  /// Rebuilds the marked part of the tree, top down, keeping every unmarked
  /// subtree as it is. Leaves keep their node indices. Returns how many
  /// subtrees it joined (0 when nothing was marked).
  int rebuild() {
    return rebuild([](int jobCount, auto&& job) {
      for (int index = 0; index < jobCount; ++index) job(index);
    });
  }
  /// rebuild() with the subtrees below its top splits built as separate
  /// jobs: runJobs(jobCount, job) must call job(index) once for each index
  /// in [0, jobCount), on any threads in any order. The tree comes out the
  /// same, node for node, however the jobs run.
  template <class RunJobs>
  int rebuild(RunJobs&& runJobs) {
    if (!planRebuild()) return 0;
    runJobs(static_cast<int>(buildJobs_.size()), [this](int index) { runBuildJob(index); });
    return finishRebuild();
  }

  const AABB& box(std::int32_t node) const { return nodes_[node].box; }
  std::int32_t userValue(std::int32_t node) const { return nodes_[node].child2; }
  /// Whether `node` is in range and a leaf in use.
  /// Nodes are numbered below this.
  std::int32_t nodeCapacity() const { return static_cast<std::int32_t>(nodes_.size()); }

  bool isLeafNode(std::int32_t node) const {
    return node >= 0 && node < static_cast<std::int32_t>(nodes_.size()) && nodes_[node].height == 0;
  }

  /// Calls visit(node) for each leaf whose box overlaps `box`, in a
  /// deterministic order; visit returns false to stop.
  template <typename Visit>
  void query(const AABB& box, Visit&& visit) const;

  /// Two nodes whose leaves a walk pairs: each leaf under `a` with each
  /// under `b`, or, where a == b, every two leaves under a.
  struct NodePair {
    std::int32_t a = kNull;
    std::int32_t b = kNull;
  };
  /// Splits the search for every two leaves whose boxes overlap into at
  /// least `count` node pairs where the tree has that many (`parts`,
  /// cleared first): their walks (forEachLeafPair) together find each such
  /// pair once. The parts are the same for the same tree.
  void splitLeafPairs(std::size_t count, std::vector<NodePair>& parts) const;
  /// Calls visit(leafA, leafB) for each two distinct leaves of `part` whose
  /// boxes overlap, each pair once, in a deterministic order. Walking the
  /// tree against itself finds the pairs of most of its leaves for less
  /// than a query of each, which starts from the root every time.
  template <typename Visit>
  void forEachLeafPair(NodePair part, Visit&& visit) const;

  /// A segment origin -> origin + maxFraction * translation, or a box of
  /// half-size `extent` centred on it and swept along it (a shape cast).
  struct Ray {
    Vec2 origin = Vec2::Zero();
    Vec2 translation = Vec2::Zero();
    Real maxFraction = 1;
    Vec2 extent = Vec2::Zero();
  };

  /// Calls clip(node, maxFraction) for each leaf whose box (grown by the
  /// ray's extent) the ray enters before its current max fraction, in a
  /// deterministic order: at each node the nearer child first (so leaves
  /// come roughly, not strictly, nearest first). clip returns the new max
  /// fraction: the one it was given to go on, a smaller one to shorten the
  /// ray (so a closest-hit search skips what lies beyond its best hit), a
  /// negative one to stop.
  template <typename Clip>
  void rayCast(const Ray& ray, Clip&& clip) const;

  /// A leaf, an inner node or a free node, as a saved tree holds it
  /// (height: leaf 0, free -1; parent is the free-list link of a free node).
  struct Node {
    AABB box;
    std::int32_t parent = kNull;
    std::int32_t child1 = kNull;
    std::int32_t child2 = kNull;
    std::int32_t userValue = -1;
    std::int16_t height = 0;
    bool isLeaf() const { return child1 == kNull; }
  };
  /// The whole tree, node by node: its shape decides which nodes later
  /// proxies get and the order queries visit leaves in, so a saved world
  /// keeps it.
  struct State {
    std::vector<Node> nodes;
    std::int32_t root = kNull;
    std::int32_t freeList = kNull;
    int leafCount = 0;
  };
  State state() const;
  /// Replaces the tree with a saved one; false (tree unchanged) when it is
  /// not a valid tree (isValid) or a leaf's box is not finite.
  bool restore(const State& state);
  /// Moves every box by -offset (the world's origin moved by offset),
  /// rounded outwards so a parent still holds its children and a box still
  /// holds what it held.
  void shift(const Vec2d& offset);

  int height() const;
  int leafCount() const { return leafCount_; }
  /// Checks parent links, heights, enclosing boxes, the height bound the
  /// queries' stacks rely on, the leaf count and the free list.
  bool isValid() const;

 private:
  // A node as the tree keeps it: one cache line, on a line's boundary. An
  // inner node keeps a copy of its children's boxes (childBoxes, in child
  // order), so that a query decides where to go next from the node it is
  // at, one line, rather than from its two children's lines (in a crowd's
  // pair search most of the time went to those loads). A leaf has no
  // children and keeps its user value in child2.
  struct alignas(64) TreeNode {
    AABB childBoxes[2];
    AABB box;
    std::int32_t parent = kNull;
    std::int32_t child1 = kNull;
    std::int32_t child2 = kNull;
    std::int16_t height = 0;
    // An inner node above a leaf enlargeProxy gave a new box since the last
    // rebuild (so are all its ancestors).
    bool enlarged = false;
    bool isLeaf() const { return child1 == kNull; }
  };
  static_assert(sizeof(TreeNode) == 64);
  static TreeNode packed(const Node& node);
  static Node unpacked(const TreeNode& node);

  std::int32_t allocateNode();
  void freeNode(std::int32_t node);
  void insertLeaf(std::int32_t leaf);
  void removeLeaf(std::int32_t leaf);
  std::int32_t findBestSibling(const AABB& leafBox) const;
  void replaceChild(std::int32_t parent, std::int32_t oldChild, std::int32_t newChild);
  // Sets the node's box and height from its children's, and its copies of
  // their boxes.
  void refit(std::int32_t node);
  void copyAllChildBoxes();
  void refitAncestors(std::int32_t node, bool trySwaps);
  std::int32_t balance(std::int32_t node, bool trySwaps);
  std::int32_t rotateUp(std::int32_t node, std::int32_t child, bool trySwaps);
  void swapForArea(std::int32_t node);
  bool isValidNode(std::int32_t node) const;
  std::int64_t freeNodeCount() const;

  // A subtree a rebuild keeps whole (a leaf, or an inner node nothing moved
  // in), by the centre of its box, which the splits read in order rather
  // than visit the scattered nodes.
  struct BuildItem {
    Vec2 center;
    std::int32_t node;
  };
  void reserveBuildItems();
  void collectBuildItems(bool wholeTree);
  // A subtree of items.size() items is built into items.size() - 1 nodes,
  // `slots`, taken in the order the node joining its two parts comes after
  // both parts' nodes, so its root is the last slot. `spread` is the box
  // of the items' centres, which each split passes on to its parts rather
  // than have them read their items again.
  struct BuildJob {
    std::span<BuildItem> items;
    AABB spread;
    int depth;
    std::span<const std::int32_t> slots;
  };
  // A node over two subtrees of the top, joined once both are built.
  struct TopJoin {
    std::int32_t node;
    std::int32_t child1;
    std::int32_t child2;
  };
  BuildJob wholeBuild();
  bool planRebuild();
  std::int32_t planSubtree(const BuildJob& job, int splitsLeft);
  void runBuildJob(int index);
  int finishRebuild();
  std::int32_t buildSubtree(const BuildJob& job);
  // The two parts of a build's split.
  static std::pair<BuildJob, BuildJob> split(const BuildJob& job);
  static std::size_t splitAtMiddle(std::span<BuildItem> items, const AABB& spread, AABB (&spreads)[2]);
  static std::size_t splitAtMedian(std::span<BuildItem> items, const AABB& spread);
  void joinUnderNode(std::int32_t parent, std::int32_t child1, std::int32_t child2);

  std::vector<TreeNode> nodes_;
  std::int32_t root_ = kNull;
  std::int32_t freeList_ = kNull;
  int leafCount_ = 0;
  // The rebuild's scratch, kept so that a step allocates nothing: the
  // subtrees it joins, the marked nodes above them it reuses (in the order
  // it fills them), its jobs and the joins above the jobs.
  std::vector<BuildItem> buildItems_;
  std::vector<std::int32_t> buildSlots_;
  std::vector<BuildJob> buildJobs_;
  std::vector<TopJoin> topJoins_;
  // A node waiting in a ray cast, with where the ray enters its box.
  // Trivial, so a stack of them costs nothing to declare.
  struct RayEntry {
    std::int32_t node;
    Real enter;
  };
  // Queries and ray casts keep their stack on the C++ stack, so concurrent
  // const queries share nothing. Depth-first, a stack holds at most one
  // pending sibling per level: the height plus one. Insertion's balance bound
  // and the rebuild's turn to median splits deep down keep the height logarithmic, far below
  // kMaxHeight for any tree that fits in memory; a rebuild that would pass it
  // rebuilds the whole tree.
  static constexpr int kStackSize = 256;
  static constexpr int kMaxHeight = kStackSize - 2;
  // Starts loading a node a query pushes, whose line it reads once it pops
  // the node: it arrives while the nodes pushed after it are searched.
  // Returns the node.
  std::int32_t fetch(std::int32_t node) const {
    __builtin_prefetch(&nodes_[node]);
    return node;
  }
  // query below `top`, whose box overlaps queryBox.
  template <typename Visit>
  void querySubtree(std::int32_t top, const AABB& queryBox, Visit&& visit) const;
  // The leaf of two nodes one of which at least is a leaf (a walk queries
  // the other with its box); kNull for a node against itself or two inner
  // nodes, which the walk splits.
  std::int32_t leafSide(const NodePair& pair) const {
    if (pair.a == pair.b) return kNull;
    if (nodes_[pair.a].isLeaf()) return pair.a;
    return nodes_[pair.b].isLeaf() ? pair.b : kNull;
  }
  // emit(next) for each pair a walk of `pair` (no leafSide) goes on to
  // whose boxes overlap: a node against itself, its two children each
  // against itself and against each other (none for a leaf); two inner
  // nodes, the larger one's children (by perimeter) against the other. The
  // children's boxes are their parent's copies.
  template <typename Emit>
  void splitPair(const NodePair& pair, Emit&& emit) const {
    const TreeNode& a = nodes_[pair.a];
    if (pair.a == pair.b) {
      if (a.isLeaf()) return;
      const std::int32_t first = fetch(a.child1);
      const std::int32_t second = fetch(a.child2);
      if (a.childBoxes[0].overlaps(a.childBoxes[1])) emit(NodePair{first, second});
      emit(NodePair{second, second});
      emit(NodePair{first, first});
      return;
    }
    const TreeNode& b = nodes_[pair.b];
    const bool splitsA = a.box.perimeter() >= b.box.perimeter();
    const TreeNode& split = splitsA ? a : b;
    const AABB& other = splitsA ? b.box : a.box;
    for (int child = 0; child < 2; ++child) {
      if (!split.childBoxes[child].overlaps(other)) continue;
      const std::int32_t node = fetch(child == 0 ? split.child1 : split.child2);
      emit(splitsA ? NodePair{node, pair.b} : NodePair{pair.a, node});
    }
  }
  // A walk's stack: each level of its descent, which goes one node deeper
  // on one side or both, leaves at most two pairs waiting, and it descends
  // at most twice the height.
  static constexpr int kPairStackSize = 4 * kStackSize;
  static_assert(kPairStackSize >= 2 * (2 * kMaxHeight) + 1);
};

template <typename Visit>
void DynamicTree::query(const AABB& queryBox, Visit&& visit) const {
  if (root_ == kNull || !nodes_[root_].box.overlaps(queryBox)) return;
  querySubtree(root_, queryBox, visit);
}

template <typename Visit>
void DynamicTree::querySubtree(std::int32_t top, const AABB& queryBox, Visit&& visit) const {
  // Only nodes whose box overlaps go on the stack, tested from their
  // parent's copies of their boxes.
  std::int32_t stack[kStackSize];
  int count = 0;
  stack[count++] = top;
  while (count > 0) {
    const std::int32_t index = stack[--count];
    const TreeNode& node = nodes_[index];
    if (node.isLeaf()) {
      if (!visit(index)) return;
      continue;
    }
    const bool first = node.childBoxes[0].overlaps(queryBox);
    const bool second = node.childBoxes[1].overlaps(queryBox);
    if (first) stack[count++] = fetch(node.child1);
    if (second) stack[count++] = fetch(node.child2);
  }
}

template <typename Visit>
void DynamicTree::forEachLeafPair(NodePair part, Visit&& visit) const {
  NodePair stack[kPairStackSize];
  int count = 0;
  stack[count++] = part;
  while (count > 0) {
    const NodePair pair = stack[--count];
    // A leaf against a subtree (or a leaf): the subtree is queried with the
    // leaf's box, two child boxes tested a node, where the walk would weigh
    // both sides of every pair it meets.
    const std::int32_t leaf = leafSide(pair);
    if (leaf == kNull) {
      splitPair(pair, [&](const NodePair& next) { stack[count++] = next; });
      continue;
    }
    querySubtree(leaf == pair.a ? pair.b : pair.a, nodes_[leaf].box, [&](std::int32_t other) {
      visit(leaf, other);
      return true;
    });
  }
}

// Where the segment origin + t * translation, t in [0, maxFraction], is
// inside the box: [enter, exit], or enter > exit when it misses (slab test).
struct SlabSpan {
  Real enter = 0;
  Real exit = 0;
};

inline SlabSpan clipToBox(const Vec2& origin, const Vec2& translation, Real maxFraction,
                          const AABB& box) {
  SlabSpan span{0, maxFraction};
  for (int axis = 0; axis < 2; ++axis) {
    const Real start = origin[axis];
    const Real step = translation[axis];
    if (step == 0) {
      // Parallel to this slab: inside it all along, or never.
      if (start < box.lower[axis] || start > box.upper[axis]) return {1, 0};
      continue;
    }
    Real near = (box.lower[axis] - start) / step;
    Real far = (box.upper[axis] - start) / step;
    if (near > far) std::swap(near, far);
    span.enter = std::max(span.enter, near);
    span.exit = std::min(span.exit, far);
    if (span.enter > span.exit) return span;
  }
  return span;
}

template <typename Clip>
void DynamicTree::rayCast(const Ray& ray, Clip&& clip) const {
  if (root_ == kNull || ray.maxFraction < 0) return;
  Real maxFraction = ray.maxFraction;
  // Where the ray enters a node's box grown by the extent; a miss is
  // past any fraction.
  auto enterOf = [&](std::int32_t index) {
    const AABB& box = nodes_[index].box;
    const SlabSpan span = clipToBox(ray.origin, ray.translation, maxFraction,
                                    AABB{box.lower - ray.extent, box.upper + ray.extent});
    return span.enter <= span.exit ? span.enter : std::numeric_limits<Real>::infinity();
  };
  RayEntry stack[kStackSize];
  int count = 0;
  stack[count++] = {root_, enterOf(root_)};
  while (count > 0) {
    const RayEntry entry = stack[--count];
    // The ray may have been clipped since the node was pushed.
    if (entry.enter > maxFraction) continue;
    const TreeNode& node = nodes_[entry.node];
    if (node.isLeaf()) {
      maxFraction = clip(entry.node, maxFraction);
      if (maxFraction < 0) return;
      continue;
    }
    // The nearer child goes on top, so near hits come first and clip the
    // ray before the far side is searched.
    RayEntry first{node.child1, enterOf(node.child1)};
    RayEntry second{node.child2, enterOf(node.child2)};
    if (first.enter < second.enter) std::swap(first, second);
    if (first.enter <= maxFraction) stack[count++] = first;
    if (second.enter <= maxFraction) stack[count++] = second;
  }
}

}  // namespace impulse
