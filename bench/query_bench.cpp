#include "query_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "engine_adapter.h"

namespace bench {
namespace {

constexpr std::uint32_t kSeed = 28;
constexpr double kSpacing = 0.7;  // metres between body centres
// Closest-hit fractions further apart than this count as a disagreement
// (float round-off on rays up to 30 m stays far below it).
constexpr double kFractionTolerance = 1e-4;

struct Ray {
  Vec2d origin;
  Vec2d translation;
};

struct Box {
  Vec2d lower;
  Vec2d upper;
};

// side x side bodies at rest with no gravity, boxes and circles in a
// chequer pattern, each box turned at a random angle.
SceneDescription gridWorld(int side, std::mt19937& random) {
  std::uniform_real_distribution<double> angle(0, std::numbers::pi);
  SceneDescription scene;
  scene.gravity = {0, 0};
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const bool isBox = (i + j) % 2 == 0;
      const ShapeDesc shape = isBox ? ShapeDesc::box(0.3, 0.2) : ShapeDesc::circle(0.25);
      BodyDesc body = makeBody(shape, {i * kSpacing, j * kSpacing}, impulse::Material::Solid);
      if (isBox) body.angle = angle(random);
      addBody(scene, body);
    }
  }
  return scene;
}

// Rays from anywhere over the world (a metre of margin), in any direction,
// 2 to 30 m long.
std::vector<Ray> randomRays(int count, double size, std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-1, size + 1);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
  std::uniform_real_distribution<double> length(2, 30);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Vec2d origin{coordinate(random), coordinate(random)};
    const double a = angle(random);
    const double l = length(random);
    rays.push_back({origin, {l * std::cos(a), l * std::sin(a)}});
  }
  return rays;
}

// Boxes 0.5 to 5 m a side anywhere over the world.
std::vector<Box> randomBoxes(int count, double size, std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-1, size + 1);
  std::uniform_real_distribution<double> half(0.25, 2.5);
  std::vector<Box> boxes;
  for (int i = 0; i < count; ++i) {
    const Vec2d centre{coordinate(random), coordinate(random)};
    const double hx = half(random);
    const double hy = half(random);
    boxes.push_back({{centre.x - hx, centre.y - hy}, {centre.x + hx, centre.y + hy}});
  }
  return boxes;
}

struct Answers {
  std::vector<double> closest;
  std::vector<int> rayHits;
  std::vector<int> overlaps;
};

// Microseconds per query over each round of each kind, and the answers.
struct EngineRun {
  Engine engine = Engine::Impulse;
  std::unique_ptr<EngineAdapter> adapter;
  Answers answers;
  std::vector<double> closestTimes;
  std::vector<double> allTimes;
  std::vector<double> overlapTimes;
};

template <typename Query>
double microsecondsPerQuery(std::size_t count, Query&& query) {
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < count; ++i) query(i);
  const std::chrono::duration<double, std::micro> elapsed = std::chrono::steady_clock::now() - start;
  return elapsed.count() / double(count);
}

