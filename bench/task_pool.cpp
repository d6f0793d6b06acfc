#include "task_pool.h"

namespace bench {

TaskPool::TaskPool(int threads) {
  for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { work(); });
}

TaskPool::~TaskPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  queued_.notify_all();
  threads_.clear();  // joins
}

void* TaskPool::enqueue(Task* task, void* context) {
  Job* job = nullptr;
  {
    std::lock_guard lock(mutex_);
    job = &jobs_.emplace_back(Job{task, context, false, false});
    waiting_.push_back(job);
  }
  queued_.notify_one();
  return job;
}

void TaskPool::finish(void* handle) {
  auto* job = static_cast<Job*>(handle);
  std::unique_lock lock(mutex_);
  finished_.wait(lock, [&] { return job->done; });
  // Jobs are finished in any order; a slot goes once its finish returned.
  job->released = true;
  while (!jobs_.empty() && jobs_.front().released) jobs_.pop_front();
}

void TaskPool::work() {
  std::unique_lock lock(mutex_);
  while (true) {
    queued_.wait(lock, [&] { return stopping_ || !waiting_.empty(); });
    if (stopping_) return;
    Job* job = waiting_.front();
    waiting_.pop_front();
    lock.unlock();
    job->task(job->context);
    lock.lock();
    job->done = true;
    finished_.notify_all();
  }
}

}  // namespace bench
