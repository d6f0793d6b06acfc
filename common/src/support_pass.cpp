#include "support_pass.h"

#include <algorithm>

#include "world_data.h"

namespace impulse {

namespace {

constexpr std::int32_t kUnreached = -1;
// cos(25 degrees): a body stands on contacts this close to level. Steeper
// ones lean on their neighbour; among them the 30 degrees of circles packed
// in a pile, which lifting one-sidedly would keep stirring.
constexpr Real kMinUpwardNormal = Real(0.9);

// A jointed body is held by more than its contacts: lifting it alone would
// fight its joints (a welded pair landing twisted), so the soft rows keep it.
bool isJointed(const WorldData& world, std::int32_t state) {
  return world.bodies[world.solverIntegration[std::size_t(state)].body].jointHead != kNullIndex;
}

}  // namespace

// Breadth-first from the static dummy (state 0) over the level contacts
// (by facing_), held as adjacency lists in one array (counted, then
// filled). Only level contacts count: a column of circles against a wall
// touches the static world at every storey, yet stands on the ground alone.
void SupportPass::levelBodies(std::span<const ConstraintRef> refs, std::size_t stateCount) {
  edgeStart_.assign(stateCount + 1, 0);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (facing_[i] == 0) continue;
    ++edgeStart_[std::size_t(refs[i].stateA) + 1];
    ++edgeStart_[std::size_t(refs[i].stateB) + 1];
  }
  for (std::size_t s = 1; s <= stateCount; ++s) edgeStart_[s] += edgeStart_[s - 1];
  neighbours_.resize(std::size_t(edgeStart_[stateCount]));
  cursor_.assign(edgeStart_.begin(), edgeStart_.end() - 1);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (facing_[i] == 0) continue;
    const ConstraintRef& ref = refs[i];
    neighbours_[std::size_t(cursor_[std::size_t(ref.stateA)]++)] = ref.stateB;
    neighbours_[std::size_t(cursor_[std::size_t(ref.stateB)]++)] = ref.stateA;
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

void SupportPass::classifyContacts(const WorldData& world, std::span<const ConstraintRef> refs) {
  const Vec2 up = -world.settings.gravity.normalized();
  facing_.resize(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const Real upward = world.contacts[refs[i].contact].manifold.normal.dot(up);
    facing_[i] = upward >= kMinUpwardNormal ? 1 : upward <= -kMinUpwardNormal ? -1 : 0;
  }
}

bool SupportPass::sameGraphAsLastStep(const WorldData& world, std::span<const ConstraintRef> refs) const {
  auto sameRef = [](const ConstraintRef& a, const ConstraintRef& b) {
    return a.contact == b.contact && a.stateA == b.stateA && a.stateB == b.stateB;
  };
  return haveLast_ && world.jointLinkChanges == lastJointLinkChanges_ && facing_ == lastFacing_ &&
         world.awakeBodies == lastAwake_ && std::equal(refs.begin(), refs.end(), lastRefs_.begin(), lastRefs_.end(), sameRef);
}

void SupportPass::remember(const WorldData& world, std::span<const ConstraintRef> refs) {
  lastRefs_.assign(refs.begin(), refs.end());
  lastFacing_ = facing_;
  lastAwake_ = world.awakeBodies;
  lastJointLinkChanges_ = world.jointLinkChanges;
  haveLast_ = true;
}

void SupportPass::order(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount) {
  if (refs.empty() || world.settings.gravity.squaredNorm() == 0) {
    rows_.clear();
    groupStart_.assign(1, 0);
    storeyGroupStart_.assign(1, 0);
    haveLast_ = false;
    return;
  }
  classifyContacts(world, refs);
  if (sameGraphAsLastStep(world, refs)) {
    for (const SupportRow& row : rows_) refs[std::size_t(row.ref)].holdsUp = true;
    return;
  }
  rows_.clear();
  groupStart_.assign(1, 0);
  storeyGroupStart_.assign(1, 0);
  levelBodies(refs, stateCount);

  unsorted_.clear();
  rowLevel_.clear();
  std::int32_t topLevel = 0;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ConstraintRef& ref = refs[i];
    if (facing_[i] == 0) continue;
    const bool upperIsB = facing_[i] > 0;
    std::int32_t lower = level_[std::size_t(upperIsB ? ref.stateA : ref.stateB)];
    std::int32_t upper = level_[std::size_t(upperIsB ? ref.stateB : ref.stateA)];
    if (lower == kUnreached || upper <= lower || isJointed(world, upperIsB ? ref.stateB : ref.stateA)) continue;
    ref.holdsUp = true;
    SupportRow row;
    row.ref = static_cast<std::int32_t>(i);
    row.upperIsB = upperIsB;
    unsorted_.push_back(row);
    rowLevel_.push_back(lower);
    topLevel = std::max(topLevel, lower);
  }
  // Counting sort by the lower body's level, stable: the ground's contacts
  // first, then each storey in contact order.
  storeyStart_.assign(std::size_t(topLevel) + 2, 0);
  for (std::int32_t level : rowLevel_) ++storeyStart_[std::size_t(level) + 1];
  for (std::size_t l = 1; l < storeyStart_.size(); ++l) storeyStart_[l] += storeyStart_[l - 1];
  byStorey_.resize(unsorted_.size());
  cursor_.assign(storeyStart_.begin(), storeyStart_.end() - 1);
  for (std::size_t r = 0; r < unsorted_.size(); ++r) {
    byStorey_[std::size_t(cursor_[std::size_t(rowLevel_[r])]++)] = unsorted_[r];
  }
  rows_.resize(byStorey_.size());
  rowGroup_.resize(byStorey_.size());
  upperStorey_.assign(stateCount, -1);
  upperRows_.resize(stateCount);
  for (std::size_t storey = 0; storey + 1 < storeyStart_.size(); ++storey) {
    groupStorey(refs, storey);
  }
  remember(world, refs);
}

// A body's k-th row in the storey goes to group k; the groups are then laid
// out in order (a stable counting sort), each keeping contact order.
void SupportPass::groupStorey(std::span<const ConstraintRef> refs, std::size_t storey) {
  const std::size_t first = std::size_t(storeyStart_[storey]);
  const std::size_t end = std::size_t(storeyStart_[storey + 1]);
  std::int32_t groups = 0;
  for (std::size_t r = first; r < end; ++r) {
    const ConstraintRef& ref = refs[std::size_t(byStorey_[r].ref)];
    const std::size_t upper = std::size_t(byStorey_[r].upperIsB ? ref.stateB : ref.stateA);
    if (upperStorey_[upper] != std::int32_t(storey)) {
      upperStorey_[upper] = std::int32_t(storey);
      upperRows_[upper] = 0;
    }
    rowGroup_[r] = upperRows_[upper]++;
    groups = std::max(groups, rowGroup_[r] + 1);
  }
  const std::size_t base = groupStart_.size() - 1;  // the storey's first group
  groupStart_.resize(base + std::size_t(groups) + 1, 0);
  for (std::size_t r = first; r < end; ++r) ++groupStart_[base + std::size_t(rowGroup_[r]) + 1];
  for (std::size_t g = base + 1; g < groupStart_.size(); ++g) groupStart_[g] += groupStart_[g - 1];
  cursor_.assign(groupStart_.begin() + std::ptrdiff_t(base), groupStart_.end() - 1);
  for (std::size_t r = first; r < end; ++r) {
    rows_[std::size_t(cursor_[std::size_t(rowGroup_[r])]++)] = byStorey_[r];
  }
  storeyGroupStart_.push_back(std::int32_t(groupStart_.size() - 1));
}

}  // namespace impulse
