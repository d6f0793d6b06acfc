#pragma once
// The world's own threads, used when the game gives no job system
// (impulse/tasks.h). Each phase of the step is cut into one contiguous range
// per thread, the caller's included: the same thread gets the same bodies in
// every per-body phase, so their states stay in its cache.
//
// Threads spin between the phases of a step (a phase is tens of
// microseconds; waking a sleeping thread costs as much) and sleep when no
// phase comes for a while (between steps).

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "impulse/tasks.h"

namespace impulse {

class WorkerPool {
 public:
  /// Starts workerCount - 1 threads.
  explicit WorkerPool(int workerCount);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int workerCount() const { return static_cast<int>(threads_.size()) + 1; }

  /// Runs task over [0, itemCount) in ranges of at least minRange items and
  /// returns when every range has run.
  void run(TaskFunction* task, int itemCount, int minRange, void* taskContext);

 private:
  struct Phase {
    TaskFunction* task = nullptr;
    void* context = nullptr;
    int itemCount = 0;
    int parts = 0;
  };

  void work(int worker);
  std::uint64_t awaitPhase(std::uint64_t seen);
  void runPart(const Phase& phase, int part) const;
  void awaitWorkers();

  std::vector<std::jthread> threads_;
  Phase phase_;
  // Bumped once per phase; workers watch it. Padded apart: the caller writes
  // one, the workers the other.
  alignas(64) std::atomic<std::uint64_t> generation_{0};
  alignas(64) std::atomic<int> finished_{0};
  std::atomic<int> sleepers_{0};
  std::atomic<bool> stopping_{false};
};

}  // namespace impulse
