#include "impulse/dynamic_tree.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

namespace impulse {
namespace {

// Children of a node may differ in height by at most this, which bounds the
// height by about 1.8 log2(leaves) whatever the input (identical or nested
// boxes would otherwise make a list). One (strict AVL) leaves the area
// heuristic less freedom: on 10000 random boxes queries visited 15% more nodes
// after insertion; three or more gained nothing over two once boxes moved.
constexpr int kMaxHeightDifference = 2;

bool heightsBalanced(int a, int b) { return std::abs(a - b) <= kMaxHeightDifference; }

Vec2 center(const AABB& box) { return Real(0.5) * (box.lower + box.upper); }

// value - offset in float, rounded down (towards -inf) or up, never to the
// nearer float only: a box moved this way still covers what it covered.
Real shiftedDown(Real value, double offset) {
  const double exact = double(value) - offset;
  const Real rounded = Real(exact);
  return double(rounded) > exact ? std::nextafter(rounded, -std::numeric_limits<Real>::infinity())
                                 : rounded;
}

Real shiftedUp(Real value, double offset) {
  const double exact = double(value) - offset;
  const Real rounded = Real(exact);
  return double(rounded) < exact ? std::nextafter(rounded, std::numeric_limits<Real>::infinity())
                                 : rounded;
}

// Below this depth the rebuild splits at the median instead: whatever the
// boxes, the rest of the subtree is then log2(n) deep.
constexpr int kMiddleSplitDepth = 40;

// Levels of the rebuild split before the parts are left to jobs (up to
// 2^levels of them), and the fewest subtrees a job is given: fewer take
// less time than handing them to another thread.
constexpr int kSplitsBeforeJobs = 2;
constexpr std::size_t kItemsPerJob = 256;

// The bounds of a spread of no points: any point's coordinates replace them.
constexpr Real kHuge = std::numeric_limits<Real>::max();

// 0 for x, 1 for y: the axis along which a box is wider.
int widerAxis(const AABB& box) {
  return box.upper.x() - box.lower.x() >= box.upper.y() - box.lower.y() ? 0 : 1;
}

// The box of points added one by one, in four scalars: through Eigen's
// 2-vectors GCC moved each point through the stack, and the rebuild's
// splits spent a third of their time on it.
class SpreadBuilder {
 public:
  void add(const Vec2& point) {
    lowerX_ = std::min(lowerX_, point.x());
    lowerY_ = std::min(lowerY_, point.y());
    upperX_ = std::max(upperX_, point.x());
    upperY_ = std::max(upperY_, point.y());
  }
  AABB box() const { return {Vec2(lowerX_, lowerY_), Vec2(upperX_, upperY_)}; }

