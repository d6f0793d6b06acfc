#pragma once
/// Broad phase: which shapes may touch, without testing every pair.
///
/// Two dynamic AABB trees (static proxies, movable proxies), so static-static
/// pairs are never considered and a moving proxy only queries what it could
/// touch. Only proxies that moved out of their fat box are re-inserted (or
/// enlarged, and the tree above them rebuilt), and only proxies marked moved
/// look for new pairs. A movable proxy's fat box is its tight box grown by a
/// margin in proportion to its size and stretched along the motion its
/// shape is expected to make over the next step.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "impulse/dynamic_tree.h"
#include "impulse/math.h"

namespace impulse {

/// A candidate pair of user values, first < second.
struct ProxyPair {
  std::int32_t first = 0;
  std::int32_t second = 0;
  friend bool operator==(const ProxyPair&, const ProxyPair&) = default;
};

/// Room a movable proxy's fat box keeps for motion nobody foresaw (a
/// knock, a tumble), per metre of its tight box's half-diagonal, beyond
/// the speculative distance and at most kAabbMargin. A quarter by default.
/// At a fixed 10 cm a drum of tumbling 20 cm boxes (v3's washer) held 2.5
/// contacts per touching one; at a quarter, 1.7. Less room leaves fewer
/// pairs whose manifolds are computed without finding points, but sends
/// more shapes back through the tree: worth it for polygons (kPolygonRoom),
/// whose manifolds cost the most, not for circles: at a tenth, a rain of
/// 25 cm balls (the bench's rain-2000) ran 15 % slower, the jiggling balls
/// of its heap re-entering the tree, and its pairs formed late enough to
/// leave its deepest overlap 5 % deeper.
inline constexpr Real kDefaultRoom = Real(0.25);
/// A polygon's room: on v3's smash, washer, junkyard and tumbler (crowds of
/// boxes) a tenth rather than a quarter took 5-10 % off a step, the
/// collide stage most; the bench's stacks, pyramids and piles keep their
/// errors. None at all (the speculative distance alone) lets a row of
/// boxes flying 5 cm apart lose its pairs once their speculative points
/// stop their boxes' stretching, and end 30 cm into each other at a wall.
inline constexpr Real kPolygonRoom = Real(0.1);

/// How a movable proxy's shape is expected to move over the next step (as
/// over the last one): its centre's displacement, and how far a point of it
/// may move by the turn; and the room its fat box keeps for the rest.
struct ProxyMotion {
  Vec2 displacement = Vec2::Zero();
  Real turnReach = 0;
  Real room = kDefaultRoom;
};

class BroadPhase {
 public:
  enum class ProxyKind : std::uint8_t { Static = 0, Movable = 1 };

  /// The fat box of a movable proxy: the tight box grown by the speculative
  /// distance plus the motion's room times its half-diagonal (at most
  /// kAabbMargin) and by the turn reach, and stretched along the displacement, so that a
  /// shape keeping its motion meets what lies ahead as a pair before it
  /// arrives.
  static AABB fatBox(const AABB& tightAABB, const ProxyMotion& motion);

  /// Adds a proxy for a tight AABB; movable proxies are fattened (fatBox,
  /// with `room` but no motion: a new body's first step is not known yet).
  /// Returns a proxy key (tree index and kind packed together).
  std::int32_t createProxy(const AABB& tightAABB, std::int32_t userValue, ProxyKind kind,
                           Real room = kDefaultRoom);
  void destroyProxy(std::int32_t proxyKey);

