#include "worker_pool.h"

#include <algorithm>
#include <chrono>

namespace impulse {

namespace {

// How long a worker polls for the next phase before it sleeps: longer than
// the serial stretches of a step (the pair search's end, the top of the
// tree's rebuild: up to a few tenths of a millisecond on 10 000 bodies),
// since a sleeping worker takes tens of microseconds to wake, and short
// beside a frame. Counted on the clock: a `pause` takes 10 to 140 cycles
// depending on the processor.
constexpr std::chrono::microseconds kPollBeforeSleep{400};
// Polls between two readings of the clock, about a microsecond. Past the
// first kSpinsBeforeYield, each reading also yields: on a loaded machine
// the thread lets others run instead of burning their time.
constexpr int kSpinsPerClockRead = 64;
constexpr int kSpinsBeforeYield = 2048;
// Spins of a thread waiting for the others to finish a phase before it
// yields to them, in case one of them was preempted.
constexpr int kWaitSpinsBeforeYield = 4000;

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
  if (++spins < kWaitSpinsBeforeYield) {
    relaxCpu();
  } else {
    std::this_thread::yield();  // a thread we wait for was preempted: let it run
  }
}

// Runs the parts of `share` nobody has claimed; returns how many it ran.
// Part p covers [p * count / parts, (p + 1) * count / parts). A share
// already used up is only read: no write moves its cache line.
int WorkerPool::runShare(Phase& phase, Share& share, int worker) {
  int ran = 0;
  while (share.next.load(std::memory_order_relaxed) < share.end) {
    const int part = share.next.fetch_add(1, std::memory_order_relaxed);
    if (part >= share.end) break;
    const auto begin = int(std::int64_t(phase.itemCount) * part / phase.parts);
    const auto end = int(std::int64_t(phase.itemCount) * (part + 1) / phase.parts);
    if (begin < end) phase.task(begin, end, worker, phase.context);
    ++ran;
  }
  return ran;
}

// A thread's own share first, then what is left of the others'.
void WorkerPool::runParts(Phase& phase, int worker) {
  const int workers = workerCount();
  int ran = runShare(phase, phase.shares[std::size_t(worker)], worker);
  for (int k = 1; k < workers; ++k) ran += runShare(phase, phase.shares[std::size_t((worker + k) % workers)], worker);
  if (ran > 0) phase.unfinished.fetch_sub(ran, std::memory_order_release);
}

void WorkerPool::run(TaskFunction* task, int itemCount, int minRange, void* taskContext) {
  if (itemCount <= 0) return;
  const int byRange = std::max(1, itemCount / std::max(minRange, 1));
  const int parts = std::min(workerCount() * kPartsPerWorker, byRange);
  if (parts == 1) {
    task(0, itemCount, 0, taskContext);
    return;
  }
  Phase& phase = publish(task, itemCount, parts, taskContext);
  runParts(phase, 0);
  for (int spins = 0; phase.unfinished.load(std::memory_order_acquire) > 0;) spinOrYield(spins);
}

void WorkerPool::wake() {
  if (sleepers_.load() > 0) publish(nullptr, 0, 0, nullptr);
}

WorkerPool::Phase& WorkerPool::publish(TaskFunction* task, int itemCount, int parts, void* taskContext) {
  const int workers = workerCount();
  const std::uint64_t next = generation_.load() + 1;
  Phase& phase = phases_[next % 2];
  // A thread still looking at the phase before last must leave it first.
  for (int spins = 0; phase.readers.load() > 0;) spinOrYield(spins);
  phase.task = task;
  phase.context = taskContext;
  phase.itemCount = itemCount;
  phase.parts = parts;
  for (int worker = 0; worker < workers; ++worker) {
    Share& share = phase.shares[std::size_t(worker)];
    share.next.store(parts * worker / workers, std::memory_order_relaxed);
    share.end = parts * (worker + 1) / workers;
  }
  phase.unfinished.store(parts, std::memory_order_relaxed);
  generation_.store(next);
  if (sleepers_.load() > 0) generation_.notify_all();
  return phase;
}

std::uint64_t WorkerPool::awaitGeneration(std::uint64_t seen) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point sleepAt = Clock::now() + kPollBeforeSleep;
  for (int spins = 1;; ++spins) {
    const std::uint64_t now = generation_.load(std::memory_order_acquire);
    if (now != seen) return now;
    relaxCpu();
    if (spins % kSpinsPerClockRead != 0) continue;
    if (Clock::now() >= sleepAt) break;
    if (spins >= kSpinsBeforeYield) std::this_thread::yield();
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
