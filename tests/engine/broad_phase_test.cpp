#include "impulse/broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "impulse/constants.h"

namespace impulse {
namespace {

using Kind = BroadPhase::ProxyKind;

AABB makeBox(Real x, Real y, Real halfWidth, Real halfHeight) {
  return {Vec2(x - halfWidth, y - halfHeight), Vec2(x + halfWidth, y + halfHeight)};
}

AABB shifted(const AABB& box, Real dx, Real dy) {
  return {box.lower + Vec2(dx, dy), box.upper + Vec2(dx, dy)};
}

bool sameBox(const AABB& a, const AABB& b) { return a.lower == b.lower && a.upper == b.upper; }

// std::pair, which gtest prints readably when a comparison fails.
using Pair = std::pair<std::int32_t, std::int32_t>;
std::vector<Pair> asPairs(const std::vector<ProxyPair>& pairs) {
  std::vector<Pair> converted;
  for (const ProxyPair& pair : pairs) converted.emplace_back(pair.first, pair.second);
  return converted;
}

bool containsUser(const std::vector<ProxyPair>& pairs, std::int32_t user) {
  return std::any_of(pairs.begin(), pairs.end(),
                     [&](const ProxyPair& p) { return p.first == user || p.second == user; });
}

// An independent model of what the broad phase should hold: the user value of
// a proxy is its index here.
struct ModelProxy {
  std::int32_t key = -1;
  Kind kind = Kind::Static;
  AABB tight;
  AABB fat;
  bool alive = true;
  bool queued = false;
};

// Drives a BroadPhase and the model through the same random history of
// creations, moves, touches and destructions, checking each step against a
// brute-force pair search.
// How a step's movers reach the broad phase: one re-insertion each,
// enlarged in place and the tree rebuilt once, or enlarged in place with
// their ancestors marked a batch at a time (as the world's step does).
enum class Moves { OneByOne, InBulk, InBatches };

class Scenario {
 public:
  explicit Scenario(unsigned seed, Moves moves = Moves::OneByOne) : rng_(seed), moves_(moves) {}

  void populate(int movable, int fixed) {
    for (int i = 0; i < movable; ++i) create(Kind::Movable);
    for (int i = 0; i < fixed; ++i) create(Kind::Static);
  }

  // One step of random activity, without the pair search: `jumpPercent`
  // of the movable proxies jump out of their fat boxes.
  void step(int jumpPercent = 30) {
    std::uniform_real_distribution<Real> small(-kAabbMargin / 2, kAabbMargin / 2);
    std::uniform_real_distribution<Real> large(-2, 2);
    std::uniform_int_distribution<int> percent(0, 99);
    for (ModelProxy& proxy : proxies_) {
      if (!proxy.alive || proxy.kind != Kind::Movable) continue;
      const bool jump = percent(rng_) < jumpPercent;
      const Real dx = jump ? large(rng_) : small(rng_);
      const Real dy = jump ? large(rng_) : small(rng_);
      move(proxy, shifted(proxy.tight, dx, dy));
    }
    if (moves_ == Moves::InBatches) markBatch();
    if (moves_ != Moves::OneByOne) broadPhase_.rebuildEnlarged();
    for (ModelProxy& proxy : proxies_) {
      if (proxy.alive && percent(rng_) < 3) {
        broadPhase_.touchProxy(proxy.key);
        proxy.queued = true;
      }
    }
    for (ModelProxy& proxy : proxies_) {
      if (proxy.alive && percent(rng_) < 2) {
        broadPhase_.destroyProxy(proxy.key);
        proxy.alive = false;
        proxy.queued = false;
      }
    }
    for (int i = 0; i < 5; ++i) create(i < 3 ? Kind::Movable : Kind::Static);
  }

  std::vector<ProxyPair> findPairs() {
    std::vector<ProxyPair> pairs;
    broadPhase_.findNewPairs(pairs);
    for (ModelProxy& proxy : proxies_) proxy.queued = false;
    return pairs;
  }