  /// Called with the new tight AABB of a moving proxy. Re-inserts it (and
  /// queues it for pair search) only when the tight box, with the motion
  /// the proxy is about to make, leaves its fat AABB. Returns true when it
  /// was re-inserted.
  bool updateProxy(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion = {});
  /// updateProxy for many proxies moving at once (a step's awake bodies): a
  /// movable proxy that left its fat AABB is enlarged in place, and
  /// rebuildEnlarged() must follow before any other change or query.
  bool enlargeProxy(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion = {});
  /// enlargeProxy of movable proxies in three parts, for many at once.
  /// resizeLeaf, side by side for distinct proxies (it writes only the
  /// proxy's own leaf and box record), gives a proxy that left its fat box
  /// its new one and returns whether it did; markGrown, side by side for
  /// distinct batches, marks the ancestors of a batch of such proxies for
  /// the rebuild, each leaf's parent (a cache miss in a crowd) fetched a
  /// few leaves ahead; queueGrown, one proxy at a time in the order they
  /// are to be searched, queues each.
  bool resizeLeaf(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion);
  void markGrown(std::span<const std::int32_t> proxyKeys);
  void queueGrown(std::int32_t proxyKey);
  /// Whether the proxy's fat AABB still holds its tight box with the motion
  /// it is about to make (then updateProxy and enlargeProxy leave it). Safe
  /// from several threads at once while nothing moves a proxy.
  bool holds(std::int32_t proxyKey, const AABB& tightAABB, const ProxyMotion& motion) const;
  /// Rebuilds the parts of the trees that enlargeProxy grew.
  void rebuildEnlarged();
  /// rebuildEnlarged with the rebuild split into jobs that runJobs may run
  /// on several threads (DynamicTree::rebuild); the trees come out the same.
  template <class RunJobs>
  void rebuildEnlarged(RunJobs&& runJobs) {
    trees_[static_cast<int>(ProxyKind::Movable)].rebuild(runJobs);
  }

  /// Queues a proxy for pair search without moving it (e.g. a body woke up). A
  /// queued static proxy looks for movable partners only.
  void touchProxy(std::int32_t proxyKey);

  /// Drops from `candidates` (pairs of user values, smaller first) the ones
  /// already known to the caller (that have a contact), keeping the rest at
  /// the front in their order, and returns how many are left. Given a batch
  /// at a time, with the batch it will be given next (`next`, possibly
  /// empty), whose lookups (mostly a cache miss each) the caller can start.
  using KnownPairs =
      std::function<std::size_t(std::span<ProxyPair> candidates, std::span<const ProxyPair> next)>;

  /// Finds the pairs whose fat AABBs overlap and involve a queued proxy, sorted
  /// and without duplicates, into `pairs` (cleared first), then empties the
  /// queue. Pairs `known` accepts are left out as they are found: in a moving
  /// pile most overlaps already have their contact, and sorting them was
  /// most of the work.
  void findNewPairs(std::vector<ProxyPair>& pairs, const KnownPairs& known = nullptr);

  /// findNewPairs in parts, for a search split among threads: the queued
  /// proxies (each once); then, from any thread, queryPairs on a slice of
  /// them and walkPairs on a part of the walk, each appending the pairs it
  /// finds to that thread's list; then finishPairSearch on all the lists
  /// joined, which sorts them, drops duplicates and empties the queue.
  /// Where half the movable proxies or more are queued, and at least a few
  /// hundred (a tumbling crowd), queuedProxies splits the search for pairs
  /// of two movable proxies into the parts of one walk of the movable tree
  /// against itself (DynamicTree::forEachLeafPair), at least
  /// `minWalkParts` of them, and queryPairs finds a queued movable proxy's
  /// static partners only; otherwise there are no walk parts. The pairs
  /// found are the same either way.
  std::span<const std::int32_t> queuedProxies(std::size_t minWalkParts = 1);
  void queryPairs(std::span<const std::int32_t> proxyKeys, const KnownPairs& known,
                  std::vector<ProxyPair>& pairs) const;
  std::size_t walkPartCount() const { return walkParts_.size(); }
  void walkPairs(std::size_t part, const KnownPairs& known, std::vector<ProxyPair>& pairs) const;
  void finishPairSearch(std::vector<ProxyPair>& pairs);

