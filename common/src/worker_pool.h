#pragma once
// The world's own threads, used when the game gives no job system
// (impulse/tasks.h). Each phase of the step is cut into a few parts per
// thread; each thread first runs the parts of its own share (the same
// bodies in every per-body phase, so their states stay in its cache), then
// takes parts of the others' shares that nobody has started. A thread the
// OS has not scheduled holds nothing up: the others run its parts.
//
// Threads poll between the phases of a step (a phase is tens of
// microseconds; waking a sleeping thread costs as much) and sleep when no
// phase comes for a while (between steps); a step wakes them as it begins.
//
// A step runs a few hundred phases, so what a phase costs besides its
// parts counts: a thread claims its own parts off a counter on its own
// cache line (no other thread writes it until that share is nearly done)
// and reports once per phase how many parts it ran.

#include <array>
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
  /// Wakes the threads that sleep, with no work: they poll again, so that
  /// the phases of a step about to begin find them awake (a sleeping thread
  /// takes tens of microseconds to wake).
  void wake();

 private:
  static constexpr int kPartsPerWorker = 8;

  // A thread's share of a phase: parts [next, end) are still unclaimed.
  struct alignas(64) Share {
    std::atomic<int> next{0};
    int end = 0;
  };

  // One phase's description and progress. Two alternate, so a thread that
  // wakes late and still reads the last phase is never overwritten: the
  // next phase takes the other one.
  struct Phase {
    TaskFunction* task = nullptr;
    void* context = nullptr;
    int itemCount = 0;
    int parts = 0;
    std::array<Share, kMaxWorkers> shares;
    alignas(64) std::atomic<int> unfinished{0};  ///< parts not yet run
    alignas(64) std::atomic<int> readers{0};  ///< threads looking at it
  };

  /// Describes the next phase (`parts` of them, none for a wake) and wakes
  /// the threads that sleep.
  Phase& publish(TaskFunction* task, int itemCount, int parts, void* taskContext);
  void work(int worker);
  std::uint64_t awaitGeneration(std::uint64_t seen);
  void runParts(Phase& phase, int worker);
  int runShare(Phase& phase, Share& share, int worker);
  static void spinOrYield(int& spins);

  std::vector<std::jthread> threads_;
  std::array<Phase, 2> phases_;
  // Phase g is phases_[g % 2]. Bumped once per phase; workers watch it.
  alignas(64) std::atomic<std::uint64_t> generation_{0};
  std::atomic<int> sleepers_{0};
  std::atomic<bool> stopping_{false};
};

}  // namespace impulse
