#include "gui.h"

#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <filesystem>

#include "palette.h"

namespace impulse::viewer {

namespace {

constexpr float kFontPixels = 15;
constexpr float kTitlePixels = 21;

ImVec4 toImGui(Colour c, float alpha = 1) {
  return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, alpha};
}

void applyStyle() {
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0;
  style.WindowBorderSize = 0;
  style.FrameRounding = 3;
  style.ItemSpacing = {8, 5};
  style.Colors[ImGuiCol_WindowBg] = toImGui(palette::kPanelBackground);
  style.Colors[ImGuiCol_Text] = toImGui(palette::kText);
  style.Colors[ImGuiCol_TextDisabled] = toImGui(palette::kDimText);
}

}  // namespace

Gui::Gui(SDL_Window* window, SDL_Renderer* renderer, const std::string& fontPath) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // No imgui.ini next to wherever the viewer was started: the layout is fixed.
  io.IniFilename = nullptr;
  applyStyle();
  std::error_code error;
  if (std::filesystem::is_regular_file(fontPath, error)) {
    text_ = io.Fonts->AddFontFromFileTTF(fontPath.c_str(), kFontPixels);
    title_ = io.Fonts->AddFontFromFileTTF(fontPath.c_str(), kTitlePixels);
  }
  if (text_ == nullptr || title_ == nullptr) text_ = title_ = io.Fonts->AddFontDefault();
  ImGui_ImplSDL2_InitForSDLRenderer(window);
  renderer_ = std::make_unique<ImGuiRenderer>(renderer);
}

Gui::~Gui() {
  renderer_.reset();
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
}

void Gui::processEvent(const SDL_Event& event) { ImGui_ImplSDL2_ProcessEvent(&event); }

void Gui::beginFrame(const Pointer& pointer) {
  ImGui_ImplSDL2_NewFrame();
  // The panel sees the pointer the scene sees, from the same events. Dear
  // ImGui 1.86's SDL backend polls SDL's pointer instead, and only over a
  // window with the mouse focus, which a window without a display (the
  // offscreen driver the end-to-end tests use) never gets.
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = {pointer.x, pointer.y};
  io.MouseDown[0] = pointer.leftDown;
  ImGui::NewFrame();
}

void Gui::render() {
  ImGui::Render();
  renderer_->render(*ImGui::GetDrawData(), ImGui::GetBackgroundDrawList());
}

}  // namespace impulse::viewer
