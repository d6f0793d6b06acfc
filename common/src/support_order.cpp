#include "support_order.h"

#include <algorithm>

#include "world_data.h"

namespace impulse {

namespace {

constexpr std::int32_t kUnreached = -1;
// cos(60 degrees): steeper contacts lean on their neighbour rather than
// stand on it.
constexpr Real kMinUpwardNormal = Real(0.5);

// A jointed body is held by more than its contacts: lifting it alone would
// fight its joints (a welded pair landing twisted), so the soft rows keep it.
bool isJointed(const WorldData& world, std::int32_t state) {
  return world.bodies[world.solverIntegration[std::size_t(state)].body].jointHead != kNullIndex;
}

}  // namespace

// Breadth-first from the static dummy (state 0) over the touching contacts,
// held as adjacency lists in one array (counted, then filled).
void SupportOrder::levelBodies(std::span<const ConstraintRef> refs, std::size_t stateCount) {
  edgeStart_.assign(stateCount + 1, 0);
  for (const ConstraintRef& ref : refs) {
    ++edgeStart_[std::size_t(ref.stateA) + 1];
    ++edgeStart_[std::size_t(ref.stateB) + 1];
  }
  for (std::size_t s = 1; s <= stateCount; ++s) edgeStart_[s] += edgeStart_[s - 1];
  neighbours_.resize(2 * refs.size());
  queue_.assign(edgeStart_.begin(), edgeStart_.end() - 1);  // fill cursors, reused below
  for (const ConstraintRef& ref : refs) {
    neighbours_[std::size_t(queue_[std::size_t(ref.stateA)]++)] = ref.stateB;
    neighbours_[std::size_t(queue_[std::size_t(ref.stateB)]++)] = ref.stateA;
  }
  level_.assign(stateCount, kUnreached);
  level_[0] = 0;
  queue_.assign(1, 0);
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    std::int32_t state = queue_[head];
    for (std::int32_t e = edgeStart_[std::size_t(state)]; e < edgeStart_[std::size_t(state) + 1]; ++e) {
      std::int32_t next = neighbours_[std::size_t(e)];
      if (level_[std::size_t(next)] != kUnreached) continue;
      level_[std::size_t(next)] = level_[std::size_t(state)] + 1;
      queue_.push_back(next);
    }
  }
}

void SupportOrder::build(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount) {
  rows_.clear();
  levelStart_.assign(1, 0);
  const Vec2 gravity = world.settings.gravity;
  if (refs.empty() || gravity.squaredNorm() == 0) return;
  const Vec2 up = -gravity.normalized();
  levelBodies(refs, stateCount);

  unsorted_.clear();
  rowLevel_.clear();
  std::int32_t topLevel = 0;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ConstraintRef& ref = refs[i];
    Real upward = world.contacts[ref.contact].manifold.normal.dot(up);
    if (std::abs(upward) < kMinUpwardNormal) continue;
    const bool upperIsB = upward > 0;
    std::int32_t lower = level_[std::size_t(upperIsB ? ref.stateA : ref.stateB)];
    std::int32_t upper = level_[std::size_t(upperIsB ? ref.stateB : ref.stateA)];
    if (lower == kUnreached || upper <= lower || isJointed(world, upperIsB ? ref.stateB : ref.stateA)) continue;
    ref.holdsUp = true;
    unsorted_.push_back({static_cast<std::int32_t>(i), upperIsB});
    rowLevel_.push_back(lower);
    topLevel = std::max(topLevel, lower);
  }
  // Counting sort by the lower body's level, stable: the ground's contacts
  // first, then each storey in contact order.
  levelStart_.assign(std::size_t(topLevel) + 2, 0);
  for (std::int32_t level : rowLevel_) ++levelStart_[std::size_t(level) + 1];
  for (std::size_t l = 1; l < levelStart_.size(); ++l) levelStart_[l] += levelStart_[l - 1];
  rows_.resize(unsorted_.size());
  for (std::size_t r = 0; r < unsorted_.size(); ++r) {
    rows_[std::size_t(levelStart_[std::size_t(rowLevel_[r])]++)] = unsorted_[r];
  }
  // The fill moved each start to the next level's: shift back by one.
  levelStart_.pop_back();
  levelStart_.insert(levelStart_.begin(), 0);
}

}  // namespace impulse
