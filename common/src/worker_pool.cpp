#include "worker_pool.h"

#include <algorithm>

namespace impulse {

namespace {

// About 0.1-0.2 ms of polling before a thread sleeps: longer than any gap
// between two phases of a step, far shorter than a frame.
constexpr int kSpinsBeforeSleep = 4000;

void relaxCpu() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

}  // namespace

WorkerPool::WorkerPool(int workerCount) {
  const int threads = std::clamp(workerCount, 1, kMaxWorkers) - 1;
  threads_.reserve(std::size_t(threads));
  for (int worker = 1; worker <= threads; ++worker) threads_.emplace_back([this, worker] { work(worker); });
}

WorkerPool::~WorkerPool() {
  stopping_.store(true);
  generation_.fetch_add(1);
  generation_.notify_all();
  threads_.clear();  // joins
}

// Part k of n covers [k * count / n, (k + 1) * count / n): contiguous, and
// the same bodies for the same part whenever the count is the same.
void WorkerPool::runPart(const Phase& phase, int part) const {
  const auto begin = int(std::int64_t(phase.itemCount) * part / phase.parts);
  const auto end = int(std::int64_t(phase.itemCount) * (part + 1) / phase.parts);
  if (begin < end) phase.task(begin, end, part, phase.context);
}

void WorkerPool::run(TaskFunction* task, int itemCount, int minRange, void* taskContext) {
  if (itemCount <= 0) return;
  const int byRange = std::max(1, itemCount / std::max(minRange, 1));
  const int parts = std::min(workerCount(), byRange);
  if (parts == 1) {
    task(0, itemCount, 0, taskContext);
    return;
  }
  phase_ = {task, taskContext, itemCount, parts};
  finished_.store(0, std::memory_order_relaxed);
  generation_.fetch_add(1);
  if (sleepers_.load() > 0) generation_.notify_all();
  runPart(phase_, 0);
  awaitWorkers();
}

// Every thread acknowledges every phase, those without a part included, so
// none can still be reading phase_ when the next one is written.
void WorkerPool::awaitWorkers() {
  const int others = static_cast<int>(threads_.size());
  for (int spins = 0; finished_.load(std::memory_order_acquire) < others; ++spins) {
    if (spins < kSpinsBeforeSleep) {
      relaxCpu();
    } else {
      std::this_thread::yield();  // a worker was preempted: let it run
    }
  }
}

std::uint64_t WorkerPool::awaitPhase(std::uint64_t seen) {
  for (int spins = 0; spins < kSpinsBeforeSleep; ++spins) {
    const std::uint64_t now = generation_.load(std::memory_order_acquire);
    if (now != seen) return now;
    relaxCpu();
  }
  // Announce the sleep before the last look: the caller either sees a
  // sleeper and notifies, or this thread sees the new generation.
  sleepers_.fetch_add(1);
  while (generation_.load() == seen) generation_.wait(seen);
  sleepers_.fetch_sub(1);
  return generation_.load(std::memory_order_acquire);
}

void WorkerPool::work(int worker) {
  std::uint64_t seen = 0;
  while (true) {
    seen = awaitPhase(seen);
    if (stopping_.load()) return;
    if (worker < phase_.parts) runPart(phase_, worker);
    finished_.fetch_add(1, std::memory_order_release);
  }
}

}  // namespace impulse
