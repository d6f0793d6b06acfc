#include "side_panel.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "impulse/client/number_format.h"
#include "palette.h"
#include "renderer.h"

namespace impulse::viewer {

namespace {

using client::formatNumber;

constexpr ImGuiWindowFlags kPanelFlags =
    ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_NoBringToFrontOnFocus;

ImVec4 colourOf(Colour c) { return ImGui::ColorConvertU32ToFloat4(packed(c)); }

std::string modeName(DrawMode mode) {
  switch (mode) {
    case DrawMode::Polygon: return "polygon (P to finish, Esc cancels)";
    case DrawMode::Circle: return "circle (O to finish, Esc cancels)";
    case DrawMode::Capsule: return "capsule (R to finish, - = radius, Esc cancels)";
    case DrawMode::Segment: return "segment (L to finish, Esc cancels)";
    case DrawMode::Chain: return "chain (H to finish, Shift+H to close, Esc cancels)";
    case DrawMode::Ray: return "ray (drag it; E or Esc leaves)";
    case DrawMode::None: break;
  }
  return "none (P polygon, O circle, R capsule, L segment, H chain, E ray)";
}

ImVec4 linkColour(LinkState link) {
  switch (link) {
    case LinkState::Connected: return colourOf(palette::kValid);
    case LinkState::Connecting: return colourOf(palette::kWarning);
    case LinkState::Lost: break;
  }
  return colourOf(palette::kInvalid);
}

// A button that joins the row when it fits.
bool rowButton(const char* label) {
  sameLineIfFits(ImGui::CalcTextSize(label, nullptr, true).x +
                 2 * ImGui::GetStyle().FramePadding.x);
  return ImGui::Button(label);
}

void drawTimeScale(const PanelInput& input, const std::function<void(ControlKey)>& act) {
  // Slow motion and fast forward keep the step size: only the pace changes.
  const ImVec4 colour = colourOf(input.timeScale == 1 ? palette::kText : palette::kWarning);
  ImGui::TextColored(colour, "speed %sx", formatNumber(input.timeScale, 2).c_str());
  if (rowButton("slower ([)")) act({Control::SlowerTime});
  if (rowButton("1x (\\)")) act({Control::NormalTime});
  if (rowButton("faster (])")) act({Control::FasterTime});
}

void drawTime(const PanelInput& input, const std::function<void(ControlKey)>& act) {
  if (input.link != LinkState::Connected) {
    ImGui::TextDisabled("not connected: the clock is the server's");
    return;
  }
  if (input.serverPaused) {
    ImGui::TextColored(colourOf(palette::kWarning), "PAUSED");
  } else {
    ImGui::TextColored(colourOf(palette::kValid), "RUNNING");
  }
  ImGui::SameLine();
  ImGui::TextWrapped("tick %llu, t = %s s", static_cast<unsigned long long>(input.tick),
                     formatNumber(input.simTime, 2).c_str());
  if (ImGui::Button(input.serverPaused ? "Resume (Space)" : "Pause (Space)")) {
    act({Control::TogglePause});
  }
  ImGui::BeginDisabled(!input.serverPaused);
  if (rowButton("Step (.)")) act({Control::StepOnce});
  ImGui::EndDisabled();
  drawTimeScale(input, act);
}

void drawRayAnswer(const Controls& controls) {
  if (controls.mode() != DrawMode::Ray) return;
  const auto& answer = controls.rayTool().answer();
  if (!answer) {
    ImGui::TextWrapped("Ray (E): drag across the scene");
    return;
  }
  ImGui::TextWrapped("Ray (E): %s", describeRay(*answer).c_str());
  if (!answer->hit) return;
  const RayHit& hit = *answer->hit;
  ImGui::TextWrapped("  point (%s, %s) m, normal (%s, %s)", formatNumber(hit.point.x(), 3).c_str(),
                     formatNumber(hit.point.y(), 3).c_str(), formatNumber(hit.normal.x(), 3).c_str(),
                     formatNumber(hit.normal.y(), 3).c_str());
}

// The part of the panel that never scrolls: what is shown, where, and when.
void drawHeader(const PanelFonts& fonts, const Controls& controls, const PanelInput& input,
                const std::function<void(ControlKey)>& act) {
  ImGui::PushFont(fonts.title);
  ImGui::TextWrapped("%s", input.preset != nullptr ? input.preset->title.c_str() : "Impulse");
  ImGui::PopFont();
  ImGui::PushStyleColor(ImGuiCol_Text, linkColour(input.link));
  ImGui::TextWrapped("room %s: %s", input.room.c_str(), input.linkText.c_str());
  ImGui::PopStyleColor();
  drawTime(input, act);
  if (input.notice) {
    ImGui::PushStyleColor(ImGuiCol_Text, colourOf(palette::kWarning));
    ImGui::TextWrapped("%s", input.notice->c_str());
    ImGui::PopStyleColor();
  }
  // What the ray tool's ray hit stays in sight while the tool is in use.
  drawRayAnswer(controls);
}

// Under the link line, always in sight: whether the viewer predicts its own
// drags and pushes, and the correction it is blending in.
void drawPrediction(const PanelInput& input, const PanelActions& actions, PanelState& state) {
  bool predicting = input.predicting;
  if (ImGui::Checkbox("Predict my actions", &predicting)) actions.setPredicting(predicting);
  if (ImGui::IsItemVisible()) state.predictBox = lastItemRect();
  // Always one unwrapped line, so the sections below never move as the
  // readout appears or its numbers change under the user's pointer.
  if (!input.prediction) {
    ImGui::TextDisabled("%s", predicting ? "predicting from the first snapshot" : "not predicting");
    return;
  }
  ImGui::Text("%s ticks ahead, correcting %s m (largest %s m)", std::to_string(input.prediction->leadTicks).c_str(),
              formatNumber(input.prediction->shownCorrection, 3).c_str(),
              formatNumber(input.prediction->largestCorrection, 3).c_str());
}

void swatch(Colour fill, Colour outline, float thickness, bool striped = false) {
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float size = ImGui::GetTextLineHeight();
  ImDrawList& list = *ImGui::GetWindowDrawList();
  list.AddRectFilled(at, {at.x + size, at.y + size}, packed(fill), 3);
  if (striped) {
    const std::array<ImVec2, 4> square{at, {at.x + size, at.y}, {at.x + size, at.y + size}, {at.x, at.y + size}};
    hatchConvex(list, square, at, packed(outline));
  }
  list.AddRect(at, {at.x + size, at.y + size}, packed(outline), 3, 0, thickness);
  ImGui::Dummy({size, size});
  ImGui::SameLine();
}

void drawLegend(const Controls& controls, const std::function<void(ControlKey)>& act) {
  for (int index = 0; index < kMaterialCount; ++index) {
    const Material material = *materialFromIndex(index);
    swatch(bodyFill(material, false), bodyOutline(material, false, false), 1.5f);
    const MaterialProperties& p = materialProperties(material);
    const std::string label = materialLabel(material) + "  " + formatNumber(p.density) +
                              " kg/m2, e " + formatNumber(p.restitution);
    ImGui::PushID(index);
    if (ImGui::Selectable(label.c_str(), controls.material() == material)) {
      act({Control::SelectMaterial, index});
    }
    ImGui::PopID();
  }
  swatch(bodyFill(Material::Solid, true), bodyOutline(Material::Solid, true, false), 1.5f);
  ImGui::TextUnformatted("static scenery");
  swatch(bodyFill(Material::Solid, false), bodyOutline(Material::Solid, false, false), 1.5f, true);
  ImGui::TextUnformatted("kinematic (striped)");
  swatch(bodyFill(Material::Solid, false), palette::kSleep, 2.5f);
  ImGui::TextUnformatted("asleep (violet outline)");
  const SurfaceLook sensor = surfaceLook(Material::Solid, true, false, true);
  swatch(sensor.fill, sensor.outline, 1.0f);
  ImGui::TextUnformatted("sensor (see-through, dashed)");
  swatch(palette::kSceneBackground, palette::kSelection, 2.5f);
  ImGui::TextUnformatted("selected or grabbed");
}

void drawNextShape(const Controls& controls, const std::function<void(ControlKey)>& act) {
  ImGui::TextWrapped("Mode: %s", modeName(controls.mode()).c_str());
  bool isStatic = controls.nextStatic();
  if (ImGui::Checkbox("Static (Q)", &isStatic)) act({Control::ToggleStatic});
  bool gravity = controls.nextFeelsGravity();
  sameLineIfFits(ImGui::CalcTextSize("Gravity (G)").x + ImGui::GetFrameHeight() +
                 ImGui::GetStyle().ItemInnerSpacing.x);
  if (ImGui::Checkbox("Gravity (G)", &gravity)) act({Control::ToggleGravity});
  ImGui::TextWrapped("Shapes at the cursor (T Y U I): %s m to a corner (- =)",
                     formatNumber(controls.shapeSize(), 2).c_str());
  ImGui::TextWrapped("Capsule radius: %s m (- = in capsule mode)",
                     formatNumber(controls.capsuleRadius(), 2).c_str());
  ImGui::TextUnformatted("Material (KP 1-8, F5-F12):");
  drawLegend(controls, act);
}

void drawGravityDial(const Vec2& gravity) {
  // The arrow reaches the rim at 12 m/s^2, so Earth's gravity fills most of
  // the dial and any nudge shows.
  constexpr float kFullScale = 12;
  const float radius = 34;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const ImVec2 centre{at.x + radius + 2, at.y + radius + 2};
  ImDrawList& list = *ImGui::GetWindowDrawList();
  list.AddCircle(centre, radius, packed(palette::kDimText), 0, 1.5f);
  const float g = gravity.norm();
  if (g > 1e-3f) {
    const float length = radius * std::min(1.0f, g / kFullScale);
    const ImVec2 tip{centre.x + gravity.x() / g * length, centre.y - gravity.y() / g * length};
    const float ux = (tip.x - centre.x) / length;
    const float uy = (tip.y - centre.y) / length;
    const ImU32 colour = packed(palette::kGravity);
    list.AddLine(centre, tip, colour, 3);
    const float head = 10;
    list.AddTriangleFilled(tip, {tip.x - head * (ux + 0.5f * uy), tip.y - head * (uy - 0.5f * ux)},
                           {tip.x - head * (ux - 0.5f * uy), tip.y - head * (uy + 0.5f * ux)},
                           colour);
  }
  ImGui::Dummy({2 * radius + 4, 2 * radius + 4});
  ImGui::SameLine();
  ImGui::BeginGroup();
  ImGui::TextWrapped("g = (%s, %s) m/s2", formatNumber(gravity.x(), 2).c_str(),
                     formatNumber(gravity.y(), 2).c_str());
  ImGui::TextDisabled("W A S D nudge");
  ImGui::TextDisabled("Enter resets");
  ImGui::EndGroup();
}

void drawOverlayToggles(Controls& controls, const PanelInput& input) {
  Overlays& overlays = controls.overlays();
  ImGui::Checkbox("contacts and normals (K)", &overlays.contacts);
  ImGui::Checkbox("bounding boxes (B)", &overlays.bounds);
  ImGui::Checkbox("velocities (V)", &overlays.velocities);
  ImGui::Checkbox("flash hits, contacts, sensors (N)", &overlays.eventFlashes);
  if (overlays.eventFlashes) {
    ImGui::TextDisabled("  events received: %llu", static_cast<unsigned long long>(input.eventMessages));
  }
}

void drawControlsSection(Controls& controls, const std::function<void(ControlKey)>& act) {
  // X opens and closes this section; clicking its header does the same.
  ImGui::SetNextItemOpen(controls.panelVisible(), ImGuiCond_Always);
  const bool open = ImGui::CollapsingHeader("Controls (X)");
  if (open != controls.panelVisible()) act({Control::TogglePanel});
  if (open) drawControlsTable();
}

}  // namespace

void sameLineIfFits(float width) {
  ImGui::SameLine();
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
}

PixelRect lastItemRect() {
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  return {min.x, min.y, max.x - min.x, max.y - min.y};
}

void drawSidePanel(const PixelRect& rect, const PanelFonts& fonts, Controls& controls,
                   const PanelInput& input, const PanelActions& actions, PanelState& state) {
  const auto& act = actions.key;
  state.presetEntries.clear();
  state.stopButton.reset();
  state.predictBox.reset();
  state.poseFields.reset();
  state.typeButtons = {};
  state.flagBoxes = {};
  ImGui::SetNextWindowPos({rect.x, rect.y});
  ImGui::SetNextWindowSize({rect.w, rect.h});
  ImGui::Begin("##side panel", nullptr,
               kPanelFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  drawHeader(fonts, controls, input, act);
  drawPrediction(input, actions, state);
  ImGui::Separator();
  // Only the sections scroll; the header above stays.
  ImGui::BeginChild("##sections");
  // Most looked-at first: the selected body while the inspector is on (it
  // is what the person works on), the scenes, the live figures.
  if (controls.inspectorVisible() &&
      ImGui::CollapsingHeader("Inspector (M)", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawInspectorSection(controls, input, actions, state);
  }
  if (ImGui::CollapsingHeader("Scenes", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawScenePicker(input, actions, state);
  }
  drawControlsSection(controls, act);
  if (ImGui::CollapsingHeader("Server and viewer", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawStatsSection(input);
  }
  if (ImGui::CollapsingHeader("Debug overlays", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawOverlayToggles(controls, input);
  }
  if (ImGui::CollapsingHeader("Next shape and materials", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawNextShape(controls, act);
  }
  if (ImGui::CollapsingHeader("Gravity", ImGuiTreeNodeFlags_DefaultOpen)) {
    drawGravityDial(input.gravity);
  }
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace impulse::viewer
