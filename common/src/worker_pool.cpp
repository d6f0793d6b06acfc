#include "worker_pool.h"

#include <algorithm>

namespace impulse {

namespace {

// About 0.1 ms of polling: longer than any gap between two phases of a
// step, far shorter than a frame.
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

void WorkerPool::spinOrYield(int& spins) {
  if (++spins < kSpinsBeforeSleep) {
    relaxCpu();
  } else {
    std::this_thread::yield();  // a thread we wait for was preempted: let it run
  }
}

// Part p covers [p * count / parts, (p + 1) * count / parts).
void WorkerPool::runPartIfFree(Phase& phase, int part, int worker) {
  if (phase.claimed[std::size_t(part)].exchange(true, std::memory_order_acq_rel)) return;
  const auto begin = int(std::int64_t(phase.itemCount) * part / phase.parts);
  const auto end = int(std::int64_t(phase.itemCount) * (part + 1) / phase.parts);
  if (begin < end) phase.task(begin, end, worker, phase.context);
  phase.unfinished.fetch_sub(1, std::memory_order_release);
}

// A thread's own share first, then whatever is left.
void WorkerPool::runParts(Phase& phase, int worker) {
  const int first = phase.parts * worker / workerCount();
  const int last = phase.parts * (worker + 1) / workerCount();
  for (int part = first; part < last; ++part) runPartIfFree(phase, part, worker);
  for (int part = 0; part < phase.parts; ++part) runPartIfFree(phase, part, worker);
}

void WorkerPool::run(TaskFunction* task, int itemCount, int minRange, void* taskContext) {
  if (itemCount <= 0) return;
  const int byRange = std::max(1, itemCount / std::max(minRange, 1));
  const int parts = std::min(workerCount() * kPartsPerWorker, byRange);
  if (parts == 1) {
    task(0, itemCount, 0, taskContext);
    return;
  }
  const std::uint64_t next = generation_.load() + 1;
  Phase& phase = phases_[next % 2];
  // A thread still looking at the phase before last must leave it first.
  for (int spins = 0; phase.readers.load() > 0;) spinOrYield(spins);
  phase.task = task;
  phase.context = taskContext;
  phase.itemCount = itemCount;
  phase.parts = parts;
  for (int part = 0; part < parts; ++part) phase.claimed[std::size_t(part)].store(false, std::memory_order_relaxed);
  phase.unfinished.store(parts, std::memory_order_relaxed);
  generation_.store(next);
  if (sleepers_.load() > 0) generation_.notify_all();
  runParts(phase, 0);
  for (int spins = 0; phase.unfinished.load(std::memory_order_acquire) > 0;) spinOrYield(spins);
}

std::uint64_t WorkerPool::awaitGeneration(std::uint64_t seen) {
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
  return generation_.load();
}

void WorkerPool::work(int worker) {
  std::uint64_t seen = 0;
  while (true) {
    const std::uint64_t generation = awaitGeneration(seen);
    if (stopping_.load()) return;
    Phase& phase = phases_[generation % 2];
    phase.readers.fetch_add(1);
    // Still that phase: its description is whole. Once the caller moved on,
    // every part of it has run, and the slot may be rewritten.
    if (generation_.load() == generation) runParts(phase, worker);
    phase.readers.fetch_sub(1);
    seen = generation;
  }
}

}  // namespace impulse
