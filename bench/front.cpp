#include "front.h"

#include <algorithm>

namespace bench {

namespace {

bool dominates(const RunResult& a, const RunResult& b) {
  bool noWorse = a.medianMs <= b.medianMs && a.error() <= b.error();
  bool better = a.medianMs < b.medianMs || a.error() < b.error();
  return noWorse && better;
}

}  // namespace

std::vector<const RunResult*> paretoFront(const std::vector<RunResult>& results) {
  std::vector<const RunResult*> front;
  for (const RunResult& candidate : results) {
    if (!candidate.ok() || candidate.metrics.empty()) continue;
    bool dominated = std::any_of(results.begin(), results.end(), [&](const RunResult& other) {
      return other.ok() && !other.metrics.empty() && dominates(other, candidate);
    });
    if (!dominated) front.push_back(&candidate);
  }
  std::sort(front.begin(), front.end(),
            [](const RunResult* a, const RunResult* b) { return a->medianMs < b->medianMs; });
  return front;
}

}  // namespace bench