  // The search split as the world's step splits it among threads: the
  // queued proxies' queries in `chunks` slices, then the parts of the walk
  // of the movable tree (at least `walkParts`, where it walks), each into
  // a list of its own. Returns the joined pairs and how many walk parts ran.
  std::pair<std::vector<ProxyPair>, std::size_t> findPairsInParts(std::size_t chunks, std::size_t walkParts) {
    const std::span<const std::int32_t> queued = broadPhase_.queuedProxies(walkParts);
    std::vector<ProxyPair> pairs;
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
      std::vector<ProxyPair> found;
      const std::size_t first = queued.size() * chunk / chunks;
      const std::size_t last = queued.size() * (chunk + 1) / chunks;
      broadPhase_.queryPairs(queued.subspan(first, last - first), nullptr, found);
      pairs.insert(pairs.end(), found.begin(), found.end());
    }
    const std::size_t walked = broadPhase_.walkPartCount();
    for (std::size_t part = 0; part < walked; ++part) {
      std::vector<ProxyPair> found;
      broadPhase_.walkPairs(part, nullptr, found);
      pairs.insert(pairs.end(), found.begin(), found.end());
    }
    broadPhase_.finishPairSearch(pairs);
    for (ModelProxy& proxy : proxies_) proxy.queued = false;
    return {pairs, walked};
  }

  // Pairs of live proxies whose fat boxes overlap, involving a queued proxy and
  // a movable one, in (first, second) order.
  std::vector<ProxyPair> expectedPairs() const {
    std::vector<ProxyPair> pairs;
    for (std::size_t i = 0; i < proxies_.size(); ++i) {
      for (std::size_t j = i + 1; j < proxies_.size(); ++j) {
        const ModelProxy& a = proxies_[i];
        const ModelProxy& b = proxies_[j];
        if (!a.alive || !b.alive || !(a.queued || b.queued)) continue;
        if (a.kind == Kind::Static && b.kind == Kind::Static) continue;
        if (a.fat.overlaps(b.fat)) {
          pairs.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
        }
      }
    }
    return pairs;
  }

  void expectFatBoxesMatch() const {
    for (const ModelProxy& proxy : proxies_) {
      if (proxy.alive) {
        ASSERT_TRUE(sameBox(broadPhase_.fatAABB(proxy.key), proxy.fat));
      }
    }
  }

  int aliveCount() const {
    return static_cast<int>(std::count_if(proxies_.begin(), proxies_.end(),
                                          [](const ModelProxy& p) { return p.alive; }));
  }
  const std::vector<ModelProxy>& proxies() const { return proxies_; }
  const BroadPhase& broadPhase() const { return broadPhase_; }

 private:
  void create(Kind kind) {
    std::uniform_real_distribution<Real> position(0, 40);
    std::uniform_real_distribution<Real> half(Real(0.2), Real(1.5));
    const AABB tight = makeBox(position(rng_), position(rng_), half(rng_), half(rng_));
    ModelProxy proxy;
    proxy.kind = kind;
    proxy.tight = tight;
    proxy.fat = kind == Kind::Movable ? BroadPhase::fatBox(tight, {}) : tight;
    proxy.queued = kind == Kind::Movable;
    proxy.key = broadPhase_.createProxy(tight, static_cast<std::int32_t>(proxies_.size()), kind);
    proxies_.push_back(proxy);
  }

  void move(ModelProxy& proxy, const AABB& tight) {
    const bool leaves = !proxy.fat.contains(tight);
    const bool moved = moveProxy(proxy.key, tight);
    ASSERT_EQ(moved, leaves);
    proxy.tight = tight;
    if (leaves) {
      proxy.fat = BroadPhase::fatBox(tight, {});
      proxy.queued = true;
    }
  }

  bool moveProxy(std::int32_t key, const AABB& tight) {
    switch (moves_) {
      case Moves::OneByOne:
        return broadPhase_.updateProxy(key, tight);
      case Moves::InBulk:
        return broadPhase_.enlargeProxy(key, tight);
      case Moves::InBatches:
        if (!broadPhase_.resizeLeaf(key, tight, {})) return false;
        grown_.push_back(key);
        return true;
    }
    return false;
  }

  // The batch's ancestors marked at once, then its proxies queued.
  void markBatch() {
    broadPhase_.markGrown(grown_);
    for (const std::int32_t key : grown_) broadPhase_.queueGrown(key);
    grown_.clear();
  }

