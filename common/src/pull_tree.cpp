// Barnes-Hut quadtree for gravitation (impulse/gravitation.h states the
// error bound it keeps): cells hold their mass, centre of mass, spread and
// radius; a far cell pulls as one mass.

#include <algorithm>
#include <cmath>

#include "impulse/gravitation.h"

namespace impulse {

namespace {

constexpr int kLeafSize = 8;
// Coincident masses cannot be split; past this depth a cell stays a leaf.
constexpr int kMaxDepth = 32;

}  // namespace

void PullTree::build(std::span<const PointMass> masses) {
  masses_ = masses;
  cells_.clear();
  order_.resize(masses.size());
  for (std::size_t i = 0; i < masses.size(); ++i) order_[i] = static_cast<int>(i);
  if (masses.empty()) return;
  Vec2d lower = masses[0].position, upper = masses[0].position;
  for (const PointMass& m : masses) {
    lower = lower.cwiseMin(m.position);
    upper = upper.cwiseMax(m.position);
  }
  buildCell(lower, upper, 0, static_cast<int>(masses.size()), 0);
}

int PullTree::buildCell(Vec2d lower, Vec2d upper, int begin, int end, int depth) {
  const int index = static_cast<int>(cells_.size());
  cells_.push_back({lower, upper});
  cells_[index].begin = begin;
  cells_[index].end = end;
  summarise(cells_[index]);
  if (end - begin <= kLeafSize || depth >= kMaxDepth) return index;
  const Vec2d middle = 0.5 * (lower + upper);
  int* first = order_.data() + begin;
  int* last = order_.data() + end;
  int* splitY = std::partition(first, last, [&](int i) { return masses_[i].position.y() < middle.y(); });
  int* splitLowX = std::partition(first, splitY, [&](int i) { return masses_[i].position.x() < middle.x(); });
  int* splitHighX = std::partition(splitY, last, [&](int i) { return masses_[i].position.x() < middle.x(); });
  const int bounds[5] = {begin, int(splitLowX - order_.data()), int(splitY - order_.data()),
                         int(splitHighX - order_.data()), end};
  const Vec2d quarterLower[4] = {lower, {middle.x(), lower.y()}, {lower.x(), middle.y()}, middle};
  const Vec2d quarterUpper[4] = {middle, {upper.x(), middle.y()}, {middle.x(), upper.y()}, upper};
  for (int q = 0; q < 4; ++q) {
    if (bounds[q] == bounds[q + 1]) continue;
    const int child = buildCell(quarterLower[q], quarterUpper[q], bounds[q], bounds[q + 1], depth + 1);
    cells_[index].children[q] = child;
  }
  return index;
}

// Exact over the cell's masses (they are contiguous in order_).
void PullTree::summarise(Cell& cell) const {
  cell.mass = 0;
  Vec2d weighted = Vec2d::Zero();
  Vec2d momentum = Vec2d::Zero();
  cell.maxReach = 0;
  for (int k = cell.begin; k < cell.end; ++k) {
    const PointMass& m = masses_[order_[k]];
    cell.mass += m.mass;
    weighted += m.mass * m.position;
    momentum += m.mass * m.velocity;
    cell.maxReach = std::max(cell.maxReach, m.reach);
  }
  cell.centerOfMass = cell.mass > 0 ? Vec2d(weighted / cell.mass) : Vec2d(0.5 * (cell.lower + cell.upper));
  cell.velocity = cell.mass > 0 ? Vec2d(momentum / cell.mass) : Vec2d::Zero();
  cell.spread = 0;
  cell.radius = 0;
  for (int k = cell.begin; k < cell.end; ++k) {
    const PointMass& m = masses_[order_[k]];
    const double distance = (m.position - cell.centerOfMass).norm();
    cell.spread += m.mass * distance * distance;
    cell.radius = std::max(cell.radius, distance);
  }
}

Pull PullTree::pull(std::size_t target, double* bound) const {
  Pull sum;
  auto add = [&sum](const Pull& part) {
    sum.acceleration += part.acceleration;
    sum.change += part.change;
  };
  if (cells_.empty()) return sum;
  const PointMass& body = masses_[target];
  stack_.assign(1, 0);
  while (!stack_.empty()) {
    const Cell& cell = cells_[stack_.back()];
    stack_.pop_back();
    if (cell.mass <= 0) continue;
    const double distance = (cell.centerOfMass - body.position).norm();
    const double clearance = distance - cell.radius;
    const bool far = cell.radius < theta_ * distance && clearance > body.reach + cell.maxReach;
    if (far) {
      add(pullPerUnitG(body, {cell.centerOfMass, cell.mass, 0, cell.velocity}));
      if (bound) *bound += 3 * cell.spread / std::pow(clearance, 4);
    } else if (!cell.isLeaf()) {
      for (int child : cell.children) {
        if (child >= 0) stack_.push_back(child);
      }
    } else {
      for (int k = cell.begin; k < cell.end; ++k) {
        const std::size_t source = static_cast<std::size_t>(order_[k]);
        if (source == target) continue;
        add(pullPerUnitG(body, masses_[source]));
      }
    }
  }
  return sum;
}

}  // namespace impulse
