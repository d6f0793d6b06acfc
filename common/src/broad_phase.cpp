#include "impulse/broad_phase.h"

#include <cassert>

#include <algorithm>

#include "impulse/constants.h"

namespace impulse {
namespace {

constexpr std::int32_t kNullKey = -1;

// A proxy key is the tree node index shifted left by one, with the kind (the
// tree) in the low bit.
std::int32_t makeKey(std::int32_t node, BroadPhase::ProxyKind kind) {
  return (node << 1) | static_cast<std::int32_t>(kind);
}
std::int32_t nodeOf(std::int32_t proxyKey) { return proxyKey >> 1; }
BroadPhase::ProxyKind kindOf(std::int32_t proxyKey) {
  return static_cast<BroadPhase::ProxyKind>(proxyKey & 1);
}
int treeIndex(BroadPhase::ProxyKind kind) { return static_cast<int>(kind); }

// The box moved by `shift`, joined with where it was.
AABB swept(const AABB& box, const Vec2& shift) {
  return {box.lower + shift.cwiseMin(Vec2::Zero()), box.upper + shift.cwiseMax(Vec2::Zero())};
}

// Where the shape's tight box may be over the next step.
AABB expectedReach(const AABB& tight, const ProxyMotion& motion) {
  return swept(tight.expanded(motion.turnReach), motion.displacement);
}

AABB fatten(const AABB& tight, BroadPhase::ProxyKind kind, const ProxyMotion& motion) {
  // Static proxies never move, so a margin would only produce false pairs.
  return kind == BroadPhase::ProxyKind::Movable ? BroadPhase::fatBox(tight, motion) : tight;
}

// Sets or clears a queued proxy's flag (BroadPhase::queuedNode_, per tree).
void markQueued(std::vector<std::uint8_t> (&queuedNode)[2], std::int32_t proxyKey, std::uint8_t queued) {
  queuedNode[treeIndex(kindOf(proxyKey))][std::size_t(nodeOf(proxyKey))] = queued;
}

// The pair of two user values, the smaller first.
ProxyPair orderedPair(std::int32_t a, std::int32_t b) { return {std::min(a, b), std::max(a, b)}; }

bool pairLess(const ProxyPair& a, const ProxyPair& b) {
  return a.first != b.first ? a.first < b.first : a.second < b.second;
}

// Candidate pairs of one query, held back so that the caller is asked
// which are known a batch at a time after the tree walk rather than one by
// one during it, and a batch behind: the caller starts the lookups of the
// batch just filled (mostly a cache miss each into its set of contacts) and
// answers for the one before, whose lookups have had a batch's tree walk
// to arrive (started just before the answers, they had mostly not: on v3's
// spinner the checks took 61 perf samples of ~3 800, now 22). Fixed
// arrays, so that known pairs never grow (or allocate) the output list.
class PairBatch {
 public:
  PairBatch(const BroadPhase::KnownPairs& known, std::vector<ProxyPair>& pairs) : known_(known), pairs_(pairs) {}
  ~PairBatch() {
    settle(pending(), std::span(held_[filling_], count_[filling_]));
    settle(filling_, {});
  }
  PairBatch(const PairBatch&) = delete;
  PairBatch& operator=(const PairBatch&) = delete;

  void add(const ProxyPair& pair) {
    held_[filling_][count_[filling_]++] = pair;
    if (count_[filling_] < kCapacity) return;
    settle(pending(), std::span(held_[filling_], kCapacity));
    filling_ = pending();
  }

 private:
  static constexpr std::size_t kCapacity = 32;

  std::size_t pending() const { return 1 - filling_; }

  // Batch `b`'s unknown pairs into the output, the caller meanwhile
  // starting the lookups of `next`; the batch is emptied.
  void settle(std::size_t b, std::span<const ProxyPair> next) {
    const std::span<ProxyPair> batch(held_[b], count_[b]);
    const std::size_t unknown = known_ ? known_(batch, next) : batch.size();
    pairs_.insert(pairs_.end(), batch.begin(), batch.begin() + std::ptrdiff_t(unknown));
    count_[b] = 0;
  }

