#pragma once
// A plain job system for an engine that takes enqueue and finish callbacks
// (Box2D v3's b2WorldDef): each enqueued task runs once on one of `threads`
// threads while the caller goes on, and finish waits for it. Box2D v3
// enqueues one solver task per worker and those spin on each other, so the
// pool has a thread for every worker the engine is given.

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace bench {

class TaskPool {
 public:
  using Task = void(void* context);

  explicit TaskPool(int threads);
  ~TaskPool();
  TaskPool(const TaskPool&) = delete;
  TaskPool& operator=(const TaskPool&) = delete;

  /// Queues one run of task(context); returns the handle finish() waits on.
  void* enqueue(Task* task, void* context);
  void finish(void* handle);

 private:
  struct Job {
    Task* task = nullptr;
    void* context = nullptr;
    bool done = false;
    bool released = false;  ///< finish() returned: the slot may go
  };

  void work();

  std::mutex mutex_;
  std::condition_variable queued_;
  std::condition_variable finished_;
  std::deque<Job> jobs_;       // stable addresses while in use
  std::deque<Job*> waiting_;   // queued, not yet taken by a thread
  bool stopping_ = false;
  std::vector<std::jthread> threads_;
};

}  // namespace bench
