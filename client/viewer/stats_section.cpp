#include <cstdio>

#include "impulse/client/number_format.h"
#include "side_panel.h"

namespace impulse::viewer {

namespace {

using client::formatNumber;

void plot(const char* label, const History& history, const std::string& caption) {
  const auto& values = history.values();
  ImGui::TextUnformatted(caption.c_str());
  // The scale starts at zero, so a flat line means a steady value, not noise.
  ImGui::PlotLines(label, values.data(), int(values.size()), 0, nullptr, 0,
                   std::max(history.max() * 1.1f, 1e-3f), {ImGui::GetContentRegionAvail().x, 48});
}

}  // namespace

void drawStatsSection(const PanelInput& input) {
  if (const v1::ServerStats* stats = input.stats) {
    ImGui::TextWrapped("step %s ms (mean %s), tick %s ms",
                       formatNumber(stats->last_step_ms(), 3).c_str(),
                       formatNumber(stats->mean_step_ms(), 3).c_str(),
                       formatNumber(stats->mean_tick_ms(), 3).c_str());
    ImGui::TextWrapped("bodies %u, awake %u, clients %u", stats->bodies(), stats->awake_bodies(),
                       stats->clients());
  } else {
    ImGui::TextWrapped("bodies %zu", input.bodies);
  }
  // The viewer's own pace: frames drawn per second, and the work of one
  // frame without the wait for the display.
  ImGui::TextWrapped("viewer %s fps, frame %s ms", formatNumber(input.framesPerSecond, 0).c_str(),
                     formatNumber(input.frameMs, 1).c_str());
  std::string figures = "snapshots " + formatNumber(input.snapshotsPerSecond, 0) + "/s";
  if (input.roundTripMs >= 0) figures += ", rtt " + formatNumber(input.roundTripMs, 1) + " ms";
  ImGui::TextWrapped("%s", figures.c_str());
  ImGui::TextWrapped("delay %s ms, zoom %sx", formatNumber(input.playoutDelayMs, 0).c_str(),
                     formatNumber(input.zoom, 2).c_str());
  if (input.stepMs != nullptr) {
    plot("##step", *input.stepMs,
         "step time, ms (last " + formatNumber(input.stepMs->latest(), 3) + ")");
  }
  if (input.kineticEnergy != nullptr) {
    plot("##energy", *input.kineticEnergy,
         "kinetic energy, J (now " + formatNumber(input.kineticEnergy->latest(), 1) + ")");
  }
}

}  // namespace impulse::viewer
