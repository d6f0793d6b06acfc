#pragma once
/// \file
/// Worker threads for the step, as a game's own job system can provide them.
///
/// The step cuts its parallel phases into ranges of items. Each item writes
/// only its own outputs, so the result is bit-identical however the items
/// are split and in whatever order the ranges run: one thread, two, or a
/// job system that runs them backwards.

namespace impulse {

/// Runs items [begin, end) of one parallel phase. `worker` is in
/// [0, workerCount): the thread's index, for per-thread scratch.
using TaskFunction = void(int begin, int end, int worker, void* taskContext);

/// Starts `task` over items [0, itemCount), cut into ranges of at least
/// `minRange` items, on up to workerCount threads (the caller's included).
/// Returns a handle for FinishTaskCallback, or nullptr when it ran the task
/// to the end before returning.
using EnqueueTaskCallback = void* (*)(TaskFunction* task, int itemCount, int minRange, void* taskContext,
                                      void* userContext);

/// Waits until every range of an enqueued task has run.
using FinishTaskCallback = void (*)(void* userTask, void* userContext);

/// Who runs the step's parallel phases (WorldSettings::tasks).
struct TaskSettings {
  /// Threads that work on one step, the caller's included. With no
  /// callbacks the world keeps workerCount - 1 threads of its own.
  int workerCount = 1;
  /// A game's own job system: both set, or both null.
  EnqueueTaskCallback enqueueTask = nullptr;
  FinishTaskCallback finishTask = nullptr;
  void* userContext = nullptr;
};

/// The most threads a world works with.
inline constexpr int kMaxWorkers = 64;

}  // namespace impulse
