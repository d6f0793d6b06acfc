#pragma once
// The query bench: the same 10 000-body world built in each engine that
// wires its queries (EngineAdapter::hasQueries), the same seeded rays and
// boxes asked of each, timed per query, and the answers compared
// (bench/queries.md).

#include <cstdio>
#include <string>

namespace bench {

struct QueryBenchOptions {
  /// A small world and few queries: proves the bench runs, times nothing.
  bool quick = false;
  /// Comma-separated engine names to keep (empty: every engine with queries).
  std::string engineFilter;
};

/// Runs the bench and prints its table to `out`; returns the number of
/// answers on which the engines disagreed beyond round-off.
int runQueryBench(std::FILE* out, const QueryBenchOptions& options);

}  // namespace bench
