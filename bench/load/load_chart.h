#pragma once
// The load bench's chart: one SVG with a panel per series over the run's
// seconds (tick time against the tick period, bytes per second per client).

#include <string>
#include <vector>

namespace load {

struct Series {
  std::string title;  // with its unit
  std::vector<double> values;  // one per second
  /// A dashed reference line (the tick period); none when <= 0.
  double reference = 0;
  std::string referenceLabel;
};

/// Writes the panels to `path`; false when the file cannot be written.
bool writeChart(const std::string& path, const std::string& title,
                const std::vector<Series>& panels);

}  // namespace load
