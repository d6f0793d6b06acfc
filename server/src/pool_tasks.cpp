#include "impulse/server/pool_tasks.h"

#include <algorithm>
#include <asio/post.hpp>
#include <chrono>
#include <cstdint>
#include <thread>

namespace impulse::server {

namespace {

using HelperClock = std::chrono::steady_clock;

// Ranges per worker: more than one, so a thread that started late or was
// slowed by another process still finds work, and the ranges even out.
constexpr int kRangesPerWorker = 4;
// A helper with no open task waits this long for the step's next phase
// before it gives its thread back: waking a pool thread costs about as much.
constexpr auto kHelperIdleWait = std::chrono::microseconds(100);
// A helper gives its thread back after this long, so that another room's
// tick queued behind it waits no longer: if the step still needs help, its
// next phase posts a helper that queues behind that tick.
constexpr auto kHelperTurn = std::chrono::milliseconds(1);

int rangeCountFor(int itemCount, int minRange, int workers) {
  return std::clamp(itemCount / std::max(minRange, 1), 1, workers * kRangesPerWorker);
}

}  // namespace

struct PoolTasks::Task {
  TaskFunction* function = nullptr;
  void* context = nullptr;
  int itemCount = 0;
  int rangeCount = 0;
  int workerCount = 0;
  std::atomic<int> nextRange = 0;
  std::atomic<int> doneRanges = 0;
  // Worker 0 is the thread that enqueued the task.
  std::atomic<int> nextWorker = 1;
  // Helpers that joined and may still read the record.
  std::atomic<int> helpers = 0;

  void start(TaskFunction* taskFunction, void* taskContext, int items, int ranges, int workers) {
    function = taskFunction;
    context = taskContext;
    itemCount = items;
    rangeCount = ranges;
    workerCount = workers;
    nextRange = 0;
    doneRanges = 0;
    nextWorker = 1;
  }
  int rangeBegin(int range) const { return int(std::int64_t(itemCount) * range / rangeCount); }
};

PoolTasks::PoolTasks(asio::thread_pool& pool, int workersPerTask, PoolTaskCounts* counts)
    : pool_(pool), workersPerTask_(std::clamp(workersPerTask, 1, kMaxWorkers)), counts_(counts) {}

PoolTasks::~PoolTasks() = default;

TaskSettings PoolTasks::taskSettings() {
  if (workersPerTask_ == 1) return {};
  return {.workerCount = workersPerTask_,
          .enqueueTask = &enqueue,
          .finishTask = &finish,
          .userContext = this};
}

std::size_t PoolTasks::taskRecords() const {
  std::lock_guard lock(openMutex_);
  return records_.size();
}

void* PoolTasks::enqueue(TaskFunction* function, int itemCount, int minRange, void* taskContext,
                         void* self) {
  auto& tasks = *static_cast<PoolTasks*>(self);
  const int rangeCount = rangeCountFor(itemCount, minRange, tasks.workersPerTask_);
  if (rangeCount == 1) {
    function(0, itemCount, 0, taskContext);
    return nullptr;
  }
  Task* task = nullptr;
  {
    std::lock_guard lock(tasks.openMutex_);
    if (tasks.free_.empty()) {
      task = tasks.records_.emplace_back(std::make_unique<Task>()).get();
    } else {
      task = tasks.free_.back();
      tasks.free_.pop_back();
    }
    task->start(function, taskContext, itemCount, rangeCount, tasks.workersPerTask_);
    tasks.open_.push_back(task);
    tasks.openCount_.store(int(tasks.open_.size()));
  }
  tasks.postHelpers(std::min(tasks.workersPerTask_, rangeCount) - 1);
  return task;
}

void PoolTasks::finish(void* handle, void* self) {
  auto& tasks = *static_cast<PoolTasks*>(self);
  Task& task = *static_cast<Task*>(handle);
  // Whatever no helper claimed runs here, so the task ends without them.
  tasks.runRanges(task, 0);
  // What is left is running on other threads right now.
  for (int done = task.doneRanges.load(); done < task.rangeCount; done = task.doneRanges.load()) {
    task.doneRanges.wait(done);
  }
  tasks.close(task);
}

void PoolTasks::postHelpers(int wanted) {
  const int missing = wanted - waitingHelpers_.load();
  for (int i = 0; i < missing; ++i) {
    ++waitingHelpers_;
    asio::post(pool_, [this] { help(); });
  }
}

void PoolTasks::help() {
  const auto start = HelperClock::now();
  auto idleSince = start;
  for (auto now = start; now - idleSince < kHelperIdleWait && now - start < kHelperTurn;
       now = HelperClock::now()) {
    int worker = 0;
    Task* task = openCount_.load() > 0 ? joinOpenTask(worker) : nullptr;
    if (!task) {
      std::this_thread::yield();
      continue;
    }
    --waitingHelpers_;
    const int ran = runRanges(*task, worker);
    if (counts_) counts_->helpedRanges += ran;
    // Left: its record may now serve the next task.
    if (task->helpers.fetch_sub(1) == 1) task->helpers.notify_all();
    ++waitingHelpers_;
    idleSince = HelperClock::now();
  }
  --waitingHelpers_;
}

PoolTasks::Task* PoolTasks::joinOpenTask(int& worker) {
  std::lock_guard lock(openMutex_);
  for (Task* task : open_) {
    if (task->nextRange.load() >= task->rangeCount) continue;
    worker = task->nextWorker.fetch_add(1);
    if (worker < task->workerCount) {
      ++task->helpers;
      return task;
    }
  }
  return nullptr;
}

void PoolTasks::countRunning() {
  const int running = counts_->running.fetch_add(1) + 1;
  for (int peak = counts_->peakRunning.load();
       running > peak && !counts_->peakRunning.compare_exchange_weak(peak, running);) {
  }
}

int PoolTasks::runRanges(Task& task, int worker) {
  if (counts_) countRunning();
  int ran = 0;
  for (int range = task.nextRange.fetch_add(1); range < task.rangeCount;
       range = task.nextRange.fetch_add(1)) {
    task.function(task.rangeBegin(range), task.rangeBegin(range + 1), worker, task.context);
    ++ran;
    if (task.doneRanges.fetch_add(1) + 1 == task.rangeCount) task.doneRanges.notify_all();
  }
  if (counts_) --counts_->running;
  return ran;
}

void PoolTasks::close(Task& task) {
  {
    std::lock_guard lock(openMutex_);
    std::erase(open_, &task);
    openCount_.store(int(open_.size()));
  }
  // No helper joins it any more; those that did are past their last range.
  for (int helpers = task.helpers.load(); helpers != 0; helpers = task.helpers.load()) {
    task.helpers.wait(helpers);
  }
  std::lock_guard lock(openMutex_);
  free_.push_back(&task);
}

}  // namespace impulse::server
