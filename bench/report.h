#pragma once
// Text output: a table per scene, the ratio lines, the derived lines
// (scaling slope, cost of sleeping bodies) and the CSV file.

#include <cstdio>
#include <string>
#include <vector>

#include "runner.h"

namespace bench {

/// The table of one scene's results (all settings of all engines).
void printTable(std::FILE* out, const std::vector<RunResult>& results);

/// Per peer setting: our fastest time at equal (within 1%) or lower headline
/// error over the peer's time ("x0.5" = we take half the time).
void printRatios(std::FILE* out, const std::vector<RunResult>& results);

/// The speed-against-error front: the engine settings no other setting beats
/// on both median ms/step and headline error, fastest first.
void printFront(std::FILE* out, const std::vector<RunResult>& results);

/// Lines computed across scenes: ms/step-vs-n slope of the scaling-* scenes
/// (log-log least squares) and sleeping-5050 minus sleeping-awake-50.
void printDerived(std::FILE* out, const std::vector<RunResult>& all);

/// Long format: one line per (scene, engine, setting, metric).
bool writeCsv(const std::string& path, const std::vector<RunResult>& all);

}  // namespace bench
