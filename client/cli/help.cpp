#include "help.h"

#include <cctype>

#include "impulse/client/number_format.h"
#include "impulse/constants.h"
#include "impulse/material.h"
#include "impulse/shape.h"
#include "script.h"

namespace impulse::cli {

namespace {

using client::formatNumber;

std::string indented(const std::string& lines) {
  std::string text;
  for (std::size_t start = 0; start < lines.size();) {
    const std::size_t end = lines.find('\n', start) + 1;
    text.append("  ").append(lines, start, end - start);
    start = end;
  }
  return text;
}

std::string materials() {
  std::string text = "MATERIAL, in any case (density kg/m2, restitution):\n";
  for (int index = 0; index < kMaterialCount; ++index) {
    const MaterialProperties& m = materialProperties(*materialFromIndex(index));
    std::string name(m.name);
    for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    text.append("  ").append(name).append(" (").append(formatNumber(m.density));
    text.append(", ").append(formatNumber(m.restitution)).append(")");
    text.append(index + 1 < kMaterialCount ? ",\n" : "\n");
  }
  return text;
}

std::string limits() {
  const ShapeLimits shapes;
  return "Limits (the server's defaults): polygons " + std::to_string(kMinPolygonVertices) + "-" +
         std::to_string(kMaxPolygonVertices) + " vertices, radius " +
         formatNumber(shapes.minRadius) + "-" + formatNumber(shapes.maxRadius) + " m, area " +
         formatNumber(shapes.minArea) + "-" + formatNumber(shapes.maxArea) +
         " m2. A step longer than the server takes at once (its Welcome's max_step_ticks) is "
         "sent in pieces and reported as one line.\n";
}

}  // namespace

std::string scriptHelp() {
  return "Script commands, one per line ('#' starts a comment):\n" + indented(scriptGrammar()) +
         materials() + limits() +
         "--token defaults to the environment's IMPULSE_TOKEN; it is sent in Hello.\n"
         "Exit status: 0 every line succeeded, 1 some line failed, 2 arguments or connection "
         "failed.";
}

}  // namespace impulse::cli