 private:
  Real lowerX_ = kHuge;
  Real lowerY_ = kHuge;
  Real upperX_ = -kHuge;
  Real upperY_ = -kHuge;
};

// The box of the items' centres.
template <class Items>
AABB centerSpread(const Items& items) {
  SpreadBuilder spread;
  for (const auto& item : items) spread.add(item.center);
  return spread.box();
}

// What descending into one child of the node being examined could cost.
struct ChildCost {
  Real direct = 0;  // perimeter of the child united with the new leaf
  Real area = 0;    // perimeter of the child itself
  Real lowerBound = std::numeric_limits<Real>::max();  // max: nothing to descend into
};

}  // namespace

std::int32_t DynamicTree::createProxy(const AABB& box, std::int32_t userValue) {
  std::int32_t leaf = allocateNode();
  nodes_[leaf].box = box;
  nodes_[leaf].child2 = userValue;
  insertLeaf(leaf);
  ++leafCount_;
  return leaf;
}

void DynamicTree::destroyProxy(std::int32_t node) {
  removeLeaf(node);
  freeNode(node);
  --leafCount_;
}

void DynamicTree::moveProxy(std::int32_t node, const AABB& box) {
  removeLeaf(node);
  nodes_[node].box = box;
  insertLeaf(node);
}

void DynamicTree::enlargeProxy(std::int32_t node, const AABB& box) {
  setLeafBox(node, box);
  markForRebuild(node);
}

void DynamicTree::splitLeafPairs(std::size_t count, std::vector<NodePair>& parts) const {
  parts.clear();
  if (root_ == kNull) return;
  // Breadth first from the whole tree against itself, in place: parts
  // [0, done) have a leaf (a walk queries them whole), kept as they are;
  // [next, end) wait to be replaced by what their walks go on to, appended.
  parts.push_back({root_, root_});
  std::size_t done = 0;
  std::size_t next = 0;
  while (next < parts.size() && done + (parts.size() - next) < count) {
    const NodePair pair = parts[next++];
    if (leafSide(pair) != kNull) {
      parts[done++] = pair;
    } else {
      splitPair(pair, [&](const NodePair& part) { parts.push_back(part); });
    }
  }
  parts.erase(parts.begin() + std::ptrdiff_t(done), parts.begin() + std::ptrdiff_t(next));
}

void DynamicTree::markForRebuild(std::int32_t node) {
  // Marking stops at the first node marked before: whoever marked it goes
  // on to the root, so its ancestors are all marked by the time the marking
  // ends, whichever thread marks which leaf's first. The flag is all that is
  // written (atomically: two threads may mark one node), never the boxes:
  // the rebuild frees every marked node and computes the boxes of the nodes
  // it makes.
  for (std::int32_t index = nodes_[node].parent; index != kNull; index = nodes_[index].parent) {
    const std::atomic_ref<bool> enlarged(nodes_[index].enlarged);
    if (enlarged.load(std::memory_order_relaxed)) return;
    enlarged.store(true, std::memory_order_relaxed);
  }
}

// The build of every subtree collectBuildItems found.
DynamicTree::BuildJob DynamicTree::wholeBuild() {
  return {buildItems_, centerSpread(buildItems_), 0, buildSlots_};
}

bool DynamicTree::planRebuild() {
  if (root_ == kNull || !nodes_[root_].enlarged) return false;
  collectBuildItems(false);
  buildJobs_.clear();
  topJoins_.clear();
  root_ = planSubtree(wholeBuild(), kSplitsBeforeJobs);
  return true;
}

// The top of the build: splits as the build would, down to parts it leaves
// to jobs, and notes the joins above them for finishRebuild. Returns the
// subtree's root (known before it is built: the last of its slots).
std::int32_t DynamicTree::planSubtree(const BuildJob& job, int splitsLeft) {
  if (splitsLeft == 0 || job.items.size() < kItemsPerJob) {
    buildJobs_.push_back(job);
    return job.items.size() == 1 ? job.items.front().node : job.slots.back();
  }
  const auto [first, second] = split(job);
  const std::int32_t child1 = planSubtree(first, splitsLeft - 1);
  const std::int32_t child2 = planSubtree(second, splitsLeft - 1);
  topJoins_.push_back({job.slots.back(), child1, child2});
  return job.slots.back();
}

void DynamicTree::runBuildJob(int index) { buildSubtree(buildJobs_[std::size_t(index)]); }

int DynamicTree::finishRebuild() {
  // Children before parents: planSubtree noted each join after its parts'.
  for (const TopJoin& join : topJoins_) joinUnderNode(join.node, join.child1, join.child2);
  nodes_[root_].parent = kNull;
  if (nodes_[root_].height > kMaxHeight) {
    // Kept subtrees stacked too deep over many rebuilds: start afresh.
    collectBuildItems(true);
    root_ = buildSubtree(wholeBuild());
    nodes_[root_].parent = kNull;
  }
  return static_cast<int>(buildItems_.size());
}

// The subtrees the rebuild joins: every leaf and every unmarked inner node
// under marked ones (all leaves for the whole tree); the marked nodes above
// them are the slots the build fills, as many as it needs (one fewer than
// the subtrees). They go in the reverse of the order the walk meets them:
// the order a build taking nodes one by one from the free list got them
// in, so that every node keeps the number it had then.
void DynamicTree::collectBuildItems(bool wholeTree) {
  buildItems_.clear();
  buildSlots_.clear();
  std::int32_t stack[kStackSize];
  int count = 0;
  stack[count++] = root_;
  while (count > 0) {
    const std::int32_t index = stack[--count];
    TreeNode& node = nodes_[index];
    if (node.isLeaf() || !(node.enlarged || wholeTree)) {
      node.parent = kNull;
      buildItems_.push_back({center(node.box), index});
      continue;
    }
    stack[count++] = node.child1;
    stack[count++] = node.child2;
    buildSlots_.push_back(index);
  }
  std::reverse(buildSlots_.begin(), buildSlots_.end());
}

std::int32_t DynamicTree::buildSubtree(const BuildJob& job) {
  if (job.items.size() == 1) return job.items.front().node;
  const auto [first, second] = split(job);
  const std::int32_t child1 = buildSubtree(first);
  const std::int32_t child2 = buildSubtree(second);
  joinUnderNode(job.slots.back(), child1, child2);
  return job.slots.back();
}

std::pair<DynamicTree::BuildJob, DynamicTree::BuildJob> DynamicTree::split(const BuildJob& job) {
  AABB spreads[2];
  std::size_t middle = job.depth < kMiddleSplitDepth ? splitAtMiddle(job.items, job.spread, spreads) : 0;
  if (middle == 0) {
    middle = splitAtMedian(job.items, job.spread);
    spreads[0] = centerSpread(job.items.first(middle));
    spreads[1] = centerSpread(job.items.subspan(middle));
  }
  const std::size_t rest = job.items.size() - middle;
  return {{job.items.first(middle), spreads[0], job.depth + 1, job.slots.first(middle - 1)},
          {job.items.subspan(middle), spreads[1], job.depth + 1, job.slots.subspan(middle - 1, rest - 1)}};
}

// Box2D v3's split: the items whose centres lie below the middle of their
// spread along its wider axis, and the rest. On v3's churning scenes it
// builds a tree the pair search walks about as fast as one split by the
// surface area heuristic (16 bins), in a fraction of the time: the whole
// broad phase took 8 to 33% less. One pass partitions the items and
// measures each part's spread. Returns the size of the first part, or 0
// when all centres coincide.
std::size_t DynamicTree::splitAtMiddle(std::span<BuildItem> items, const AABB& spread, AABB (&spreads)[2]) {
  const int axis = widerAxis(spread);
  const Real pivot = Real(0.5) * (spread.lower[axis] + spread.upper[axis]);
  if (!(spread.lower[axis] < pivot)) return 0;
  SpreadBuilder below;
  SpreadBuilder above;
  // Hoare's scheme from both ends: each item is read once, and only items
  // on the wrong side move.
  std::size_t low = 0;
  std::size_t high = items.size();
  while (true) {
    while (low < high && items[low].center[axis] < pivot) {
      below.add(items[low].center);
      ++low;
    }
    while (low < high && !(items[high - 1].center[axis] < pivot)) {
      above.add(items[high - 1].center);
      --high;
    }
    if (low == high) break;
    std::swap(items[low], items[high - 1]);
  }
  spreads[0] = below.box();
  spreads[1] = above.box();
  return low;
}

// The median along the wider spread of centres, in place (ties by node, so
// the split is the same on every run).
std::size_t DynamicTree::splitAtMedian(std::span<BuildItem> items, const AABB& spread) {
  const std::size_t median = items.size() / 2;
  const int axis = widerAxis(spread);
  std::nth_element(items.begin(), items.begin() + std::ptrdiff_t(median), items.end(),
                   [axis](const BuildItem& a, const BuildItem& b) {
                     return a.center[axis] != b.center[axis] ? a.center[axis] < b.center[axis] : a.node < b.node;
                   });
  return median;
}

void DynamicTree::joinUnderNode(std::int32_t parent, std::int32_t child1, std::int32_t child2) {
  nodes_[parent] = TreeNode{};
  nodes_[parent].child1 = child1;
  nodes_[parent].child2 = child2;
  nodes_[child1].parent = parent;
  nodes_[child2].parent = parent;
  refit(parent);
}

DynamicTree::TreeNode DynamicTree::packed(const Node& node) {
  const bool leaf = node.isLeaf() && node.height == 0;
  return {{}, node.box, node.parent, node.child1, leaf ? node.userValue : node.child2, node.height, false};
}

DynamicTree::Node DynamicTree::unpacked(const TreeNode& node) {
  const bool leaf = node.isLeaf() && node.height == 0;
  return {node.box, node.parent, node.child1, leaf ? kNull : node.child2, leaf ? node.child2 : -1, node.height};
}

DynamicTree::State DynamicTree::state() const {
  State saved{{}, root_, freeList_, leafCount_};
  saved.nodes.reserve(nodes_.size());
  for (const TreeNode& node : nodes_) saved.nodes.push_back(unpacked(node));
  return saved;
}

bool DynamicTree::restore(const State& state) {
  DynamicTree candidate;
  candidate.nodes_.reserve(state.nodes.size());
  for (const Node& node : state.nodes) {
    // A node without a first child has no second (a packed leaf keeps its
    // user value there).
    if (node.isLeaf() && node.child2 != kNull) return false;
    candidate.nodes_.push_back(packed(node));
  }
  candidate.root_ = state.root;
  candidate.freeList_ = state.freeList;
  candidate.leafCount_ = state.leafCount;
  candidate.copyAllChildBoxes();
  if (!candidate.isValid()) return false;
  for (const TreeNode& node : candidate.nodes_) {
    if (node.height == 0 && !(isFinite(node.box.lower) && isFinite(node.box.upper))) return false;
  }
  *this = std::move(candidate);
  reserveBuildItems();
  return true;
}

// Every inner node's copies of its children's boxes, taken from the
// children: after a shift, and for a restored tree, which keeps no copies
// (where both children are nodes; isValid rejects the rest).
void DynamicTree::copyAllChildBoxes() {
  const auto size = static_cast<std::int32_t>(nodes_.size());
  auto inRange = [size](std::int32_t index) { return index >= 0 && index < size; };
  for (TreeNode& node : nodes_) {
    if (node.height <= 0 || !inRange(node.child1) || !inRange(node.child2)) continue;
    node.childBoxes[0] = nodes_[node.child1].box;
    node.childBoxes[1] = nodes_[node.child2].box;
  }
}

// A rebuild joins at most every node; its scratch grows with the node
// array, so a rebuild never allocates in a step.
void DynamicTree::reserveBuildItems() {
  if (buildItems_.capacity() >= nodes_.capacity()) return;
  buildItems_.reserve(nodes_.capacity());
  buildSlots_.reserve(nodes_.capacity());
  buildJobs_.reserve(std::size_t(1) << kSplitsBeforeJobs);
  topJoins_.reserve(std::size_t(1) << kSplitsBeforeJobs);
}

void DynamicTree::shift(const Vec2d& offset) {
  for (TreeNode& node : nodes_) {
    node.box.lower = Vec2(shiftedDown(node.box.lower.x(), offset.x()),
                          shiftedDown(node.box.lower.y(), offset.y()));
    node.box.upper = Vec2(shiftedUp(node.box.upper.x(), offset.x()),
                          shiftedUp(node.box.upper.y(), offset.y()));
  }
  copyAllChildBoxes();
}

int DynamicTree::height() const { return root_ == kNull ? 0 : nodes_[root_].height; }

bool DynamicTree::isValid() const {
  const std::int64_t freeCount = freeNodeCount();
  if (freeCount < 0) return false;
  if (root_ == kNull) {
    return leafCount_ == 0 && freeCount == static_cast<std::int64_t>(nodes_.size());
  }
  if (root_ < 0 || root_ >= static_cast<std::int32_t>(nodes_.size())) return false;
  if (nodes_[root_].parent != kNull) return false;

  // A local stack: isValid is for tests and must not disturb query's scratch space.
  std::vector<std::int32_t> pending{root_};
  std::int64_t reached = 0;
  int leaves = 0;
  while (!pending.empty()) {
    std::int32_t index = pending.back();
    pending.pop_back();
    // More nodes than exist means a cycle or a node linked twice.
    if (++reached > static_cast<std::int64_t>(nodes_.size())) return false;
    if (!isValidNode(index)) return false;
    const TreeNode& node = nodes_[index];
    if (node.isLeaf()) {
      ++leaves;
    } else {
      pending.push_back(node.child1);
      pending.push_back(node.child2);
    }
  }
  return leaves == leafCount_ && reached + freeCount == static_cast<std::int64_t>(nodes_.size()) &&
         height() <= kMaxHeight;
}

std::int32_t DynamicTree::allocateNode() {
  if (freeList_ == kNull) {
    nodes_.emplace_back();
    reserveBuildItems();
    return static_cast<std::int32_t>(nodes_.size()) - 1;
  }
  std::int32_t index = freeList_;
  freeList_ = nodes_[index].parent;
  nodes_[index] = TreeNode{};
  return index;
}

void DynamicTree::freeNode(std::int32_t node) {
  nodes_[node] = TreeNode{};
  nodes_[node].parent = freeList_;
  nodes_[node].height = -1;
  freeList_ = node;
}

void DynamicTree::insertLeaf(std::int32_t leaf) {
  if (root_ == kNull) {
    root_ = leaf;
    nodes_[leaf].parent = kNull;
    return;
  }
  const AABB leafBox = nodes_[leaf].box;
  const std::int32_t sibling = findBestSibling(leafBox);
  const std::int32_t oldParent = nodes_[sibling].parent;
  // allocateNode may grow nodes_, so no Node reference is held across it.
  const std::int32_t newParent = allocateNode();
  TreeNode& parent = nodes_[newParent];
  parent.parent = oldParent;
  parent.child1 = sibling;
  parent.child2 = leaf;
  nodes_[sibling].parent = newParent;
  nodes_[leaf].parent = newParent;
  replaceChild(oldParent, sibling, newParent);
  // The fresh node's height 0 differs from its refitted one, so the walk
  // always reaches past it.
  refitAncestors(newParent, true);
}

void DynamicTree::removeLeaf(std::int32_t leaf) {
  if (leaf == root_) {
    root_ = kNull;
    return;
  }
  const std::int32_t parent = nodes_[leaf].parent;
  const std::int32_t grandParent = nodes_[parent].parent;
  const std::int32_t sibling =
      nodes_[parent].child1 == leaf ? nodes_[parent].child2 : nodes_[parent].child1;
  replaceChild(grandParent, parent, sibling);
  nodes_[sibling].parent = grandParent;
  nodes_[leaf].parent = kNull;
  freeNode(parent);
  // Area swaps are left to insertion, which every move also goes through:
  // trying them on removal too would double their cost for no better tree.
  refitAncestors(grandParent, false);
}

// Surface area heuristic: the cost of making node S the sibling of the new leaf
// L is the perimeter of the new parent, perimeter(S u L), plus how much every
// ancestor of S grows, sum(perimeter(A u L) - perimeter(A)). One greedy path
// is followed from the root:
//
//   best = root, inherited = 0
//   at each internal node N:
//     cost(N) = perimeter(N u L) + inherited;  keep it if it beats best
//     inherited += perimeter(N u L) - perimeter(N)
//     for each child C:
//       C is a leaf:  cost(C) = perimeter(C u L) + inherited;  keep if better
//       C internal:   bound(C) = inherited + perimeter(C u L)
//                                + min(perimeter(L) - perimeter(C), 0)
//     stop when no bound can beat best, else descend into the smaller bound
//
// The bound covers both C itself as the sibling and any descendant of C, whose
// new parent is at least as large as L while C then grows by (C u L) - C.
std::int32_t DynamicTree::findBestSibling(const AABB& leafBox) const {
  const Real leafArea = leafBox.perimeter();
  std::int32_t index = root_;
  Real area = nodes_[index].box.perimeter();
  Real direct = nodes_[index].box.unite(leafBox).perimeter();
  Real inherited = 0;
  std::int32_t best = root_;
  Real bestCost = direct;

  while (!nodes_[index].isLeaf()) {
    const TreeNode& node = nodes_[index];
    if (direct + inherited < bestCost) {
      best = index;
      bestCost = direct + inherited;
    }
    inherited += direct - area;

    auto examine = [&](std::int32_t child) {
      ChildCost cost;
      cost.direct = nodes_[child].box.unite(leafBox).perimeter();
      if (nodes_[child].isLeaf()) {
        if (cost.direct + inherited < bestCost) {
          best = child;
          bestCost = cost.direct + inherited;
        }
      } else {
        cost.area = nodes_[child].box.perimeter();
        cost.lowerBound = inherited + cost.direct + std::min(leafArea - cost.area, Real(0));
      }
      return cost;
    };
    const ChildCost cost1 = examine(node.child1);
    const ChildCost cost2 = examine(node.child2);
    if (bestCost <= cost1.lowerBound && bestCost <= cost2.lowerBound) break;

    bool descendFirst = cost1.lowerBound < cost2.lowerBound;
    if (cost1.lowerBound == cost2.lowerBound) {
      // Equal bounds happen when both children contain the leaf; the nearer
      // centre is the better guess, and keeps the choice deterministic.
      const Vec2 leafCenter = center(leafBox);
      descendFirst = (center(nodes_[node.child1].box) - leafCenter).squaredNorm() <
                     (center(nodes_[node.child2].box) - leafCenter).squaredNorm();
    }
    const ChildCost& next = descendFirst ? cost1 : cost2;
    index = descendFirst ? node.child1 : node.child2;
    area = next.area;
    direct = next.direct;
  }
  return best;
}

void DynamicTree::replaceChild(std::int32_t parent, std::int32_t oldChild, std::int32_t newChild) {
  if (parent == kNull) {
    root_ = newChild;
  } else if (nodes_[parent].child1 == oldChild) {
    nodes_[parent].child1 = newChild;
  } else {
    nodes_[parent].child2 = newChild;
  }
}

void DynamicTree::refit(std::int32_t node) {
  TreeNode& n = nodes_[node];
  const TreeNode& a = nodes_[n.child1];
  const TreeNode& b = nodes_[n.child2];
  n.childBoxes[0] = a.box;
  n.childBoxes[1] = b.box;
  n.box = a.box.unite(b.box);
  n.height = static_cast<std::int16_t>(1 + std::max(a.height, b.height));
}

// Walks up from `node`, whose box and height still hold their values from
// before the change below it, balancing and refitting each ancestor.
void DynamicTree::refitAncestors(std::int32_t node, bool trySwaps) {
  while (node != kNull) {
    const AABB oldBox = nodes_[node].box;
    const int oldHeight = nodes_[node].height;
    node = balance(node, trySwaps);
    // A subtree that keeps its box and height changes nothing above it (a leaf
    // moving inside a crowd stops here, long before the root), not even the
    // parent's copy of its box, which is still the old box (a rotation here
    // puts another node in its place with the same box).
    const TreeNode& top = nodes_[node];
    if (top.height == oldHeight && top.box.lower == oldBox.lower && top.box.upper == oldBox.upper) {
      return;
    }
    node = top.parent;
  }
}

// Returns the root of the subtree at `node`, refitted, after restoring the
// height bound there (its subtrees must already satisfy it) or, when it holds
// and `trySwaps` is set, after trying a swap that shrinks the node's children.
std::int32_t DynamicTree::balance(std::int32_t node, bool trySwaps) {
  const TreeNode& n = nodes_[node];
  const int difference = nodes_[n.child2].height - nodes_[n.child1].height;
  if (difference > kMaxHeightDifference) return rotateUp(node, n.child2, trySwaps);
  if (difference < -kMaxHeightDifference) return rotateUp(node, n.child1, trySwaps);
  if (trySwaps) swapForArea(node);
  refit(node);
  return node;
}

// Rotates the tall child C of A up, with B A's other child (on either side)
// and F, G C's children:
//
//   A(B, C(F, G))  ->  C(A(B, shorter(F, G)), taller(F, G))
//
// The area heuristic may insert a leaf next to a tall subtree, far out of
// balance, so the pushed-down A is balanced again in turn: this is the join of
// two AVL trees and costs one rotation per level of difference.
std::int32_t DynamicTree::rotateUp(std::int32_t node, std::int32_t child, bool trySwaps) {
  const TreeNode& a = nodes_[node];
  const TreeNode& c = nodes_[child];
  const std::int32_t other = a.child1 == child ? a.child2 : a.child1;
  const TreeNode& f = nodes_[c.child1];
  const TreeNode& g = nodes_[c.child2];
  // With equal heights, the grandchild that packs tighter with B goes down.
  const bool keepFirst = f.height != g.height ? f.height > g.height
                                              : nodes_[other].box.unite(g.box).perimeter() <
                                                    nodes_[other].box.unite(f.box).perimeter();
  const std::int32_t taller = keepFirst ? c.child1 : c.child2;
  const std::int32_t shorter = keepFirst ? c.child2 : c.child1;

  const std::int32_t parent = a.parent;
  replaceChild(parent, node, child);
  nodes_[child].parent = parent;
  nodes_[child].child1 = node;
  nodes_[child].child2 = taller;
  nodes_[node].parent = child;
  replaceChild(node, child, shorter);
  nodes_[shorter].parent = node;

  balance(node, trySwaps);
  refit(child);
  return child;
}

// Box2D v3's tree rotation: swapping a child B of A with a grandchild F under
// A's other child C, making C(B, G), pays when C shrinks, as every query that
// reaches A then tests a smaller box. Only swaps that keep the height bound
// and A's own height are taken, so the ancestors' balance is untouched.
void DynamicTree::swapForArea(std::int32_t node) {
  const TreeNode& a = nodes_[node];
  // From the children: on the way up, a's own height is not refitted yet.
  const int height = 1 + std::max(nodes_[a.child1].height, nodes_[a.child2].height);
  std::int32_t bestDown = kNull;
  std::int32_t bestUp = kNull;
  Real bestDelta = 0;
  auto consider = [&](std::int32_t down, std::int32_t inner) {
    const TreeNode& c = nodes_[inner];
    if (c.isLeaf()) return;
    for (const auto& [up, stay] : {std::pair{c.child1, c.child2}, std::pair{c.child2, c.child1}}) {
      const int downHeight = nodes_[down].height;
      const int stayHeight = nodes_[stay].height;
      const int upHeight = nodes_[up].height;
      const int innerHeight = 1 + std::max(downHeight, stayHeight);
      if (!heightsBalanced(downHeight, stayHeight) || !heightsBalanced(upHeight, innerHeight) ||
          1 + std::max(upHeight, innerHeight) != height) {
        continue;
      }
      const Real delta = nodes_[down].box.unite(nodes_[stay].box).perimeter() - c.box.perimeter();
      if (delta < bestDelta) {
        bestDown = down;
        bestUp = up;
        bestDelta = delta;
      }
    }
  };
  consider(a.child1, a.child2);
  consider(a.child2, a.child1);
  if (bestDown == kNull) return;

  const std::int32_t inner = nodes_[bestUp].parent;
  replaceChild(node, bestDown, bestUp);
  nodes_[bestUp].parent = node;
  replaceChild(inner, bestUp, bestDown);
  nodes_[bestDown].parent = inner;
  refit(inner);
}

bool DynamicTree::isValidNode(std::int32_t index) const {
  const TreeNode& node = nodes_[index];
  if (node.isLeaf()) return node.height == 0;
  const auto size = static_cast<std::int32_t>(nodes_.size());
  if (node.child1 < 0 || node.child1 >= size || node.child2 < 0 || node.child2 >= size) {
    return false;
  }
  const TreeNode& a = nodes_[node.child1];
  const TreeNode& b = nodes_[node.child2];
  const AABB enclosing = a.box.unite(b.box);
  auto same = [](const AABB& x, const AABB& y) { return x.lower == y.lower && x.upper == y.upper; };
  return a.parent == index && b.parent == index && a.height >= 0 && b.height >= 0 &&
         node.height == 1 + std::max(a.height, b.height) && same(node.box, enclosing) &&
         same(node.childBoxes[0], a.box) && same(node.childBoxes[1], b.box);
}

// Number of nodes on the free list, or -1 when it is broken (a cycle, an index
// out of range, or a node in use on it).
std::int64_t DynamicTree::freeNodeCount() const {
  const auto size = static_cast<std::int64_t>(nodes_.size());
  std::int64_t count = 0;
  for (std::int32_t index = freeList_; index != kNull; index = nodes_[index].parent) {
    if (index < 0 || index >= size || nodes_[index].height != -1 || ++count > size) return -1;
  }
  return count;
}

}  // namespace impulse
