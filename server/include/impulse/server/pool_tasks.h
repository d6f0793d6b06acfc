#pragma once
/// Engine workers from the stepping pool (impulse/tasks.h). A room's world
/// hands each parallel phase of its step here; the stepping thread that
/// runs the room works on it, and threads of the same pool that are idle
/// join in. No thread is started: every range runs on a pool thread, so the
/// rooms and their engine workers together never run on more threads than
/// the pool has.
///
/// Why it cannot deadlock: a task's ranges are claimed from one counter by
/// whichever thread comes first. Helpers are ordinary pool jobs that claim
/// what is still unclaimed; finishTask runs every range nobody took and
/// then waits only for ranges already running on other threads. A task
/// therefore finishes even when no helper ever starts: a one-thread pool,
/// or every other thread busy with another room.
///
/// Why a busy pool is not flooded: a helper is posted only when fewer
/// helpers than the task could use are already waiting in the pool's queue
/// or idling for work. A helper that finds no open task idles for a moment
/// (the step's next phase follows within microseconds) and then returns
/// its thread to the pool.

#include <asio/thread_pool.hpp>
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "impulse/tasks.h"

namespace impulse::server {

class PoolTasks {
 public:
  /// `workersPerTask`: threads one task may use, its caller's included
  /// (1..kMaxWorkers). The pool must be joined before this is destroyed.
  PoolTasks(asio::thread_pool& pool, int workersPerTask);
  PoolTasks(const PoolTasks&) = delete;
  PoolTasks& operator=(const PoolTasks&) = delete;

  /// What a world stepped on the pool runs with: the callbacks to this, or
  /// none with one worker per task.
  TaskSettings taskSettings();

  /// Most threads that ran ranges of tasks at the same time, any world's.
  int peakConcurrency() const { return peakConcurrency_.load(); }
  /// Ranges run by helpers rather than by the thread that enqueued them.
  long long helpedRanges() const { return helpedRanges_.load(); }

 private:
  struct Task;

  static void* enqueue(TaskFunction* function, int itemCount, int minRange, void* taskContext,
                       void* self);
  static void finish(void* task, void* self);

  /// Posts helpers for `wanted` more threads, less those already waiting.
  void postHelpers(int wanted);
  /// A helper's job: works on open tasks until none is left for a moment.
  void help();
  /// An open task with a range left and a worker index free, joined.
  std::shared_ptr<Task> joinOpenTask(int& worker);
  /// Runs ranges of `task` until none is left unclaimed; returns how many.
  int runRanges(Task& task, int worker);
  void close(const Task& task);

  asio::thread_pool& pool_;
  const int workersPerTask_;
  std::mutex openMutex_;
  std::vector<std::shared_ptr<Task>> open_;
  std::atomic<int> openCount_ = 0;
  /// Helpers posted and not yet started, and started ones idling for work.
  std::atomic<int> waitingHelpers_ = 0;
  std::atomic<int> concurrency_ = 0;
  std::atomic<int> peakConcurrency_ = 0;
  std::atomic<long long> helpedRanges_ = 0;
};

}  // namespace impulse::server
