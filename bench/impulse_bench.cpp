// Speed against error, Impulse side by side with Box2D 2.4.1, Chipmunk 7 and,
// when built with it, Box2D v3: every scene in every engine setting, a table
// per scene, ratio and front lines, and optionally a CSV file and an SVG plot
// per scene.
//
//   impulse-bench [--quick] [--v3-suite | --solver2d | --queries] [--csv FILE] [--plot DIR] [--scene NAME-PART[,NAME-PART...]]
//                 [--engine NAME[,NAME...]] [--iterations N] [--threads N]
//
// --v3-suite runs Box2D v3's benchmark suite (the v3-* scenes) instead of
// Impulse's own scenes; --solver2d runs Solver2D's scene collection (the
// s2d-* scenes) instead. --queries runs the query bench instead (ray casts
// and box overlaps on one 10 000-body world, query_bench.h).
// --scene, --engine and --iterations narrow the run (for profiling one engine
// on one scene, or one side-by-side at one setting); --scene takes name parts
// separated by commas and keeps a scene that contains any of them; --engine
// takes whole engine names; --iterations keeps the settings of N sub-steps
// (Impulse, Box2D v3) or N velocity iterations (Box2D 2.4.1, Chipmunk);
// --threads keeps the settings on N threads (Impulse and Box2D v3 AVX2 at 4
// sub-steps run on 1 and 2).

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <fstream>
#include <string>

#include "query_bench.h"
#include "report.h"
#include "svg_plot.h"

namespace {

struct Options {
  bool quick = false;
  bool v3Suite = false;
  bool solver2D = false;
  bool queries = false;
  std::string csv;
  std::string plotDirectory;
  std::string sceneFilter;
  std::string engineFilter;
  int iterations = 0;  ///< 0: every setting
  int threads = 0;     ///< 0: every thread count
};

[[noreturn]] void usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s [--quick] [--v3-suite | --solver2d | --queries] [--csv FILE] [--plot DIR] [--scene NAME-PART[,NAME-PART...]] "
               "[--engine NAME[,NAME...]] [--iterations N] [--threads N]\n",
               program);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(argv[0]);
      return argv[++i];
    };
    if (std::strcmp(argv[i], "--quick") == 0) options.quick = true;
    else if (std::strcmp(argv[i], "--v3-suite") == 0) options.v3Suite = true;
    else if (std::strcmp(argv[i], "--solver2d") == 0) options.solver2D = true;
    else if (std::strcmp(argv[i], "--queries") == 0) options.queries = true;
    else if (std::strcmp(argv[i], "--csv") == 0) options.csv = value();
    else if (std::strcmp(argv[i], "--plot") == 0) options.plotDirectory = value();
    else if (std::strcmp(argv[i], "--scene") == 0) options.sceneFilter = value();
    else if (std::strcmp(argv[i], "--engine") == 0) options.engineFilter = value();
    else if (std::strcmp(argv[i], "--iterations") == 0) options.iterations = std::atoi(value().c_str());
    else if (std::strcmp(argv[i], "--threads") == 0) options.threads = std::atoi(value().c_str());
    else usage(argv[0]);
  }
  return options;
}

/// Whether any of the comma-separated parts of `filter` matches `name`.
bool anyPartMatches(const std::string& filter, const std::function<bool(const std::string& part)>& matches) {
  std::size_t start = 0;
  while (true) {
    const std::size_t end = filter.find(',', start);
    if (matches(filter.substr(start, end - start))) return true;
    if (end == std::string::npos) return false;
    start = end + 1;
  }
}

bool sceneWanted(const std::string& name, const std::string& filter) {
  return anyPartMatches(filter, [&](const std::string& part) { return name.find(part) != std::string::npos; });
}

bool settingWanted(const bench::EngineSetting& setting, const Options& options) {
  if (options.iterations != 0 && setting.iterations != options.iterations) return false;
  if (options.threads != 0 && setting.threads != options.threads) return false;
  return options.engineFilter.empty() ||
         anyPartMatches(options.engineFilter, [&](const std::string& part) { return part == bench::engineName(setting.engine); });
}

std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

// How the engine linked in was compiled (IMPULSE_AVX2), which the table's
// Impulse figures depend on as v3's do on BOX2D_AVX2.
constexpr const char* kEngineBuild =
#ifdef IMPULSE_BENCH_ENGINE_AVX2
    "impulse built for AVX2";
#else
    "impulse built for x86-64";
#endif

}  // namespace

int main(int argc, char** argv) {
  Options options = parse(argc, argv);
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::printf("impulse-bench%s%s%s  %s  %s  %s  dt 1/60\n", options.quick ? " --quick" : "",
              options.v3Suite ? " --v3-suite" : "", options.solver2D ? " --solver2d" : "", date, cpuModel().c_str(),
              kEngineBuild);
  if (options.queries) {
    const int disagreements = bench::runQueryBench(stdout, {options.quick, options.engineFilter});
    // Round-off may split a grazing ray; the bench reports, it does not judge.
    if (disagreements > 0) std::printf("%d answers differ between engines\n", disagreements);
    return 0;
  }
  if (!options.plotDirectory.empty()) std::filesystem::create_directories(options.plotDirectory);

  std::vector<bench::RunResult> all;
  int failures = 0;
  const bench::SceneList scenes = options.v3Suite    ? bench::box2DSuiteScenes(options.quick)
                                  : options.solver2D ? bench::solver2DScenes(options.quick)
                                                     : bench::allScenes(options.quick);
  for (const auto& scene : scenes) {
    if (!sceneWanted(scene->name(), options.sceneFilter)) continue;
    const bench::SceneDescription description = scene->describe();
    std::vector<bench::RunResult> results;
    for (const bench::EngineSetting& setting : bench::allSettings()) {
      if (!settingWanted(setting, options)) continue;
      results.push_back(bench::runScene(*scene, description, setting));
      if (results.back().failed) ++failures;
    }
    bench::printTable(stdout, results);
    bench::printRatios(stdout, results);
    bench::printFront(stdout, results);
    std::fflush(stdout);
    if (!options.plotDirectory.empty() && !bench::writeSvgPlot(options.plotDirectory, results)) {
      std::fprintf(stderr, "cannot write a plot in %s\n", options.plotDirectory.c_str());
      ++failures;
    }
    all.insert(all.end(), results.begin(), results.end());
  }
  bench::printDerived(stdout, all);
  if (!options.csv.empty() && !bench::writeCsv(options.csv, all)) {
    std::fprintf(stderr, "cannot write %s\n", options.csv.c_str());
    ++failures;
  }
  if (failures > 0) std::fprintf(stderr, "%d run(s) failed\n", failures);
  return failures > 0 ? 1 : 0;
}
