#include "report.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "front.h"
#include "impulse/world.h"

namespace bench {

namespace {

std::string engineSetting(const RunResult& r) {
  return std::string(engineName(r.setting.engine)) + " " + r.setting.label();
}

// Both engines default to the same sub-steps (4).
bool atDefaultSubSteps(const RunResult& r) { return r.setting.iterations == impulse::WorldSettings{}.subSteps; }

const RunResult* firstOk(const std::vector<RunResult>& results) {
  for (const RunResult& r : results) {
    if (r.ok()) return &r;
  }
  return nullptr;
}

std::optional<double> minOf(const std::vector<RunResult>& all, const std::string& scene, const EngineSetting& s) {
  for (const RunResult& r : all) {
    if (r.ok() && r.scene == scene && r.setting.engine == s.engine && r.setting.iterations == s.iterations &&
        r.setting.positionIterations == s.positionIterations) {
      return r.minMs;
    }
  }
  return std::nullopt;
}

}  // namespace

void printTable(std::FILE* out, const std::vector<RunResult>& results) {
  if (results.empty()) return;
  std::fprintf(out, "\n== %s ==\n", results.front().scene.c_str());
  std::fprintf(out, "%-22s %9s %9s", "engine setting", "ms min", "ms med");
  if (const RunResult* reference = firstOk(results)) {
    for (const Metric& m : reference->metrics) std::fprintf(out, " %14s", m.name.c_str());
  }
  std::fprintf(out, "\n");
  for (const RunResult& r : results) {
    std::fprintf(out, "%-22s", engineSetting(r).c_str());
    if (!r.ok()) {
      std::fprintf(out, " %s\n", r.problem.c_str());
      continue;
    }
    // Four significant digits: a one-body scene takes a microsecond or two.
    std::fprintf(out, " %9.4g %9.4g", r.minMs, r.medianMs);
    for (const Metric& m : r.metrics) std::fprintf(out, " %14.4g", m.value);
    if (!r.approximation.empty()) std::fprintf(out, "  (%s)", r.approximation.c_str());
    std::fprintf(out, "\n");
  }
  // One line, at the default setting: the passes barely differ by sub-steps.
  for (const RunResult& r : results) {
    const bool counted = r.setting.engine == Engine::Impulse || r.setting.engine == Engine::Box2DV3Avx2;
    if (r.ok() && !r.passes.empty() && counted && atDefaultSubSteps(r)) {
      std::fprintf(out, "passes of %s: %s\n", engineSetting(r).c_str(), r.passes.c_str());
    }
  }
  // Where each engine's own timers put the time, at the default setting:
  // Impulse and Box2D v3 AVX2, at each thread count run.
  for (const RunResult& r : results) {
    const bool timed = r.setting.engine == Engine::Impulse || r.setting.engine == Engine::Box2DV3Avx2;
    if (r.ok() && !r.stages.empty() && timed && atDefaultSubSteps(r)) {
      std::fprintf(out, "stages of %s: %s\n", engineSetting(r).c_str(), r.stages.c_str());
    }
  }
}

void printRatios(std::FILE* out, const std::vector<RunResult>& results) {
  const RunResult* reference = firstOk(results);
  if (reference == nullptr || reference->metrics.empty()) return;
  std::fprintf(out, "ratio (impulse ms / peer ms at <= peer's %s):", reference->metrics.front().name.c_str());
  for (const RunResult& peer : results) {
    if (!peer.ok() || peer.setting.engine == Engine::Impulse) continue;
    const RunResult* best = nullptr;
    for (const RunResult& ours : results) {
      if (!ours.ok() || ours.setting.engine != Engine::Impulse) continue;
      // Within 1% counts as equal: float against Chipmunk's doubles differs
      // in the fifth digit on the closed-form cases.
      if (ours.error() > peer.error() * 1.01 + 1e-12) continue;
      if (best == nullptr || ours.medianMs < best->medianMs) best = &ours;
    }
    if (best == nullptr) {
      std::fprintf(out, "  | vs %s: none as accurate", engineSetting(peer).c_str());
    } else {
      std::fprintf(out, "  | vs %s: x%.2f (%s)", engineSetting(peer).c_str(), best->medianMs / peer.medianMs,
                   best->setting.label().c_str());
    }
  }
  std::fprintf(out, "\n");
}

void printFront(std::FILE* out, const std::vector<RunResult>& results) {
  const RunResult* reference = firstOk(results);
  if (reference == nullptr || reference->metrics.empty()) return;
  std::fprintf(out, "front (ms med against %s, fastest first):", reference->metrics.front().name.c_str());
  for (const RunResult* r : paretoFront(results)) {
    std::fprintf(out, "  | %s (%.4g ms, %.4g)", engineSetting(*r).c_str(), r->medianMs, r->error());
  }
  std::fprintf(out, "\n");
}

void printDerived(std::FILE* out, const std::vector<RunResult>& all) {
  std::map<std::string, std::vector<std::pair<double, double>>> points;  // setting -> (log n, log ms)
  std::map<std::string, EngineSetting> settings;
  for (const RunResult& r : all) {
    if (!r.ok() || r.scene.rfind("scaling-", 0) != 0 || r.medianMs <= 0) continue;
    double n = std::stod(r.scene.substr(8));
    points[engineSetting(r)].push_back({std::log(n), std::log(r.medianMs)});
    settings[engineSetting(r)] = r.setting;
  }
  if (!points.empty()) std::fprintf(out, "\n== scaling: slope of log(ms/step) against log(n) ==\n");
  for (const auto& [name, xy] : points) {
    if (xy.size() < 2) continue;
    double mx = 0, my = 0;
    for (auto [x, y] : xy) mx += x, my += y;
    mx /= double(xy.size());
    my /= double(xy.size());
    double sxy = 0, sxx = 0;
    for (auto [x, y] : xy) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
    std::fprintf(out, "%-22s slope %.2f\n", name.c_str(), sxy / sxx);
  }
  bool header = false;
  for (const RunResult& r : all) {
    if (!r.ok() || r.scene != "sleeping-5050") continue;
    // Min over repeats: the difference of two small times is mostly noise otherwise.
    std::optional<double> awakeOnly = minOf(all, "sleeping-awake-50", r.setting);
    if (!awakeOnly) continue;
    if (!header) std::fprintf(out, "\n== cost of 5000 sleeping bodies: ms/step over the awake-only scene ==\n");
    header = true;
    std::fprintf(out, "%-22s %+.4f ms (min %.4f vs %.4f)\n", engineSetting(r).c_str(), r.minMs - *awakeOnly,
                 r.minMs, *awakeOnly);
  }
}

bool writeCsv(const std::string& path, const std::vector<RunResult>& all) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) return false;
  std::fprintf(file, "scene,engine,setting,ms_min,ms_median,metric,value\n");
  for (const RunResult& r : all) {
    if (!r.ok()) {
      std::fprintf(file, "%s,%s,%s,,,problem,\"%s\"\n", r.scene.c_str(), engineName(r.setting.engine),
                   r.setting.label().c_str(), r.problem.c_str());
      continue;
    }
    for (const Metric& m : r.metrics) {
      std::fprintf(file, "%s,%s,%s,%.6g,%.6g,%s,%.9g\n", r.scene.c_str(), engineName(r.setting.engine),
                   r.setting.label().c_str(), r.minMs, r.medianMs, m.name.c_str(), m.value);
    }
  }
  return std::fclose(file) == 0;
}

}  // namespace bench
