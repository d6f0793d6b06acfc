// The engine's workers drawn from the stepping pool (pool_tasks.h): a big
// world uses an idle pool's threads, busy worlds never run on more threads
// than the pool has, and a task finishes when no helper can start.
#include "impulse/server/pool_tasks.h"

#include <gtest/gtest.h>

#include <asio/post.hpp>
#include <asio/strand.hpp>
#include <asio/thread_pool.hpp>
#include <chrono>
#include <filesystem>
#include <future>
#include <memory>
#include <vector>

#include "impulse/scenes/stress.h"
#include "impulse/server/simulation.h"
#include "impulse/wire/scene_convert.h"
#include "impulse/world.h"

namespace impulse::server {
namespace {

constexpr Real kDt = Real(1) / 60;
constexpr auto kNoStall = std::chrono::seconds(30);

std::unique_ptr<World> pyramidWorld(int rows, const TaskSettings& tasks) {
  WorldSettings settings;
  settings.tasks = tasks;
  auto world = std::make_unique<World>(settings);
  buildPyramid(*world, rows);
  return world;
}

std::uint64_t oneWorkerHash(int rows, int steps) {
  auto world = pyramidWorld(rows, {});
  for (int i = 0; i < steps; ++i) world->step(kDt);
  return world->stateHash();
}

// Steps `world` on a thread of the pool, as a room's tick does.
template <class Executor>
std::future<void> stepOn(const Executor& executor, World& world, int steps) {
  auto done = std::make_shared<std::promise<void>>();
  auto finished = done->get_future();
  asio::post(executor, [&world, steps, done] {
    for (int i = 0; i < steps; ++i) world.step(kDt);
    done->set_value();
  });
  return finished;
}

int processThreads() {
  const std::filesystem::path tasks("/proc/self/task");
  return int(std::distance(std::filesystem::directory_iterator(tasks),
                           std::filesystem::directory_iterator()));
}

TEST(PoolTasks, BigWorldStepsOnTwoThreadsOfAnIdlePool_WithTheOneWorkerBits) {
  constexpr int kRows = 100;  // 5 050 boxes
  constexpr int kSteps = 60;
  asio::thread_pool pool(2);
  PoolTaskCounts counts;
  PoolTasks tasks(pool, 2, &counts);
  auto world = pyramidWorld(kRows, tasks.taskSettings());

  auto stepped = stepOn(pool.get_executor(), *world, kSteps);
  const auto status = stepped.wait_for(kNoStall);
  pool.join();  // even a late step ends before the world it steps goes

  ASSERT_EQ(status, std::future_status::ready);

  // The pool's other thread ran part of the step.
  EXPECT_GT(counts.helpedRanges.load(), 0);
  EXPECT_LE(counts.peakRunning.load(), 2);
  EXPECT_EQ(world->stateHash(), oneWorkerHash(kRows, kSteps));
  // The step's phases run one after another: every one reused one record.
  EXPECT_EQ(tasks.taskRecords(), 1u);
}

TEST(PoolTasks, BusyWorldsOnATwoThreadPool_NeverRunOnMoreThreads_AndAllAdvance) {
  constexpr int kWorlds = 6;
  constexpr int kRows = 20;  // 210 boxes each
  constexpr int kSteps = 40;
  const int threadsBefore = processThreads();
  asio::thread_pool pool(2);
  PoolTaskCounts counts;
  PoolTasks tasks(pool, 2, &counts);
  std::vector<std::unique_ptr<World>> worlds;
  std::vector<std::future<void>> stepped;
  for (int i = 0; i < kWorlds; ++i) {
    worlds.push_back(pyramidWorld(kRows, tasks.taskSettings()));
    // One strand per world, like a room: a world is never stepped by two threads.
    stepped.push_back(stepOn(asio::make_strand(pool.get_executor()), *worlds.back(), kSteps));
  }

  int mostThreads = 0;
  for (auto& world : stepped) {
    while (world.wait_for(std::chrono::milliseconds(1)) != std::future_status::ready) {
      mostThreads = std::max(mostThreads, processThreads());
    }
  }
  pool.join();

  EXPECT_LE(counts.peakRunning.load(), 2);
  // A record per world stepping at once (two threads), however many phases.
  EXPECT_LE(tasks.taskRecords(), 2u);
  // The pool's two threads and no world's own.
  EXPECT_LE(mostThreads, threadsBefore + 2);
  const std::uint64_t expected = oneWorkerHash(kRows, kSteps);
  for (const auto& world : worlds) EXPECT_EQ(world->stateHash(), expected);
}

TEST(PoolTasks, OneThreadPool_RunsEveryRangeOnTheSteppingThread) {
  constexpr int kRows = 30;
  constexpr int kSteps = 30;
  asio::thread_pool pool(1);
  // More workers than threads: every helper queues behind the step itself.
  PoolTaskCounts counts;
  PoolTasks tasks(pool, 2, &counts);
  auto world = pyramidWorld(kRows, tasks.taskSettings());

  auto stepped = stepOn(pool.get_executor(), *world, kSteps);
  const auto status = stepped.wait_for(kNoStall);
  pool.join();  // even a late step ends before the world it steps goes

  ASSERT_EQ(status, std::future_status::ready);

  EXPECT_EQ(counts.helpedRanges.load(), 0);
  EXPECT_EQ(counts.peakRunning.load(), 1);
  EXPECT_EQ(world->stateHash(), oneWorkerHash(kRows, kSteps));
}

TEST(PoolTasks, PoolSaturatedByAnotherRoom_StepFinishesWithoutItsHelpers) {
  constexpr int kRows = 30;
  constexpr int kSteps = 30;
  asio::thread_pool pool(2);
  PoolTaskCounts counts;
  PoolTasks tasks(pool, 2, &counts);
  auto world = pyramidWorld(kRows, tasks.taskSettings());

  // Another room's long tick holds the pool's other thread throughout.
  std::promise<void> busyStarted;
  std::promise<void> release;
  asio::post(pool, [&busyStarted, released = release.get_future()] {
    busyStarted.set_value();
    released.wait();
  });
  busyStarted.get_future().wait();
  auto stepped = stepOn(pool.get_executor(), *world, kSteps);
  const auto status = stepped.wait_for(kNoStall);
  release.set_value();
  pool.join();

  ASSERT_EQ(status, std::future_status::ready);
  EXPECT_EQ(counts.helpedRanges.load(), 0);
  EXPECT_EQ(counts.peakRunning.load(), 1);
  EXPECT_EQ(world->stateHash(), oneWorkerHash(kRows, kSteps));
}

TEST(PoolTasks, RoomWorldKeepsItsWorkers_AcrossPresetsScenesAndClear) {
  asio::thread_pool pool(2);
  PoolTasks tasks(pool, 2);
  Simulation simulation({.tasks = tasks.taskSettings()});
  const auto onThePool = [&] {
    const TaskSettings now = simulation.world().taskSettings();
    return now.workerCount == 2 && now.enqueueTask != nullptr && now.userContext == &tasks;
  };
  EXPECT_TRUE(onThePool());
  ASSERT_TRUE(simulation.loadPreset(1, Material::Solid));
  EXPECT_TRUE(onThePool());
  ASSERT_TRUE(simulation.loadScene(wire::saveScene(simulation.world())).ok());
  EXPECT_TRUE(onThePool());
  simulation.clear();
  EXPECT_TRUE(onThePool());
  pool.join();
}

}  // namespace
}  // namespace impulse::server