  std::mt19937 rng_;
  Moves moves_;
  BroadPhase broadPhase_;
  std::vector<ModelProxy> proxies_;
  std::vector<std::int32_t> grown_;
};

class BroadPhaseMoves : public ::testing::TestWithParam<Moves> {};

TEST_P(BroadPhaseMoves, FindsExactlyTheOverlappingPairsInvolvingQueuedProxies) {
  Scenario scenario(42, GetParam());
  scenario.populate(300, 100);
  std::vector<Pair> expected = asPairs(scenario.expectedPairs());
  ASSERT_EQ(asPairs(scenario.findPairs()), expected);
  EXPECT_GT(expected.size(), 100U);

  std::size_t total = 0;
  for (int step = 0; step < 15; ++step) {
    scenario.step();
    expected = asPairs(scenario.expectedPairs());
    const std::vector<Pair> pairs = asPairs(scenario.findPairs());
    ASSERT_EQ(pairs, expected) << "step " << step;
    scenario.expectFatBoxesMatch();
    EXPECT_EQ(scenario.broadPhase().proxyCount(), scenario.aliveCount());
    total += pairs.size();
  }
  // Moves within the margin must not hide every pair: real work was compared.
  EXPECT_GT(total, 500U);
}

std::string movesName(const ::testing::TestParamInfo<Moves>& moves) {
  constexpr const char* kNames[] = {"OneByOne", "InBulk", "InBatches"};
  return kNames[static_cast<int>(moves.param)];
}

INSTANTIATE_TEST_SUITE_P(HowMoversArrive, BroadPhaseMoves,
                         ::testing::Values(Moves::OneByOne, Moves::InBulk, Moves::InBatches), movesName);

// Where most movable proxies are queued the search walks the movable tree
// against itself, where few are it queries each: either finds exactly the
// pairs a brute-force search does, however it is split.
TEST(BroadPhase, WalkedOrQueried_InAnyNumberOfParts_FindsExactlyTheOverlappingPairs) {
  for (const Moves moves : {Moves::OneByOne, Moves::InBulk}) {
    Scenario scenario(77, moves);
    scenario.populate(800, 60);
    bool walked = false;
    bool queried = false;
    for (int step = 0; step < 12; ++step) {
      const std::vector<Pair> expected = asPairs(scenario.expectedPairs());
      const std::size_t splits = std::size_t(1 + step % 4);
      const auto [pairs, walkParts] = scenario.findPairsInParts(splits, 4 * splits);
      ASSERT_EQ(asPairs(pairs), expected) << "step " << step;
      walked = walked || walkParts >= 4 * splits;
      queried = queried || walkParts == 0;
      scenario.step(step % 2 == 0 ? 100 : 5);
    }
    EXPECT_TRUE(walked);
    EXPECT_TRUE(queried);
  }
}

TEST(BroadPhase, PairsAreSortedUniqueAndNeverStaticStatic) {
  Scenario scenario(9);
  scenario.populate(200, 200);
  scenario.findPairs();
  scenario.step();
  const std::vector<ProxyPair> pairs = scenario.findPairs();
  ASSERT_FALSE(pairs.empty());
  const std::vector<ModelProxy>& proxies = scenario.proxies();
  int withStatic = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    EXPECT_LT(pairs[i].first, pairs[i].second);
    if (i > 0) {
      const ProxyPair& previous = pairs[i - 1];
      EXPECT_TRUE(previous.first < pairs[i].first ||
                  (previous.first == pairs[i].first && previous.second < pairs[i].second));
    }
    const bool staticFirst = proxies[pairs[i].first].kind == Kind::Static;
    const bool staticSecond = proxies[pairs[i].second].kind == Kind::Static;
    EXPECT_FALSE(staticFirst && staticSecond);
    withStatic += staticFirst || staticSecond ? 1 : 0;
  }
  EXPECT_GT(withStatic, 0);
}

TEST(BroadPhase, IdenticalCallSequencesProduceIdenticalPairs) {
  auto history = [] {
    Scenario scenario(1234);
    scenario.populate(250, 80);
    std::vector<std::vector<ProxyPair>> steps{scenario.findPairs()};
    for (int step = 0; step < 10; ++step) {
      scenario.step();
      steps.push_back(scenario.findPairs());
    }
    return steps;
  };
  const std::vector<std::vector<ProxyPair>> first = history();
  EXPECT_FALSE(first.front().empty());
  EXPECT_EQ(first, history());
}

