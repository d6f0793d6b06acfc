#include "impulse/server/simulation.h"

#include <chrono>

namespace impulse::server {

namespace {

WorldSettings worldSettings(const SimulationSettings& settings) {
  WorldSettings world;
  world.subSteps = settings.subSteps;
  world.maxBodies = settings.maxBodies;
  return world;
}

}  // namespace

Simulation::Simulation(const SimulationSettings& settings)
    : tickHz_(settings.tickHz),
      world_(worldSettings(settings)),
      snapshots_(world_),
      paused_(settings.paused),
      stepTimes_(std::size_t(settings.tickHz + 0.5)) {
  loadPreset(settings.preset, Material::Solid);
}

void Simulation::step() {
  const auto start = std::chrono::steady_clock::now();
  world_.step(Real(1.0 / tickHz_));
  ++tick_;
  stepTimes_.record(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  snapshots_.stepped(world_.movedBodies());
  for (const BodyId id : world_.escapedBodies()) snapshots_.bodyLeftWorld(id);
  bodiesLeftWorld_ += world_.escapedBodies().size();
}

std::uint64_t Simulation::stateHash() {
  // Every change to the world goes through the snapshot builder, whose
  // version therefore names the world's state.
  if (hashVersion_ != snapshots_.version()) {
    hash_ = world_.stateHash();
    hashVersion_ = snapshots_.version();
  }
  return hash_;
}

bool Simulation::loadPreset(int id, Material selected) {
  const auto info = impulse::loadPreset(world_, id, selected);
  if (!info) return false;
  snapshots_.worldReplaced(*info);
  return true;
}

void Simulation::clear() {
  world_.clear();
  snapshots_.worldReplaced(snapshots_.preset());
}

void Simulation::setPaused(bool paused) {
  paused_ = paused;
  snapshots_.worldChanged();
}

}  // namespace impulse::server
