#include "task_runner.h"

#include <algorithm>

#include "worker_pool.h"

namespace impulse {

TaskRunner::TaskRunner() = default;
TaskRunner::~TaskRunner() = default;
TaskRunner::TaskRunner(TaskRunner&&) noexcept = default;
TaskRunner& TaskRunner::operator=(TaskRunner&&) noexcept = default;

TaskSettings usableTaskSettings(const TaskSettings& settings) {
  TaskSettings usable = settings;
  usable.workerCount = std::clamp(settings.workerCount, 1, kMaxWorkers);
  if (!settings.enqueueTask || !settings.finishTask) {
    usable.enqueueTask = nullptr;
    usable.finishTask = nullptr;
  }
  return usable;
}

void TaskRunner::configure(const TaskSettings& requested) {
  const TaskSettings next = usableTaskSettings(requested);
  const bool ownThreads = next.workerCount > 1 && !next.enqueueTask;
  if (next.workerCount == settings_.workerCount && next.enqueueTask == settings_.enqueueTask &&
      next.finishTask == settings_.finishTask && next.userContext == settings_.userContext &&
      ownThreads == (pool_ != nullptr)) {
    return;
  }
  settings_ = next;
  pool_.reset();
  if (ownThreads) pool_ = std::make_unique<WorkerPool>(next.workerCount);
}

void TaskRunner::stepBegins() const {
  if (pool_) pool_->wake();
}

void TaskRunner::dispatch(TaskFunction* task, int count, int minRange, void* context) const {
  if (pool_) {
    pool_->run(task, count, minRange, context);
    return;
  }
  if (!settings_.enqueueTask) {
    task(0, count, 0, context);
    return;
  }
  void* handle = settings_.enqueueTask(task, count, minRange, context, settings_.userContext);
  if (handle) settings_.finishTask(handle, settings_.userContext);
}

}  // namespace impulse