TEST(BroadPhase, StaticProxiesAreExact_MovableProxiesAreFat) {
  BroadPhase broadPhase;
  const AABB tight = makeBox(0, 0, 1, 1);
  const std::int32_t fixed = broadPhase.createProxy(tight, 1, Kind::Static);
  const std::int32_t movable = broadPhase.createProxy(tight, 2, Kind::Movable);
  EXPECT_TRUE(sameBox(broadPhase.fatAABB(fixed), tight));
  EXPECT_TRUE(sameBox(broadPhase.fatAABB(movable), tight.expanded(kAabbMargin)));
  EXPECT_EQ(broadPhase.proxyCount(), 2);
  EXPECT_TRUE(broadPhase.fatAABBsOverlap(1, 2));
  EXPECT_NE(fixed, movable);
}

bool nearlySameBox(const AABB& a, const AABB& b) {
  constexpr Real kTolerance = Real(1e-6);
  return (a.lower - b.lower).cwiseAbs().maxCoeff() < kTolerance && (a.upper - b.upper).cwiseAbs().maxCoeff() < kTolerance;
}

TEST(BroadPhase, FatBox_MarginFollowsTheShapesSize_StretchedAlongItsMotion) {
  // A 20 cm box: the speculative distance plus a quarter of its half-diagonal.
  const AABB small = makeBox(0, 0, Real(0.1), Real(0.1));
  const Real smallMargin = kSpeculativeDistance + Real(0.25) * Real(0.1) * std::sqrt(Real(2));
  EXPECT_TRUE(nearlySameBox(BroadPhase::fatBox(small, {}), small.expanded(smallMargin)));
  // A 2 m box: capped at kAabbMargin.
  const AABB large = makeBox(0, 0, 1, 1);
  EXPECT_TRUE(sameBox(BroadPhase::fatBox(large, {}), large.expanded(kAabbMargin)));
  // Moving right and down, turning: grown by the turn's reach all round and
  // stretched ahead by the displacement, not behind.
  const ProxyMotion motion{Vec2(Real(0.3), Real(-0.2)), Real(0.01)};
  const AABB fat = BroadPhase::fatBox(large, motion);
  const Real around = kAabbMargin + Real(0.01);
  EXPECT_TRUE(nearlySameBox(fat, AABB{Vec2(-1 - around, -1 - around - Real(0.2)),
                                      Vec2(1 + around + Real(0.3), 1 + around)}));
}

// A polygon's proxy keeps less room than the default quarter
// (kPolygonRoom): a tenth of the half-diagonal beyond the speculative
// distance, still capped at kAabbMargin, and stretched along its motion
// all the same.
TEST(BroadPhase, FatBox_KeepsTheRoomItsMotionGives) {
  const AABB small = makeBox(0, 0, Real(0.1), Real(0.1));
  const Real halfDiagonal = Real(0.1) * std::sqrt(Real(2));
  EXPECT_TRUE(nearlySameBox(BroadPhase::fatBox(small, {.room = kPolygonRoom}),
                            small.expanded(kSpeculativeDistance + kPolygonRoom * halfDiagonal)));
  const AABB huge = makeBox(0, 0, 10, 10);
  EXPECT_TRUE(sameBox(BroadPhase::fatBox(huge, {.room = kPolygonRoom}), huge.expanded(kAabbMargin)));
  const ProxyMotion rising{.displacement = Vec2(0, Real(0.5)), .room = kPolygonRoom};
  const Real margin = kSpeculativeDistance + kPolygonRoom * halfDiagonal;
  EXPECT_TRUE(nearlySameBox(BroadPhase::fatBox(small, rising),
                            AABB{small.lower - Vec2(margin, margin), small.upper + Vec2(margin, margin + Real(0.5))}));
  // A proxy created with that room gets it from its first box.
  BroadPhase broadPhase;
  const std::int32_t key =
      broadPhase.createProxy(small, 0, BroadPhase::ProxyKind::Movable, kPolygonRoom);
  EXPECT_TRUE(nearlySameBox(broadPhase.fatAABB(key), small.expanded(margin)));
}