  /// Whether the fat AABBs of the live proxies of two user values overlap.
  /// Read from a copy kept by user value, so that a caller holding user
  /// values (a contact's two shapes) touches one small array, not the trees.
  bool fatAABBsOverlap(std::int32_t userValueA, std::int32_t userValueB) const {
    return userBoxes_[std::size_t(userValueA)].overlaps(userBoxes_[std::size_t(userValueB)]);
  }
  const AABB& fatAABB(std::int32_t proxyKey) const;
  /// The fat AABB of a user value's live proxy, from the same copy (what
  /// fatAABBsOverlap reads).
  const AABB& fatAABBOfUser(std::int32_t userValue) const { return userBoxes_[std::size_t(userValue)]; }

  /// Calls visit(userValue) for every proxy whose fat AABB overlaps box;
  /// visit returns false to stop early.
  template <typename Visit>
  void query(const AABB& box, Visit&& visit) const {
    bool proceed = true;
    for (const DynamicTree& tree : trees_) {
      if (!proceed) return;
      tree.query(box, [&](std::int32_t node) {
        proceed = visit(tree.userValue(node));
        return proceed;
      });
    }
  }

  /// query over the static proxies alone.
  template <typename Visit>
  void queryStatic(const AABB& box, Visit&& visit) const {
    const DynamicTree& tree = trees_[static_cast<int>(ProxyKind::Static)];
    tree.query(box, [&](std::int32_t node) { return visit(tree.userValue(node)); });
  }

  /// DynamicTree::rayCast through both trees, the max fraction carried from
  /// one to the next; clip(userValue, maxFraction) returns the new one.
  template <typename Clip>
  void rayCast(DynamicTree::Ray ray, Clip&& clip) const {
    for (const DynamicTree& tree : trees_) {
      tree.rayCast(ray, [&](std::int32_t node, Real maxFraction) {
        ray.maxFraction = clip(tree.userValue(node), maxFraction);
        return ray.maxFraction;
      });
      if (ray.maxFraction < 0) return;
    }
  }

  int proxyCount() const;

  /// Both trees (static, movable) and the queue of proxies waiting for a
  /// pair search, for saving a world.
  struct State {
    DynamicTree::State trees[2];
    std::vector<std::int32_t> queued;
  };
  State state() const;
  /// Replaces both trees and the queue; false (unchanged) when a tree is
  /// invalid or a queued key names no leaf. The caller checks that the
  /// leaves' user values are its own.
  bool restore(const State& state);
  /// Moves both trees by -offset (the world's origin moved by offset).
  void shift(const Vec2d& offset);
  /// The user value of the leaf a key names, or -1 when it names none.
  std::int32_t leafUserValue(std::int32_t proxyKey) const;

 private:
  bool isQueued(ProxyKind kind, std::int32_t node) const {
    const std::vector<std::uint8_t>& queued = queuedNode_[static_cast<int>(kind)];
    return std::size_t(node) < queued.size() && queued[std::size_t(node)] != 0;
  }

  /// Calls add(pair) for each pair of the proxy that queryPairs lists.
  template <class Add>
  void forEachPairOf(std::int32_t proxyKey, Add&& add) const;

  /// Copies the proxy's fat AABB to userBoxes_.
  void recordUserBox(std::int32_t proxyKey);
  void recordAllUserBoxes();

  DynamicTree trees_[2];
  /// By user value: the fat AABB of its live proxy (what a dead one had).
  std::vector<AABB> userBoxes_;
  std::vector<std::int32_t> moveBuffer_;
  /// During a pair search, per tree node: whether the proxy is queued. Two
  /// queued proxies that overlap would find each other twice; one of them
  /// leaves the pair to the other.
  std::vector<std::uint8_t> queuedNode_[2];
  /// During a pair search that walks the movable tree: the walk's parts
  /// (queuedProxies), empty when each queued proxy is queried.
  std::vector<DynamicTree::NodePair> walkParts_;
};

}  // namespace impulse
