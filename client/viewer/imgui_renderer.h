#pragma once
/// Dear ImGui's draw data onto an SDL_Renderer (SDL_RenderGeometryRaw).
/// Debian's libimgui-dev ships the header of ImGui's SDL_Renderer backend
/// but not its object file, so the viewer carries this small one.

#include <SDL.h>

struct ImDrawData;
struct ImDrawList;

namespace impulse::viewer {

class ImGuiRenderer {
 public:
  /// Uploads the font atlas of the current ImGui context (throws
  /// std::runtime_error when SDL cannot make the texture).
  explicit ImGuiRenderer(SDL_Renderer* renderer);
  ~ImGuiRenderer();
  ImGuiRenderer(const ImGuiRenderer&) = delete;
  ImGuiRenderer& operator=(const ImGuiRenderer&) = delete;

  /// Renders every list of `data`. `untextured` (the scene's list) holds
  /// shapes only, no text: it is drawn with vertex colours alone, which
  /// SDL's software renderer fills several times faster than textured
  /// triangles.
  void render(const ImDrawData& data, const ImDrawList* untextured);

 private:
  SDL_Renderer* renderer_;
  SDL_Texture* font_ = nullptr;
};

}  // namespace impulse::viewer
