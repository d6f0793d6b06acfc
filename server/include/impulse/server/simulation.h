#pragma once
/// The served world: engine world, tick counter, pause state and the snapshot
/// bookkeeping that every change to the world must go through.

#include <cstdint>

#include "impulse/material.h"
#include "impulse/scenes/presets.h"
#include "impulse/server/snapshot_builder.h"
#include "impulse/server/tick_schedule.h"
#include "impulse/world.h"

namespace impulse::server {

struct SimulationSettings {
  double tickHz = 60;
  int subSteps = 4;
  int maxBodies = 10000;
  int preset = 0;
  bool paused = false;
};

class Simulation {
 public:
  explicit Simulation(const SimulationSettings& settings);

  World& world() { return world_; }
  const World& world() const { return world_; }
  SnapshotBuilder& snapshots() { return snapshots_; }

  /// Advances one tick and records what moved.
  void step();
  /// Replaces the world with preset `id`; false (world untouched) when out of range.
  bool loadPreset(int id, Material selected);
  /// Removes every body.
  void clear();

  std::uint64_t tick() const { return tick_; }
  double tickHz() const { return tickHz_; }
  double simTime() const { return double(tick_) / tickHz_; }
  bool paused() const { return paused_; }
  void setPaused(bool paused);
  SnapshotMeta meta() const { return {tick_, simTime(), paused_}; }
  /// Wall-clock milliseconds of the world steps over the last second.
  const TickTimes& stepTimes() const { return stepTimes_; }
  /// World::stateHash(), computed at most once per change of the world.
  std::uint64_t stateHash();
  /// Bodies removed so far for leaving the world bounds far behind.
  std::uint64_t bodiesLeftWorld() const { return bodiesLeftWorld_; }

 private:
  double tickHz_;
  World world_;
  SnapshotBuilder snapshots_;
  std::uint64_t tick_ = 0;
  bool paused_ = false;
  TickTimes stepTimes_;
  std::uint64_t bodiesLeftWorld_ = 0;
  std::uint64_t hash_ = 0;
  std::uint64_t hashVersion_ = ~std::uint64_t(0);
};

}  // namespace impulse::server
