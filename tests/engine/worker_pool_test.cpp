// The world's own threads (worker_pool.h): every item of a phase runs
// exactly once, in ranges no shorter than asked, on a valid worker index,
// however the parts are claimed and whether the threads were asleep.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "worker_pool.h"

namespace impulse {
namespace {

// What the threads did in one phase: how often each item ran, the shortest
// range and any worker index out of bounds.
struct PhaseRecord {
  explicit PhaseRecord(int items, int workers) : runs(std::size_t(items)), workerCount(workers) {}
  std::vector<std::atomic<int>> runs;
  std::atomic<int> shortestRange{1 << 30};
  std::atomic<int> badWorkers{0};
  int workerCount;
};

void recordRange(int begin, int end, int worker, void* context) {
  auto& record = *static_cast<PhaseRecord*>(context);
  for (int item = begin; item < end; ++item) record.runs[std::size_t(item)].fetch_add(1);
  int shortest = record.shortestRange.load();
  while (end - begin < shortest && !record.shortestRange.compare_exchange_weak(shortest, end - begin)) {
  }
  if (worker < 0 || worker >= record.workerCount) record.badWorkers.fetch_add(1);
}

// Runs one phase of `items` and checks what it did.
void expectEachItemOnce(WorkerPool& pool, int items, int minRange) {
  PhaseRecord record(items, pool.workerCount());
  pool.run(recordRange, items, minRange, &record);
  for (int item = 0; item < items; ++item) {
    ASSERT_EQ(record.runs[std::size_t(item)].load(), 1) << "item " << item << " of " << items << ", ranges of "
                                                        << minRange << ", " << pool.workerCount() << " workers";
  }
  if (items > 0) {
    EXPECT_GE(record.shortestRange.load(), std::min(minRange, items));
  }
  EXPECT_EQ(record.badWorkers.load(), 0);
}

TEST(WorkerPool, EveryItemRunsOnceInRangesNoShorterThanAsked) {
  for (int workers : {2, 3, 5}) {
    WorkerPool pool(workers);
    for (int items : {0, 1, 2, 7, 16, 63, 100, 1000, 4097}) {
      for (int minRange : {1, 3, 16, 64}) {
        for (int repeat = 0; repeat < 3; ++repeat) expectEachItemOnce(pool, items, minRange);
      }
    }
  }
}

TEST(WorkerPool, ThreadsWokenOrAsleepLoseNoWork) {
  WorkerPool pool(3);
  for (int round = 0; round < 20; ++round) {
    if (round % 3 == 0) pool.wake();
    // Long enough, now and then, for the threads to have gone to sleep.
    if (round % 4 == 1) std::this_thread::sleep_for(std::chrono::milliseconds(3));
    expectEachItemOnce(pool, 500 + round, 8);
  }
  pool.wake();  // with no phase to follow: the pool still stops cleanly
}

}  // namespace
}  // namespace impulse
