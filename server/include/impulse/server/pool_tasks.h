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
///
/// Why a phase allocates nothing: task records are reused. One goes back to
/// the free list once its task finished and every helper that joined it has
/// left it, so a helper never claims a range of the next task through an old
/// one; there are only ever as many records as tasks open at once.

#include <asio/thread_pool.hpp>
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "impulse/tasks.h"

namespace impulse::server {

/// What tests read of a PoolTasks: threads running ranges at once, the most
/// seen, and ranges run by helpers rather than the thread that enqueued
/// them. A PoolTasks made without one counts nothing.
struct PoolTaskCounts {
  std::atomic<int> running = 0;
  std::atomic<int> peakRunning = 0;
  std::atomic<long long> helpedRanges = 0;
};

class PoolTasks {
 public:
  /// `workersPerTask`: threads one task may use, its caller's included
  /// (1..kMaxWorkers). The pool must be joined before this is destroyed.
  PoolTasks(asio::thread_pool& pool, int workersPerTask, PoolTaskCounts* counts = nullptr);
  ~PoolTasks();
  PoolTasks(const PoolTasks&) = delete;
  PoolTasks& operator=(const PoolTasks&) = delete;

  /// What a world stepped on the pool runs with: the callbacks to this, or
  /// none with one worker per task.
  TaskSettings taskSettings();

  /// Task records made so far: the most tasks that were open at once.
  std::size_t taskRecords() const;

 private:
  struct Task;

  static void* enqueue(TaskFunction* function, int itemCount, int minRange, void* taskContext,
                       void* self);
  static void finish(void* task, void* self);

  /// Posts helpers for `wanted` more threads, less those already waiting.
  void postHelpers(int wanted);
  /// A helper's job: works on open tasks until none is left for a moment.
  void help();
  /// An open task with a range left and a worker index free, joined
  /// (leave it after its ranges).
  Task* joinOpenTask(int& worker);
  /// Runs ranges of `task` until none is left unclaimed; returns how many.
  int runRanges(Task& task, int worker);
  /// Takes the finished task off the open list and, once its helpers left
  /// it, puts its record back for the next task.
  void close(Task& task);
  /// Counts a thread starting on ranges (PoolTaskCounts).
  void countRunning();

  asio::thread_pool& pool_;
  const int workersPerTask_;
  PoolTaskCounts* const counts_;
  mutable std::mutex openMutex_;
  std::vector<Task*> open_;
  std::atomic<int> openCount_ = 0;
  /// Every record made, and those free for the next task.
  std::vector<std::unique_ptr<Task>> records_;
  std::vector<Task*> free_;
  /// Helpers posted and not yet started, and started ones idling for work.
  std::atomic<int> waitingHelpers_ = 0;
};

}  // namespace impulse::server