TEST(BroadPhase, UpdateProxy_RefattensWhenTheComingStepWouldLeaveTheBox) {
  BroadPhase broadPhase;
  const AABB tight = makeBox(0, 0, 1, 1);
  const std::int32_t key = broadPhase.createProxy(tight, 1, Kind::Movable);
  // A wall 0.4 m ahead: beyond the margin, within the coming step's motion.
  broadPhase.createProxy(makeBox(Real(1.5), 0, Real(0.1), 1), 2, Kind::Static);
  std::vector<ProxyPair> pairs;
  broadPhase.findNewPairs(pairs);
  EXPECT_TRUE(pairs.empty());
  // At rest inside its box it stays; about to move 0.5 m right it is
  // re-fattened ahead and meets the wall before it arrives.
  EXPECT_FALSE(broadPhase.updateProxy(key, tight));
  EXPECT_TRUE(broadPhase.updateProxy(key, tight, ProxyMotion{Vec2(Real(0.5), 0), 0}));
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{1, 2}}));
}

TEST(BroadPhase, FatAABBsOverlap_SeesTheMargin) {
  BroadPhase broadPhase;
  const std::int32_t a = broadPhase.createProxy(makeBox(0, 0, 1, 1), 1, Kind::Movable);
  // Tight boxes 0.15 apart: the two 0.1 margins bridge the gap.
  const std::int32_t b = broadPhase.createProxy(makeBox(Real(2.15), 0, 1, 1), 2, Kind::Movable);
  broadPhase.createProxy(makeBox(Real(2.15), 0, 1, 1), 3, Kind::Static);
  EXPECT_TRUE(broadPhase.fatAABBsOverlap(1, 2));
  EXPECT_FALSE(broadPhase.fatAABBsOverlap(1, 3));
  // Moved one by one or in bulk, the user values see the boxes moved.
  broadPhase.updateProxy(b, makeBox(6, 0, 1, 1));
  EXPECT_FALSE(broadPhase.fatAABBsOverlap(1, 2));
  broadPhase.enlargeProxy(a, makeBox(Real(6.5), 0, 1, 1));
  broadPhase.rebuildEnlarged();
  EXPECT_TRUE(broadPhase.fatAABBsOverlap(1, 2));
}

TEST(BroadPhase, UpdateProxy_FalseInsideMargin_TrueWhenLeavingFatBox) {
  BroadPhase broadPhase;
  const AABB tight = makeBox(0, 0, 1, 1);
  const std::int32_t key = broadPhase.createProxy(tight, 1, Kind::Movable);
  broadPhase.createProxy(makeBox(Real(2.5), 0, 1, 1), 2, Kind::Static);
  broadPhase.createProxy(makeBox(0, Real(-1.5), 1, 1), 4, Kind::Static);
  std::vector<ProxyPair> pairs;
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{1, 4}}));
  const AABB fat = broadPhase.fatAABB(key);

  // Inside the margin: nothing changes and nothing is queued (a queued proxy
  // would report its neighbour 4 again).
  EXPECT_FALSE(broadPhase.updateProxy(key, shifted(tight, Real(0.05), Real(-0.05))));
  EXPECT_TRUE(sameBox(broadPhase.fatAABB(key), fat));
  EXPECT_FALSE(broadPhase.updateProxy(key, shifted(tight, kAabbMargin, 0)));
  broadPhase.findNewPairs(pairs);
  EXPECT_TRUE(pairs.empty());

  // Out of the fat box: re-fattened around the new box and queued, so the
  // static neighbour it now reaches is reported.
  const AABB moved = shifted(tight, Real(0.45), 0);
  EXPECT_TRUE(broadPhase.updateProxy(key, moved));
  EXPECT_TRUE(sameBox(broadPhase.fatAABB(key), moved.expanded(kAabbMargin)));
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{1, 2}, {1, 4}}));
}

TEST(BroadPhase, StaticProxiesPairOnlyWithMovableOnes_EvenWhenTouched) {
  BroadPhase broadPhase;
  const std::int32_t wall = broadPhase.createProxy(makeBox(0, 0, 1, 1), 1, Kind::Static);
  broadPhase.createProxy(makeBox(Real(0.5), 0, 1, 1), 2, Kind::Static);
  std::vector<ProxyPair> pairs;
  broadPhase.findNewPairs(pairs);
  EXPECT_TRUE(pairs.empty());

  broadPhase.touchProxy(wall);
  broadPhase.findNewPairs(pairs);
  EXPECT_TRUE(pairs.empty());

  // A movable proxy reaching the wall only: found when created, and found
  // again through the wall when the wall is touched.
  broadPhase.createProxy(makeBox(Real(-1.2), 0, Real(0.5), Real(0.5)), 3, Kind::Movable);
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{1, 3}}));
  broadPhase.touchProxy(wall);
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{1, 3}}));
}

