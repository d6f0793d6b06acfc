#include "load_chart.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace load {

namespace {

constexpr double kWidth = 640;
constexpr double kPanelHeight = 180;
constexpr double kLeft = 70;
constexpr double kRight = 20;
constexpr double kTop = 40;
constexpr double kGap = 50;

std::string format(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// One panel: axes, the series as a polyline with points, the reference dashed.
std::string panel(const Series& series, double top) {
  const double plotWidth = kWidth - kLeft - kRight;
  const double plotHeight = kPanelHeight - 40;
  double maximum = series.reference;
  for (const double value : series.values) maximum = std::max(maximum, value);
  maximum = maximum > 0 ? maximum * 1.15 : 1;
  const std::size_t count = std::max<std::size_t>(series.values.size(), 2);
  auto x = [&](std::size_t i) { return kLeft + plotWidth * double(i) / double(count - 1); };
  auto y = [&](double v) { return top + 20 + plotHeight * (1 - v / maximum); };

  std::string svg = "<text x='" + format(kLeft) + "' y='" + format(top + 12) +
                    "' font-size='13'>" + series.title + "</text>\n";
  svg += "<line x1='" + format(kLeft) + "' y1='" + format(y(0)) + "' x2='" +
         format(kLeft + plotWidth) + "' y2='" + format(y(0)) + "' stroke='black'/>\n";
  svg += "<line x1='" + format(kLeft) + "' y1='" + format(top + 20) + "' x2='" + format(kLeft) +
         "' y2='" + format(y(0)) + "' stroke='black'/>\n";
  svg += "<text x='" + format(kLeft - 6) + "' y='" + format(top + 24) +
         "' font-size='11' text-anchor='end'>" + format(maximum) + "</text>\n";
  svg += "<text x='" + format(kLeft - 6) + "' y='" + format(y(0)) +
         "' font-size='11' text-anchor='end'>0</text>\n";
  if (series.reference > 0) {
    svg += "<line x1='" + format(kLeft) + "' y1='" + format(y(series.reference)) + "' x2='" +
           format(kLeft + plotWidth) + "' y2='" + format(y(series.reference)) +
           "' stroke='red' stroke-dasharray='6,4'/>\n";
    svg += "<text x='" + format(kLeft + plotWidth) + "' y='" + format(y(series.reference) - 4) +
           "' font-size='11' fill='red' text-anchor='end'>" + series.referenceLabel + "</text>\n";
  }
  std::string points;
  for (std::size_t i = 0; i < series.values.size(); ++i) {
    points += format(x(i)) + "," + format(y(series.values[i])) + " ";
    svg += "<circle cx='" + format(x(i)) + "' cy='" + format(y(series.values[i])) +
           "' r='2.5' fill='steelblue'/>\n";
  }
  svg += "<polyline fill='none' stroke='steelblue' points='" + points + "'/>\n";
  svg += "<text x='" + format(kLeft + plotWidth / 2) + "' y='" + format(y(0) + 16) +
         "' font-size='11' text-anchor='middle'>second of the measured run</text>\n";
  return svg;
}

}  // namespace

bool writeChart(const std::string& path, const std::string& title,
                const std::vector<Series>& panels) {
  const double height = kTop + double(panels.size()) * (kPanelHeight + kGap);
  std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='" + format(kWidth) +
                    "' height='" + format(height) + "' font-family='sans-serif'>\n";
  svg += "<rect width='100%' height='100%' fill='white'/>\n";
  svg += "<text x='" + format(kWidth / 2) + "' y='22' font-size='15' text-anchor='middle'>" +
         title + "</text>\n";
  for (std::size_t i = 0; i < panels.size(); ++i) {
    svg += panel(panels[i], kTop + double(i) * (kPanelHeight + kGap));
  }
  svg += "</svg>\n";
  std::ofstream file(path);
  file << svg;
  return bool(file);
}

}  // namespace load
