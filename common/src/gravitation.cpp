// Newton's gravitation as a force field: the exact pairwise sum for small
// worlds, the Barnes-Hut tree (pull_tree.cpp) for large ones. The pull is
// given as an impulse at every sub-step (everySubStep), so with the
// sub-steps' drift the step is symplectic Euler for it at the sub-step: a
// circular orbit keeps its radius and energy stays bounded instead of
// spiralling.

#include "impulse/gravitation.h"

#include <cmath>

#include "input_limits.h"

namespace impulse {

Vec2d pullPerUnitG(const PointMass& target, const PointMass& source) {
  const Vec2d offset = source.position - target.position;
  const double nearest = target.reach + source.reach;
  const double distance = std::max(offset.norm(), nearest);
  if (distance == 0) return Vec2d::Zero();
  return source.mass / (distance * distance * distance) * offset;
}

void exactPull(std::span<const PointMass> masses, double constant, std::span<Vec2d> accelerations) {
  const std::size_t moving = accelerations.size();
  for (Vec2d& a : accelerations) a.setZero();
  // Moving pairs once each, equal and opposite (momentum is kept exactly).
  for (std::size_t i = 0; i < moving; ++i) {
    for (std::size_t j = i + 1; j < moving; ++j) {
      const Vec2d perMass = pullPerUnitG(masses[i], {masses[j].position, 1, masses[j].reach});
      accelerations[i] += masses[j].mass * perMass;
      accelerations[j] -= masses[i].mass * perMass;
    }
    for (std::size_t j = moving; j < masses.size(); ++j) accelerations[i] += pullPerUnitG(masses[i], masses[j]);
  }
  for (Vec2d& a : accelerations) a *= constant;
}

void Gravitation::accelerations(std::size_t movingCount) const {
  accelerations_.resize(movingCount);
  if (masses_.size() <= kExactLimit) {
    exactPull(masses_, constant_, accelerations_);
    return;
  }
  tree_.build(masses_);
  for (std::size_t i = 0; i < movingCount; ++i) accelerations_[i] = constant_ * tree_.acceleration(i);
}

void Gravitation::apply(const FieldStep& step, std::span<FieldLoad> loads) const {
  masses_.clear();
  auto add = [&](const FieldBody& body) {
    masses_.push_back({body.transform.p.cast<double>(), double(body.mass), double(body.extent)});
  };
  for (const FieldBody& body : step.bodies) add(body);
  for (const FieldBody& body : step.stillBodies) add(body);
  accelerations(step.bodies.size());
  for (std::size_t i = 0; i < step.bodies.size(); ++i) {
    loads[i].impulse += (double(step.bodies[i].mass) * double(step.dt) * accelerations_[i]).cast<Real>();
  }
}

FieldBuild makeGravitation(const GravitationDef& def) {
  if (!std::isfinite(def.constant) || def.constant <= 0 || def.constant > 1000) {
    return {nullptr, "gravitation constant " + describeNumber(def.constant) + " is outside (0, 1000]"};
  }
  return {std::make_shared<Gravitation>(def.constant), {}};
}

}  // namespace impulse
