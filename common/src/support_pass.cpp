#include "support_pass.h"

#include <algorithm>
#include <array>

#include "world_data.h"

namespace impulse {

namespace {

constexpr std::int32_t kUnreached = -1;
// cos(25 degrees): a body stands on contacts this close to level. Steeper
// ones lean on their neighbour; among them the 30 degrees of circles packed
// in a pile, which lifting one-sidedly would keep stirring.
constexpr Real kMinUpwardNormal = Real(0.9);

bool isLevel(Real upward) { return std::abs(upward) >= kMinUpwardNormal; }

// A jointed body is held by more than its contacts: lifting it alone would
// fight its joints (a welded pair landing twisted), so the soft rows keep it.
bool isJointed(const WorldData& world, std::int32_t state) {
  return world.bodies[world.solverIntegration[std::size_t(state)].body].jointHead != kNullIndex;
}

// The smallest non-negative impulses (at most two points) that lift every
// point by its shortfall b: the 2x2 linear complementarity problem by its
// cases. Solving the two points one after the other instead gives the first
// a spin the second only half undoes: a box resting flat crept sideways.
std::array<Real, 2> liftImpulses(const SupportRow& row, Real b1, Real b2) {
  Real l1 = row.pairInverse11 * b1 + row.pairInverse12 * b2;
  Real l2 = row.pairInverse12 * b1 + row.pairInverse22 * b2;
  if (l1 >= 0 && l2 >= 0 && (l1 > 0 || l2 > 0)) return {l1, l2};
  Real alone1 = b1 * row.singleMass[0];
  if (alone1 > 0 && row.k12 * alone1 >= b2) return {alone1, 0};
  Real alone2 = b2 * row.singleMass[1];
  if (alone2 > 0 && row.k12 * alone2 >= b1) return {0, alone2};
  return {0, 0};
}

Vec2 pointVelocity(const SolverState& state, const Vec2& anchor) {
  return state.linearVelocity + cross(state.angularVelocity, anchor);
}

// One row: with the lower body immovable, the upper body's points may not
// approach it (or, when apart, not close more than the gap this sub-step).
void holdUp(std::span<SolverState> states, Real inverseSubStep, SupportRow& row) {
  SolverState& a = states[std::size_t(row.stateA)];
  SolverState& b = states[std::size_t(row.stateB)];
  const Vec2 deltaPosition = b.deltaPosition - a.deltaPosition;
  std::array<Real, 2> shortfall{0, 0};
  for (std::size_t j = 0; j < 2; ++j) {
    const SupportRow::Point& p = row.points[j];
    if (!p.present) continue;
    Vec2 moved = deltaPosition + b.deltaRotation.apply(p.anchorB) - a.deltaRotation.apply(p.anchorA);
    Real separation = p.baseSeparation + moved.dot(row.normal);
    Real slowestAllowed = separation > 0 ? -separation * inverseSubStep : Real(0);
    Real normalSpeed = (pointVelocity(b, p.anchorB) - pointVelocity(a, p.anchorA)).dot(row.normal);
    shortfall[j] = slowestAllowed - normalSpeed;
  }
  if (shortfall[0] <= 0 && shortfall[1] <= 0) {
    row.impulse = {0, 0};
    return;
  }
  row.impulse = liftImpulses(row, shortfall[0], shortfall[1]);
  const Real arm0 = row.points[0].arm;
  const Real arm1 = row.points[1].arm;
  // The impulse pushes B along the normal and A against it: either way, up.
  SolverState& upper = row.upperIsB ? b : a;
  const Real lift = (row.upperIsB ? Real(1) : Real(-1)) * (row.impulse[0] + row.impulse[1]);
  const Real turn = (row.upperIsB ? Real(1) : Real(-1)) * (arm0 * row.impulse[0] + arm1 * row.impulse[1]);
  upper.linearVelocity += row.invMass * lift * row.normal;
  upper.angularVelocity += row.invInertia * turn;
}

// K_ij = invMass + invInertia * arm_i * arm_j over the present points; a
// missing point's row and column are left out (it has no shortfall).
void invertResponse(SupportRow& row) {
  const std::array<Real, 2> arm{row.points[0].arm, row.points[1].arm};
  auto k = [&](std::size_t i, std::size_t j) { return row.invMass + row.invInertia * arm[i] * arm[j]; };
  for (std::size_t j = 0; j < 2; ++j) row.singleMass[j] = row.points[j].present ? 1 / k(j, j) : Real(0);
  row.k12 = k(0, 1);
  row.pairInverse11 = row.pairInverse12 = row.pairInverse22 = 0;
  if (!row.points[0].present || !row.points[1].present) return;
  const Real det = k(0, 0) * k(1, 1) - row.k12 * row.k12;
  if (det <= Real(1e-6) * k(0, 0) * k(1, 1)) return;  // the points share one arm
  row.pairInverse11 = k(1, 1) / det;
  row.pairInverse12 = -row.k12 / det;
  row.pairInverse22 = k(0, 0) / det;
}

}  // namespace

void SupportPass::load(std::size_t index, const ContactConstraint& c) {
  SupportRow& row = rows_[index];
  row.stateA = c.stateA;
  row.stateB = c.stateB;
  row.normal = c.normal;
  row.invMass = row.upperIsB ? c.invMassB : c.invMassA;
  row.invInertia = row.upperIsB ? c.invInertiaB : c.invInertiaA;
  for (std::size_t j = 0; j < 2; ++j) {
    const ConstraintPoint& cp = c.points[j];
    SupportRow::Point& p = row.points[j];
    // A one-point manifold's second point has zero mass: it never lifts.
    p.present = int(j) < c.pointCount && cp.normalMass > 0;
    p.anchorA = cp.anchorA;
    p.anchorB = cp.anchorB;
    p.baseSeparation = cp.baseSeparation;
    p.arm = p.present ? cross(row.upperIsB ? cp.anchorB : cp.anchorA, c.normal) : Real(0);
    row.impulse[j] = 0;
  }
  invertResponse(row);
}

void SupportPass::solve(std::span<SolverState> states, Real inverseSubStep, bool reverse) {
  for (std::size_t storey = 0; storey + 1 < storeyStart_.size(); ++storey) {
    const std::int32_t first = storeyStart_[storey];
    const std::int32_t end = storeyStart_[storey + 1];
    for (std::int32_t k = 0; k < end - first; ++k) {
      holdUp(states, inverseSubStep, rows_[std::size_t(reverse ? end - 1 - k : first + k)]);
    }
  }
}

void SupportPass::store(WorldData& world, std::span<const ConstraintRef> refs) const {
  for (const SupportRow& row : rows_) {
    Manifold& manifold = world.contacts[refs[std::size_t(row.ref)].contact].manifold;
    for (int j = 0; j < manifold.pointCount; ++j) manifold.points[std::size_t(j)].supportImpulse = row.impulse[std::size_t(j)];
  }
}

// Breadth-first from the static dummy (state 0) over the level contacts
// (by upward_), held as adjacency lists in one array (counted, then
// filled). Only level contacts count: a column of circles against a wall
// touches the static world at every storey, yet stands on the ground alone.
void SupportPass::levelBodies(std::span<const ConstraintRef> refs, std::size_t stateCount) {
  edgeStart_.assign(stateCount + 1, 0);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (!isLevel(upward_[i])) continue;
    ++edgeStart_[std::size_t(refs[i].stateA) + 1];
    ++edgeStart_[std::size_t(refs[i].stateB) + 1];
  }
  for (std::size_t s = 1; s <= stateCount; ++s) edgeStart_[s] += edgeStart_[s - 1];
  neighbours_.resize(std::size_t(edgeStart_[stateCount]));
  cursor_.assign(edgeStart_.begin(), edgeStart_.end() - 1);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (!isLevel(upward_[i])) continue;
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

void SupportPass::order(const WorldData& world, std::span<ConstraintRef> refs, std::size_t stateCount) {
  rows_.clear();
  storeyStart_.assign(1, 0);
  const Vec2 gravity = world.settings.gravity;
  if (refs.empty() || gravity.squaredNorm() == 0) return;
  const Vec2 up = -gravity.normalized();
  upward_.resize(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    upward_[i] = world.contacts[refs[i].contact].manifold.normal.dot(up);
  }
  levelBodies(refs, stateCount);

  unsorted_.clear();
  rowLevel_.clear();
  std::int32_t topLevel = 0;
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ConstraintRef& ref = refs[i];
    if (!isLevel(upward_[i])) continue;
    const bool upperIsB = upward_[i] > 0;
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
  rows_.resize(unsorted_.size());
  cursor_.assign(storeyStart_.begin(), storeyStart_.end() - 1);
  for (std::size_t r = 0; r < unsorted_.size(); ++r) {
    rows_[std::size_t(cursor_[std::size_t(rowLevel_[r])]++)] = unsorted_[r];
  }
}

}  // namespace impulse