void runRound(EngineRun& run, const std::vector<Ray>& rays, const std::vector<Box>& boxes) {
  EngineAdapter& adapter = *run.adapter;
  Answers& answers = run.answers;
  answers.closest.resize(rays.size());
  answers.rayHits.resize(rays.size());
  answers.overlaps.resize(boxes.size());
  run.closestTimes.push_back(microsecondsPerQuery(rays.size(), [&](std::size_t i) {
    answers.closest[i] = adapter.castRayClosest(rays[i].origin, rays[i].translation);
  }));
  run.allTimes.push_back(microsecondsPerQuery(rays.size(), [&](std::size_t i) {
    answers.rayHits[i] = adapter.castRayCount(rays[i].origin, rays[i].translation);
  }));
  run.overlapTimes.push_back(microsecondsPerQuery(boxes.size(), [&](std::size_t i) {
    answers.overlaps[i] = adapter.overlapBoxCount(boxes[i].lower, boxes[i].upper);
  }));
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

long total(const std::vector<int>& counts) {
  long sum = 0;
  for (int count : counts) sum += count;
  return sum;
}

long hitCount(const std::vector<double>& fractions) {
  return std::count_if(fractions.begin(), fractions.end(), [](double f) { return f >= 0; });
}

bool engineWanted(Engine engine, const std::string& filter) {
  if (filter.empty()) return true;
  const std::string name = engineName(engine);
  std::size_t start = 0;
  while (true) {
    const std::size_t end = filter.find(',', start);
    if (filter.substr(start, end - start) == name) return true;
    if (end == std::string::npos) return false;
    start = end + 1;
  }
}

// One adapter per engine that wires queries (the first setting of each:
// queries do not depend on the solver's), stepped once so each engine's
// broad phase is as its step leaves it.
std::vector<EngineRun> buildEngines(const SceneDescription& scene, const std::string& filter) {
  std::vector<EngineRun> runs;
  std::set<Engine> seen;
  for (const EngineSetting& setting : allSettings()) {
    if (!seen.insert(setting.engine).second || !engineWanted(setting.engine, filter)) continue;
    std::unique_ptr<EngineAdapter> adapter = makeAdapter(scene, setting);
    if (!adapter->hasQueries()) continue;
    adapter->step(1.0 / 60);
    runs.push_back({setting.engine, std::move(adapter), {}, {}, {}, {}});
  }
  return runs;
}

// Answers of `run` that differ from the reference's.
struct Disagreements {
  int closest = 0;
  int rayHits = 0;
  int overlaps = 0;
  int sum() const { return closest + rayHits + overlaps; }
};

Disagreements compare(const Answers& reference, const Answers& run) {
  Disagreements d;
  for (std::size_t i = 0; i < reference.closest.size(); ++i) {
    const double a = reference.closest[i];
    const double b = run.closest[i];
    if ((a < 0) != (b < 0) || std::abs(a - b) > kFractionTolerance) ++d.closest;
    if (reference.rayHits[i] != run.rayHits[i]) ++d.rayHits;
  }
  for (std::size_t i = 0; i < reference.overlaps.size(); ++i) {
    if (reference.overlaps[i] != run.overlaps[i]) ++d.overlaps;
  }
  return d;
}

}  // namespace

int runQueryBench(std::FILE* out, const QueryBenchOptions& options) {
  const int side = options.quick ? 10 : 100;
  const int queries = options.quick ? 100 : 2000;
  const int rounds = options.quick ? 1 : 9;
  std::mt19937 random(kSeed);
  const SceneDescription scene = gridWorld(side, random);
  const double size = (side - 1) * kSpacing;
  const std::vector<Ray> rays = randomRays(queries, size, random);
  const std::vector<Box> boxes = randomBoxes(queries, size, random);

  std::vector<EngineRun> runs = buildEngines(scene, options.engineFilter);
  if (runs.empty()) {
    std::fprintf(out, "queries: no engine with queries selected\n");
    return 0;
  }
  // Rounds interleave the engines, each round starting with the next one,
  // so drift in the machine's load falls on all of them alike.
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      runRound(runs[(k + static_cast<std::size_t>(round)) % runs.size()], rays, boxes);
    }
  }

  std::fprintf(out, "\nqueries: %d bodies (%dx%d boxes and circles, %.1f m apart), %d rays 2-30 m, "
               "%d boxes 0.5-5 m, seed %u; median of %d interleaved rounds\n",
               side * side, side, side, kSpacing, queries, queries, kSeed, rounds);
  std::fprintf(out, "%-16s %12s %12s %12s %12s %12s %14s\n", "engine", "closest us", "all-hits us",
               "overlap us", "closest hits", "ray hits", "overlap shapes");
  for (const EngineRun& run : runs) {
    std::fprintf(out, "%-16s %12.3f %12.3f %12.3f %12ld %12ld %14ld\n", engineName(run.engine),
                 median(run.closestTimes), median(run.allTimes), median(run.overlapTimes),
                 hitCount(run.answers.closest), total(run.answers.rayHits), total(run.answers.overlaps));
  }
  int disagreements = 0;
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const Disagreements d = compare(runs[0].answers, runs[k].answers);
    std::fprintf(out, "%s against %s: %d closest hits, %d ray hit counts, %d overlap counts differ\n",
                 engineName(runs[k].engine), engineName(runs[0].engine), d.closest, d.rayHits, d.overlaps);
    disagreements += d.sum();
  }
  return disagreements;
}

}  // namespace bench
