// Newton's gravitation as a force field: the exact pairwise sum for small
// worlds, the Barnes-Hut tree (pull_tree.cpp) for large ones. The pull is a
// force with its rate of change (FieldLoad::forceChange): the world kicks
// each body at every sub-step with the pull carried forward to that
// sub-step, so with the sub-steps' drift the step is close to symplectic
// Euler at the sub-step (a circular orbit keeps its radius, energy stays
// bounded instead of spiralling) for one evaluation of the field per step.

#include "impulse/gravitation.h"

#include <cmath>

#include "input_limits.h"

namespace impulse {

// The pull is m r / |r|^3 with r the offset; its rate with v the offset's
// rate is m (v - 3 (r.v) r / |r|^2) / |r|^3. Within the reaches the distance
// is held, leaving m r / d^3 and m v / d^3.
Pull pullPerUnitG(const PointMass& target, const PointMass& source) {
  const Vec2d offset = source.position - target.position;
  const double apart = offset.norm();
  const double distance = std::max(apart, target.reach + source.reach);
  if (distance == 0) return {};
  const double inverse = 1 / distance, inverseSquare = inverse * inverse;
  const double perCube = source.mass * inverse * inverseSquare;
  const Vec2d closing = source.velocity - target.velocity;
  const Vec2d turning = apart < distance ? closing : Vec2d(closing - 3 * offset.dot(closing) * inverseSquare * offset);
  return {perCube * offset, perCube * turning};
}

void exactPull(std::span<const PointMass> masses, double constant, std::span<Pull> pulls) {
  const std::size_t moving = pulls.size();
  for (Pull& pull : pulls) pull = {};
  // Moving pairs once each, equal and opposite (momentum is kept exactly).
  for (std::size_t i = 0; i < moving; ++i) {
    for (std::size_t j = i + 1; j < moving; ++j) {
      const Pull perMass = pullPerUnitG(masses[i], {masses[j].position, 1, masses[j].reach, masses[j].velocity});
      pulls[i].acceleration += masses[j].mass * perMass.acceleration;
      pulls[j].acceleration -= masses[i].mass * perMass.acceleration;
      pulls[i].change += masses[j].mass * perMass.change;
      pulls[j].change -= masses[i].mass * perMass.change;
    }
    for (std::size_t j = moving; j < masses.size(); ++j) {
      const Pull pull = pullPerUnitG(masses[i], masses[j]);
      pulls[i].acceleration += pull.acceleration;
      pulls[i].change += pull.change;
    }
  }
  for (Pull& pull : pulls) {
    pull.acceleration *= constant;
    pull.change *= constant;
  }
}

void Gravitation::pulls(std::size_t movingCount) const {
  pulls_.resize(movingCount);
  if (masses_.size() <= kExactLimit) {
    exactPull(masses_, constant_, pulls_);
    return;
  }
  tree_.build(masses_);
  for (std::size_t i = 0; i < movingCount; ++i) {
    const Pull pull = tree_.pull(i);
    pulls_[i] = {constant_ * pull.acceleration, constant_ * pull.change};
  }
}

void Gravitation::apply(const FieldStep& step, std::span<FieldLoad> loads) const {
  masses_.clear();
  auto add = [&](const FieldBody& body) {
    masses_.push_back({body.transform.p.cast<double>(), double(body.mass), double(body.extent),
                       body.linearVelocity.cast<double>()});
  };
  for (const FieldBody& body : step.bodies) add(body);
  for (const FieldBody& body : step.stillBodies) add(body);
  pulls(step.bodies.size());
  for (std::size_t i = 0; i < step.bodies.size(); ++i) {
    const double mass = step.bodies[i].mass;
    loads[i].force += (mass * pulls_[i].acceleration).cast<Real>();
    loads[i].forceChange += (mass * pulls_[i].change).cast<Real>();
  }
}

FieldBuild makeGravitation(const GravitationDef& def) {
  if (!std::isfinite(def.constant) || def.constant <= 0 || def.constant > 1000) {
    return {nullptr, "gravitation constant " + describeNumber(def.constant) + " is outside (0, 1000]"};
  }
  return {std::make_shared<Gravitation>(def.constant), {}};
}

}  // namespace impulse
