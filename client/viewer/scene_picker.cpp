#include <filesystem>

#include "key_map.h"
#include "side_panel.h"

namespace impulse::viewer {

namespace {

void dimWrapped(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

// A preset's explanation as one paragraph: its lines were broken for the
// seed's fixed-width canvas, the panel wraps to its own width.
std::string paragraph(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text.append(text.empty() ? "" : " ").append(line);
  return text;
}

// A preset's explanation beside the pointer while it hovers the entry.
void explanationTooltip(const PresetInfo& preset) {
  if (!ImGui::IsItemHovered() || preset.explanation.empty()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24);
  ImGui::TextUnformatted(paragraph(preset.explanation).c_str());
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

void drawPresetList(const PanelInput& input, const PanelActions& actions, PanelState& state) {
  if (input.presets == nullptr) return;
  const int current = input.preset != nullptr ? input.preset->id : -1;
  for (const PresetInfo& preset : *input.presets) {
    const std::string key = presetKeyName(preset.id);
    const std::string label = (key.empty() ? "" : key + "  ") + preset.title;
    ImGui::PushID(preset.id);
    if (ImGui::Selectable(label.c_str(), preset.id == current)) {
      actions.key({Control::LoadPreset, preset.id});
    }
    explanationTooltip(preset);
    if (ImGui::IsItemVisible()) {
      const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
      state.presetEntries.push_back({preset.id, {min.x, min.y, max.x - min.x, max.y - min.y}});
    }
    ImGui::PopID();
  }
}

void drawSceneFiles(const PanelInput& input, const PanelActions& actions) {
  if (input.sceneFiles.empty()) {
    dimWrapped("No scene files here yet: Ctrl+S saves one (a .json name: a level file)");
    return;
  }
  dimWrapped("Scene files (.scene binary, .json level files):");
  for (const std::string& file : input.sceneFiles) {
    const std::string name = std::filesystem::path(file).filename().string();
    if (ImGui::Selectable(name.c_str())) actions.loadScene(file);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", file.c_str());
  }
}

}  // namespace

void drawScenePicker(const PanelInput& input, const PanelActions& actions, PanelState& state) {
  if (input.preset != nullptr) {
    dimWrapped(paragraph(input.preset->explanation));
    ImGui::Spacing();
  }
  dimWrapped("Presets (hover for what each shows; drawing works in all):");
  drawPresetList(input, actions, state);
  ImGui::Spacing();
  drawSceneFiles(input, actions);
}

}  // namespace impulse::viewer
