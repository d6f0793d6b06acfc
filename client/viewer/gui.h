#pragma once
/// The Dear ImGui context of the viewer's window: created with the window's
/// SDL platform backend and the viewer's own SDL_Renderer backend, the HUD
/// font loaded, destroyed with the window. One per App.

#include <SDL.h>

#include <memory>
#include <string>

#include "imgui_renderer.h"

struct ImFont;

namespace impulse::viewer {

class Gui {
 public:
  /// `fontPath`: a TrueType font; ImGui's built-in font when it cannot be read.
  Gui(SDL_Window* window, SDL_Renderer* renderer, const std::string& fontPath);
  ~Gui();
  Gui(const Gui&) = delete;
  Gui& operator=(const Gui&) = delete;

  void processEvent(const SDL_Event& event);
  /// The left button and pointer as the viewer's own event handling saw
  /// them this frame.
  struct Pointer {
    float x = 0;
    float y = 0;
    bool leftDown = false;  ///< held, or pressed at any time since the last frame
  };
  /// Starts a frame: every ImGui call of the frame goes between this and
  /// render(). The scene goes into ImGui's background list, shapes only.
  void beginFrame(const Pointer& pointer);
  void render();
  ImFont* textFont() const { return text_; }
  ImFont* titleFont() const { return title_; }

 private:
  ImFont* text_ = nullptr;
  ImFont* title_ = nullptr;
  std::unique_ptr<ImGuiRenderer> renderer_;
};

}  // namespace impulse::viewer