TEST(BroadPhase, PairOfTwoMovedProxiesIsReportedOnce) {
  BroadPhase broadPhase;
  const std::int32_t a = broadPhase.createProxy(makeBox(0, 0, 1, 1), 7, Kind::Movable);
  broadPhase.createProxy(makeBox(1, 0, 1, 1), 3, Kind::Movable);
  std::vector<ProxyPair> pairs;
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{3, 7}}));

  // Moved and touched in the same step: still one pair.
  EXPECT_TRUE(broadPhase.updateProxy(a, makeBox(Real(0.5), 0, 1, 1)));
  broadPhase.touchProxy(a);
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{3, 7}}));
}

TEST(BroadPhase, FindNewPairsEmptiesTheQueue) {
  BroadPhase broadPhase;
  broadPhase.createProxy(makeBox(0, 0, 1, 1), 1, Kind::Movable);
  broadPhase.createProxy(makeBox(1, 0, 1, 1), 2, Kind::Movable);
  std::vector<ProxyPair> pairs;
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs.size(), 1U);
  broadPhase.findNewPairs(pairs);
  EXPECT_TRUE(pairs.empty());
}

TEST(BroadPhase, DestroyedProxiesNeverAppear) {
  BroadPhase broadPhase;
  const std::int32_t doomed = broadPhase.createProxy(makeBox(0, 0, 1, 1), 1, Kind::Movable);
  const std::int32_t other = broadPhase.createProxy(makeBox(1, 0, 1, 1), 2, Kind::Movable);
  broadPhase.createProxy(makeBox(0, 1, 1, 1), 3, Kind::Static);
  broadPhase.touchProxy(doomed);
  broadPhase.destroyProxy(doomed);
  EXPECT_EQ(broadPhase.proxyCount(), 2);

  std::vector<ProxyPair> pairs;
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{2, 3}}));

  broadPhase.touchProxy(other);
  broadPhase.findNewPairs(pairs);
  EXPECT_FALSE(containsUser(pairs, 1));

  std::vector<std::int32_t> visited;
  broadPhase.query(makeBox(0, 0, 5, 5), [&](std::int32_t user) {
    visited.push_back(user);
    return true;
  });
  std::sort(visited.begin(), visited.end());
  EXPECT_EQ(visited, (std::vector<std::int32_t>{2, 3}));
}

TEST(BroadPhase, ReusedKeyCarriesOnlyTheNewProxy) {
  BroadPhase broadPhase;
  broadPhase.createProxy(makeBox(0, 0, 1, 1), 1, Kind::Static);
  const std::int32_t first = broadPhase.createProxy(makeBox(0, 0, 1, 1), 2, Kind::Movable);
  broadPhase.destroyProxy(first);
  // The movable tree's only node is freed and reused, so the key comes back.
  const std::int32_t second = broadPhase.createProxy(makeBox(0, 0, 1, 1), 3, Kind::Movable);
  ASSERT_EQ(second, first);
  std::vector<ProxyPair> pairs;
  broadPhase.findNewPairs(pairs);
  EXPECT_EQ(pairs, (std::vector<ProxyPair>{{1, 3}}));
}

TEST(BroadPhase, QueryVisitsBothKindsAndStopsEarly) {
  BroadPhase broadPhase;
  broadPhase.createProxy(makeBox(0, 0, 1, 1), 1, Kind::Static);
  broadPhase.createProxy(makeBox(0, 0, 1, 1), 2, Kind::Movable);
  broadPhase.createProxy(makeBox(9, 9, 1, 1), 3, Kind::Movable);
  std::vector<std::int32_t> visited;
  broadPhase.query(makeBox(0, 0, Real(0.5), Real(0.5)), [&](std::int32_t user) {
    visited.push_back(user);
    return true;
  });
  std::sort(visited.begin(), visited.end());
  EXPECT_EQ(visited, (std::vector<std::int32_t>{1, 2}));

  int visits = 0;
  broadPhase.query(makeBox(0, 0, Real(0.5), Real(0.5)), [&](std::int32_t) {
    ++visits;
    return false;
  });
  EXPECT_EQ(visits, 1);
}

}  // namespace
}  // namespace impulse
