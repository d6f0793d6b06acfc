#include <array>
#include <utility>

#include "side_panel.h"

namespace impulse::viewer {

namespace {

// docs/product.md's control table and the viewer's own keys, as the panel shows them.
constexpr std::array<std::pair<const char*, const char*>, 35> kControlRows{{
    {"P", "polygon mode; again: create (3+ points)"},
    {"click", "place a point where the cursor is green"},
    {"O", "circle mode; again: create (if dragged)"},
    {"drag", "circle: centre at press, radius to cursor"},
    {"R", "capsule mode: drag end to end, - = radius; again: create"},
    {"L", "segment mode: drag end to end; again: create"},
    {"H / Shift+H", "chain mode: click points; again: create (solid above) / close it"},
    {"E", "ray tool: drag a ray, see what it hits first; again: leave"},
    {"Esc", "cancel drawing, grab or selection; else quit"},
    {"left drag", "pull a body by a mouse joint; release throws it"},
    {"right click, Del", "remove the body under the cursor"},
    {"C", "clear what was made; scenery stays"},
    {"Shift+C", "clear everything"},
    {"Space", "pause or resume the server"},
    {".", "step one tick while paused"},
    {"wheel", "zoom at the cursor"},
    {"right drag", "pan (middle drag too)"},
    {"F, Home", "fit the scene to the window"},
    {"K B V", "contacts, bounding boxes, velocities"},
    {"N", "flash hits, contacts and sensors (event stream)"},
    {"X", "show or hide these controls"},
    {"M", "inspector: click a body, arrows push it"},
    {"J", "pin the selected body to the world (at the cursor)"},
    {"Q / G", "next shapes static / feel gravity"},
    {"KP 1-8, F5-F12", "SOLID ICE WOOD METAL RUBBER STONE GLASS FOAM"},
    {"1-9, F1, 0", "preset 1-9, 10, sandbox"},
    {"Shift+1-4", "spring, pendulum and cradle, chain bridge, car"},
    {"Shift+5-7", "orbits, floating, fans"},
    {"W A S D", "nudge gravity while held"},
    {"Enter", "reset gravity"},
    {"[ ] \\", "time: half, double (held: repeats), 1x speed (0.01x-16x)"},
    {"T Y U I", "triangle, square, pentagon, hexagon at the cursor"},
    {"- =", "standard shapes smaller, larger"},
    {"Ctrl+S / Ctrl+O", "save the scene to its file / load it back"},
    {"Ctrl+D / Ctrl+1-9", "keep the drawn polygon / stamp kept shape 1-9"},
}};

}  // namespace

void drawControlsTable() {
  if (!ImGui::BeginTable("controls", 2)) return;
  ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
  const ImVec4 keyColour = ImGui::GetStyleColorVec4(ImGuiCol_Text);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  for (const auto& [key, action] : kControlRows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextColored(keyColour, "%s", key);
    ImGui::TableNextColumn();
    ImGui::TextWrapped("%s", action);
  }
  ImGui::PopStyleColor();
  ImGui::EndTable();
}

}  // namespace impulse::viewer
