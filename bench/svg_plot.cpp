#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "front.h"

namespace bench {

namespace {

constexpr double kWidth = 640, kHeight = 420, kLeft = 70, kRight = 20, kTop = 40, kBottom = 50;

const char* colour(Engine engine) {
  switch (engine) {
    case Engine::Impulse: return "#d62728";
    case Engine::ImpulseSse2: return "#e377c2";
    case Engine::Box2D: return "#1f77b4";
    case Engine::Chipmunk: return "#2ca02c";
    case Engine::Box2DV3Sse2: return "#9467bd";
    case Engine::Box2DV3Avx2: return "#ff7f0e";
  }
  return "#000";
}

// A value range drawn on a log scale when it spans more than 20x and has no
// zero or negative values, else linearly from 0.
struct Axis {
  double low = 0, high = 1;
  bool log = false;
  Axis(double least, double most) {
    log = least > 0 && most / least > 20;
    if (log) {
      low = std::pow(10, std::floor(std::log10(least)));
      high = std::pow(10, std::ceil(std::log10(most)));
    } else {
      low = std::min(0.0, least);
      high = most > low ? most * 1.1 : low + 1;
    }
  }
  double fraction(double v) const {
    if (log) return (std::log10(std::max(v, low)) - std::log10(low)) / (std::log10(high) - std::log10(low));
    return (v - low) / (high - low);
  }
  std::vector<double> ticks() const {
    std::vector<double> t;
    if (log) {
      for (double v = low; v <= high * 1.0001; v *= 10) t.push_back(v);
    } else {
      for (int i = 0; i <= 4; ++i) t.push_back(low + (high - low) * i / 4);
    }
    return t;
  }
};

// Each engine's settings joined in order of cost, so its own speed-error
// curve shows.
void drawEngineLines(std::FILE* f, const std::vector<const RunResult*>& points, const auto& px, const auto& py) {
  std::map<Engine, std::vector<const RunResult*>> byEngine;
  for (const RunResult* r : points) byEngine[r->setting.engine].push_back(r);
  for (auto& [engine, runs] : byEngine) {
    std::sort(runs.begin(), runs.end(),
              [](const RunResult* a, const RunResult* b) { return a->medianMs < b->medianMs; });
    std::fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-opacity=\"0.5\" points=\"", colour(engine));
    for (const RunResult* r : runs) std::fprintf(f, "%.1f,%.1f ", px(r->error()), py(r->medianMs));
    std::fprintf(f, "\"/>\n");
  }
}

// The Pareto front as a grey staircase: nothing below and left of it exists.
void drawFront(std::FILE* f, const std::vector<RunResult>& results, const auto& px, const auto& py) {
  std::vector<const RunResult*> front = paretoFront(results);
  std::fprintf(f, "<polyline fill=\"none\" stroke=\"#444\" stroke-width=\"2\" stroke-dasharray=\"6 3\" points=\"");
  for (std::size_t i = 0; i < front.size(); ++i) {
    if (i > 0) std::fprintf(f, "%.1f,%.1f ", px(front[i - 1]->error()), py(front[i]->medianMs));
    std::fprintf(f, "%.1f,%.1f ", px(front[i]->error()), py(front[i]->medianMs));
  }
  std::fprintf(f, "\"/>\n");
}

}  // namespace

bool writeSvgPlot(const std::string& directory, const std::vector<RunResult>& results) {
  std::vector<const RunResult*> points;
  for (const RunResult& r : results) {
    if (r.ok() && !r.metrics.empty()) points.push_back(&r);
  }
  if (points.empty()) return true;
  double inf = std::numeric_limits<double>::infinity();
  double xMin = inf, xMax = -inf, yMin = inf, yMax = -inf;
  for (const RunResult* r : points) {
    xMin = std::min(xMin, r->error()), xMax = std::max(xMax, r->error());
    yMin = std::min(yMin, r->medianMs), yMax = std::max(yMax, r->medianMs);
  }
  Axis x(xMin, xMax), y(yMin, yMax);
  const double plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;
  auto px = [&](double v) { return kLeft + x.fraction(v) * plotW; };
  auto py = [&](double v) { return kTop + (1 - y.fraction(v)) * plotH; };

  std::string path = directory + "/" + points.front()->scene + ".svg";
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return false;
  std::fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" font-family=\"sans-serif\" font-size=\"11\">\n",
               kWidth, kHeight);
  std::fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
  std::fprintf(f, "<text x=\"%.0f\" y=\"20\" font-size=\"14\">%s: ms/step against %s (lower left is better; dashed: the front)</text>\n",
               kLeft, points.front()->scene.c_str(), points.front()->metrics.front().name.c_str());
  std::fprintf(f, "<rect x=\"%.0f\" y=\"%.0f\" width=\"%.0f\" height=\"%.0f\" fill=\"none\" stroke=\"#888\"/>\n", kLeft,
               kTop, plotW, plotH);
  for (double t : x.ticks()) {
    std::fprintf(f, "<text x=\"%.1f\" y=\"%.0f\" text-anchor=\"middle\">%.3g</text>\n", px(t), kTop + plotH + 15, t);
  }
  for (double t : y.ticks()) {
    std::fprintf(f, "<text x=\"%.0f\" y=\"%.1f\" text-anchor=\"end\">%.3g</text>\n", kLeft - 5, py(t) + 4, t);
  }
  std::fprintf(f, "<text x=\"%.0f\" y=\"%.0f\" text-anchor=\"middle\">%s%s</text>\n", kLeft + plotW / 2, kHeight - 10,
               points.front()->metrics.front().name.c_str(), x.log ? " (log)" : "");
  std::fprintf(f, "<text x=\"15\" y=\"%.0f\" transform=\"rotate(-90 15 %.0f)\" text-anchor=\"middle\">ms/step median%s</text>\n",
               kTop + plotH / 2, kTop + plotH / 2, y.log ? " (log)" : "");
  drawEngineLines(f, points, px, py);
  drawFront(f, results, px, py);
  for (const RunResult* r : points) {
    double cx = px(r->error()), cy = py(r->medianMs);
    std::fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"/>\n", cx, cy, colour(r->setting.engine));
    std::fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\">%s %s</text>\n", cx + 6, cy - 4, colour(r->setting.engine),
                 engineName(r->setting.engine), r->setting.label().c_str());
  }
  std::fprintf(f, "</svg>\n");
  return std::fclose(f) == 0;
}

}  // namespace bench