  const BroadPhase::KnownPairs& known_;
  std::vector<ProxyPair>& pairs_;
  ProxyPair held_[2][kCapacity];
  std::size_t count_[2] = {0, 0};
  std::size_t filling_ = 0;
};

// Adds a pair of `userValue` with every leaf of `tree` overlapping `box`,
// except the leaves `skip` names.
template <class Skip, class Add>
void collectPairs(const DynamicTree& tree, const AABB& box, std::int32_t userValue, Skip&& skip, Add&& add) {
  tree.query(box, [&](std::int32_t node) {
    if (skip(node)) return true;
    add(orderedPair(userValue, tree.userValue(node)));
    return true;
  });
}

}  // namespace

AABB BroadPhase::fatBox(const AABB& tightAABB, const ProxyMotion& motion) {
  const Real halfDiagonal = Real(0.5) * (tightAABB.upper - tightAABB.lower).norm();
  const Real margin = std::min(kAabbMargin, kSpeculativeDistance + motion.room * halfDiagonal);
  return expectedReach(tightAABB, motion).expanded(margin);
}

std::int32_t BroadPhase::createProxy(const AABB& tightAABB, std::int32_t userValue, ProxyKind kind, Real room) {
  const std::int32_t node = trees_[treeIndex(kind)].createProxy(fatten(tightAABB, kind, {.room = room}), userValue);
  const std::int32_t key = makeKey(node, kind);
  recordUserBox(key);
  // A new static proxy is not queued: it cannot pair with other static proxies,
  // and movable ones find it when they move (or the caller touches it).
  if (kind == ProxyKind::Movable) moveBuffer_.push_back(key);
  return key;
}

void BroadPhase::destroyProxy(std::int32_t proxyKey) {
  // The node may be reused by the next createProxy under the same key, so its
  // queue entries must go now. A linear scan: the queue only holds this step's
  // movers.
  std::replace(moveBuffer_.begin(), moveBuffer_.end(), proxyKey, kNullKey);
  trees_[treeIndex(kindOf(proxyKey))].destroyProxy(nodeOf(proxyKey));
}

bool BroadPhase::updateProxy(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion) {
  if (holds(proxyKey, tightAABB, motion)) return false;
  const ProxyKind kind = kindOf(proxyKey);
  trees_[treeIndex(kind)].moveProxy(nodeOf(proxyKey), fatten(tightAABB, kind, motion));
  recordUserBox(proxyKey);
  moveBuffer_.push_back(proxyKey);
  return true;
}

bool BroadPhase::enlargeProxy(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion) {
  // Only the movable tree is rebuilt; a static proxy (teleported) re-inserts.
  if (kindOf(proxyKey) != ProxyKind::Movable) return updateProxy(proxyKey, tightAABB, motion);
  if (!resizeLeaf(proxyKey, tightAABB, motion)) return false;
  markGrown(std::span(&proxyKey, 1));
  queueGrown(proxyKey);
  return true;
}

bool BroadPhase::resizeLeaf(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion) {
  assert(kindOf(proxyKey) == ProxyKind::Movable);
  if (holds(proxyKey, tightAABB, motion)) return false;
  trees_[treeIndex(ProxyKind::Movable)].setLeafBox(nodeOf(proxyKey), fatten(tightAABB, ProxyKind::Movable, motion));
  recordUserBox(proxyKey);
  return true;
}

void BroadPhase::markGrown(std::span<const std::int32_t> proxyKeys) {
  // A mark costs little but the wait for the parent's line: fetched this
  // far ahead, the waits overlap.
  constexpr std::size_t kParentsAhead = 8;
  DynamicTree& movable = trees_[treeIndex(ProxyKind::Movable)];
  for (std::size_t i = 0; i < proxyKeys.size(); ++i) {
    if (i + kParentsAhead < proxyKeys.size()) movable.fetchParent(nodeOf(proxyKeys[i + kParentsAhead]));
    movable.markForRebuild(nodeOf(proxyKeys[i]));
  }
}

void BroadPhase::queueGrown(std::int32_t proxyKey) { moveBuffer_.push_back(proxyKey); }

bool BroadPhase::holds(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion) const {
  return trees_[treeIndex(kindOf(proxyKey))].box(nodeOf(proxyKey)).contains(expectedReach(tightAABB, motion));
}

void BroadPhase::rebuildEnlarged() { trees_[treeIndex(ProxyKind::Movable)].rebuild(); }

void BroadPhase::touchProxy(std::int32_t proxyKey) { moveBuffer_.push_back(proxyKey); }

void BroadPhase::findNewPairs(std::vector<ProxyPair>& pairs, const KnownPairs& known) {
  pairs.clear();
  queryPairs(queuedProxies(), known, pairs);
  for (std::size_t part = 0; part < walkPartCount(); ++part) walkPairs(part, known, pairs);
  finishPairSearch(pairs);
}

// A pair search walks the movable tree against itself (walkPairs) rather
// than query each queued movable proxy where one in kWalkFromQueuedShare
// movable proxies or more is queued, and at least kMinWalkedProxies. The
// walk pairs every proxy, queued or not, and costs about as much as
// querying half of them: from one in four, the bench's scaling-8000 took
// 1.1 of the queries' time in its pair stage; v3's crowds, with 55 to 92 %
// of their proxies queued each step, 0.65 to 0.8 of it. A few hundred
// queries cost little, and where they are a chain's links the walk costs
// more: heavy-chain-300's 300 links
// walked took twice their queries' time (each link's box overlaps its two
// neighbours', and the boxes of a hanging chain's stretches overlap far
// more than their links do).
constexpr int kWalkFromQueuedShare = 2;
constexpr int kMinWalkedProxies = 400;

std::span<const std::int32_t> BroadPhase::queuedProxies(std::size_t minWalkParts) {
  // The flags are all clear between searches (finishPairSearch clears the
  // ones set here), so a step pays for its queued proxies, not the trees.
  for (int tree = 0; tree < 2; ++tree) {
    const auto capacity = std::size_t(trees_[tree].nodeCapacity());
    if (queuedNode_[tree].size() < capacity) queuedNode_[tree].resize(capacity, 0);
  }
  // A proxy both moved and touched is queued twice but needs one query; a
  // destroyed one left a null key. Each keeps its first place: which order
  // the queries run in changes nothing (finishPairSearch sorts the pairs),
  // and sorting a crowd's thousands of keys had been a serial stretch.
  auto kept = moveBuffer_.begin();
  int queuedMovable = 0;
  for (const std::int32_t key : moveBuffer_) {
    if (key == kNullKey || isQueued(kindOf(key), nodeOf(key))) continue;
    markQueued(queuedNode_, key, 1);
    queuedMovable += kindOf(key) == ProxyKind::Movable ? 1 : 0;
    *kept++ = key;
  }
  moveBuffer_.erase(kept, moveBuffer_.end());
  const DynamicTree& movable = trees_[treeIndex(ProxyKind::Movable)];
  walkParts_.clear();
  if (queuedMovable >= kMinWalkedProxies && kWalkFromQueuedShare * queuedMovable >= movable.leafCount()) {
    movable.splitLeafPairs(minWalkParts, walkParts_);
  }
  return moveBuffer_;
}

void BroadPhase::walkPairs(std::size_t part, const KnownPairs& known, std::vector<ProxyPair>& pairs) const {
  PairBatch batch(known, pairs);
  const DynamicTree& movable = trees_[treeIndex(ProxyKind::Movable)];
  movable.forEachLeafPair(walkParts_[part], [&](std::int32_t a, std::int32_t b) {
    if (!isQueued(ProxyKind::Movable, a) && !isQueued(ProxyKind::Movable, b)) return;
    batch.add(orderedPair(movable.userValue(a), movable.userValue(b)));
  });
}

void BroadPhase::finishPairSearch(std::vector<ProxyPair>& pairs) {
  // Two queued proxies find each other from both ends; sorting also makes the
  // output independent of tree shape, queue order and thread count.
  std::sort(pairs.begin(), pairs.end(), pairLess);
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (std::int32_t proxyKey : moveBuffer_) {
    if (proxyKey != kNullKey) markQueued(queuedNode_, proxyKey, 0);
  }
  moveBuffer_.clear();
  walkParts_.clear();
}

void BroadPhase::recordUserBox(std::int32_t proxyKey) {
  const std::size_t user = std::size_t(leafUserValue(proxyKey));
  if (user >= userBoxes_.size()) userBoxes_.resize(user + 1);
  userBoxes_[user] = fatAABB(proxyKey);
}

void BroadPhase::recordAllUserBoxes() {
  userBoxes_.clear();
  for (int tree = 0; tree < 2; ++tree) {
    for (std::int32_t node = 0; node < trees_[tree].nodeCapacity(); ++node) {
      if (trees_[tree].isLeafNode(node)) recordUserBox(makeKey(node, ProxyKind(tree)));
    }
  }
}

const AABB& BroadPhase::fatAABB(std::int32_t proxyKey) const {
  return trees_[treeIndex(kindOf(proxyKey))].box(nodeOf(proxyKey));
}

int BroadPhase::proxyCount() const {
  return trees_[treeIndex(ProxyKind::Static)].leafCount() +
         trees_[treeIndex(ProxyKind::Movable)].leafCount();
}

BroadPhase::State BroadPhase::state() const {
  return {{trees_[0].state(), trees_[1].state()}, moveBuffer_};
}

void BroadPhase::shift(const Vec2d& offset) {
  for (DynamicTree& tree : trees_) tree.shift(offset);
  recordAllUserBoxes();
}

bool BroadPhase::restore(const State& state) {
  BroadPhase candidate;
  for (int tree = 0; tree < 2; ++tree) {
    if (!candidate.trees_[tree].restore(state.trees[tree])) return false;
  }
  for (std::int32_t key : state.queued) {
    if (key != kNullKey && candidate.leafUserValue(key) < 0) return false;
  }
  candidate.moveBuffer_ = state.queued;
  candidate.recordAllUserBoxes();
  *this = std::move(candidate);
  return true;
}

std::int32_t BroadPhase::leafUserValue(std::int32_t proxyKey) const {
  if (proxyKey < 0) return -1;
  const DynamicTree& tree = trees_[treeIndex(kindOf(proxyKey))];
  return tree.isLeafNode(nodeOf(proxyKey)) ? tree.userValue(nodeOf(proxyKey)) : -1;
}

template <class Add>
void BroadPhase::forEachPairOf(std::int32_t proxyKey, Add&& add) const {
  const ProxyKind kind = kindOf(proxyKey);
  const std::int32_t node = nodeOf(proxyKey);
  const DynamicTree& own = trees_[treeIndex(kind)];
  const AABB& box = own.box(node);
  const std::int32_t userValue = own.userValue(node);
  const DynamicTree& movable = trees_[treeIndex(ProxyKind::Movable)];
  if (kind == ProxyKind::Movable) {
    // A queued static partner finds this pair itself, and so does a queued
    // movable one of a lower node.
    collectPairs(trees_[treeIndex(ProxyKind::Static)], box, userValue,
                 [&](std::int32_t other) { return isQueued(ProxyKind::Static, other); }, add);
    if (!walkParts_.empty()) return;  // the walk finds its movable partners
    collectPairs(movable, box, userValue,
                 [&](std::int32_t other) { return other == node || (other < node && isQueued(ProxyKind::Movable, other)); },
                 add);
  } else {
    // A queued static proxy (touched or teleported) only looks for movable
    // partners: static-static pairs never collide.
    collectPairs(movable, box, userValue, [](std::int32_t) { return false; }, add);
  }
}

void BroadPhase::queryPairs(std::span<const std::int32_t> proxyKeys, const KnownPairs& known,
                            std::vector<ProxyPair>& pairs) const {
  PairBatch batch(known, pairs);
  for (std::int32_t proxyKey : proxyKeys) forEachPairOf(proxyKey, [&](const ProxyPair& pair) { batch.add(pair); });
}

}  // namespace impulse
