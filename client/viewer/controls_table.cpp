#include <array>
#include <utility>

#include "side_panel.h"

namespace impulse::viewer {

namespace {

// SPEC.md's control table and the viewer's own keys, as the panel shows them.
constexpr std::array<std::pair<const char*, const char*>, 25> kControlRows{{
    {"P", "polygon mode; again: create (3+ points)"},
    {"click", "place a point where the cursor is green"},
    {"O", "circle mode; again: create (if dragged)"},
    {"drag", "circle: centre at press, radius to cursor"},
    {"Esc", "cancel drawing, grab or selection; else quit"},
    {"left drag", "grab a body; release throws it"},
    {"right click, Del", "remove the body under the cursor"},
    {"C", "clear what was made; scenery stays"},
    {"Shift+C", "clear everything"},
    {"Space", "pause or resume the server"},
    {".", "step one tick while paused"},
    {"wheel", "zoom at the cursor"},
    {"right/middle drag", "pan"},
    {"F, Home", "fit the scene to the window"},
    {"K B V", "contacts, bounding boxes, velocities"},
    {"X", "show or hide these controls"},
    {"M", "inspector: click a body, arrows push it"},
    {"Q / G", "next shapes static / feel gravity"},
    {"KP 1-5, F5-F9", "SOLID ICE WOOD METAL RUBBER"},
    {"1-9, F1, 0", "preset 1-9, 10, sandbox"},
    {"W A S D", "nudge gravity while held"},
    {"Enter", "reset gravity"},
    {"", "drawing: sandbox and presets 3, 4"},
    {"", "zoom and pan: the scene stays fitted"},
    {"", "to the window until you zoom or pan"},
}};

}  // namespace

void drawControlsTable() {
  if (!ImGui::BeginTable("controls", 2, ImGuiTableFlags_SizingFixedFit)) return;
  for (const auto& [key, action] : kControlRows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(key);
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s", action);
  }
  ImGui::EndTable();
}

}  // namespace impulse::viewer
