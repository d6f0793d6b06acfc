#pragma once
// How the step runs a parallel phase: inline on one thread, on the world's
// own threads (worker_pool.h) or through a game's job system
// (impulse/tasks.h). Phases hand it a function of an item range; every item
// must write only its own outputs, which is what keeps results bit-identical
// for any worker count.

#include <cstdint>
#include <memory>
#include <type_traits>

#include "impulse/tasks.h"

namespace impulse {

class WorkerPool;

class TaskRunner {
 public:
  TaskRunner();
  ~TaskRunner();
  TaskRunner(TaskRunner&&) noexcept;
  TaskRunner& operator=(TaskRunner&&) noexcept;

  /// Follows the settings: starts or stops the world's own threads when the
  /// worker count or the callbacks changed, and does nothing otherwise.
  void configure(const TaskSettings& settings);
  int workerCount() const { return settings_.workerCount; }
  /// A step begins: the world's own threads, if they sleep, are woken now,
  /// so that they poll by its first parallel phase.
  void stepBegins() const;

  /// Calls first() and second(), at once when there is a thread for each
  /// and the `items` each works through are at least `minItems` (fewer cost
  /// less than waking a thread). Neither may run a parallel phase of its own.
  template <class First, class Second>
  void bothAtOnce(std::int32_t items, std::int32_t minItems, First&& first, Second&& second) const {
    if (items < minItems) {
      first();
      second();
      return;
    }
    forRanges(2, 1, [&](std::int32_t begin, std::int32_t end) {
      for (std::int32_t job = begin; job < end; ++job) job == 0 ? first() : second();
    });
  }

  /// Calls body(begin, end) over ranges covering [0, count), each of at
  /// least minRange items, possibly on several threads at once.
  template <class Body>
  void forRanges(std::int32_t count, std::int32_t minRange, Body&& body) const {
    if (count <= 0) return;
    if (settings_.workerCount == 1 || count < 2 * minRange) {
      body(std::int32_t(0), count);
      return;
    }
    using Stored = std::remove_reference_t<Body>;
    dispatch(
        [](int begin, int end, int, void* context) { (*static_cast<Stored*>(context))(begin, end); }, count,
        minRange, const_cast<std::remove_const_t<Stored>*>(&body));
  }

 private:
  void dispatch(TaskFunction* task, int count, int minRange, void* context) const;

  TaskSettings settings_;
  std::unique_ptr<WorkerPool> pool_;
};

/// Clamps a worker count into [1, kMaxWorkers] and drops a half-given pair
/// of callbacks: what a world made with such settings runs with.
TaskSettings usableTaskSettings(const TaskSettings& settings);

}  // namespace impulse
