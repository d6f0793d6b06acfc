#include "imgui_renderer.h"

#include <imgui.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace impulse::viewer {

namespace {

SDL_Rect clipRect(const ImVec4& clip) {
  return {int(clip.x), int(clip.y), int(clip.z - clip.x), int(clip.w - clip.y)};
}

}  // namespace

ImGuiRenderer::ImGuiRenderer(SDL_Renderer* renderer) : renderer_(renderer) {
  ImGuiIO& io = ImGui::GetIO();
  io.BackendRendererName = "impulse_sdl_renderer";
  // Large scenes exceed 65536 vertices in one draw list: ImGui then splits
  // them into commands with vertex offsets, which render() honours.
  io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
  unsigned char* pixels = nullptr;
  int width = 0;
  int height = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  font_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, width,
                            height);
  if (font_ == nullptr) throw std::runtime_error(std::string("font texture: ") + SDL_GetError());
  SDL_UpdateTexture(font_, nullptr, pixels, width * 4);
  SDL_SetTextureBlendMode(font_, SDL_BLENDMODE_BLEND);
  SDL_SetTextureScaleMode(font_, SDL_ScaleModeLinear);
  io.Fonts->SetTexID(font_);
}

ImGuiRenderer::~ImGuiRenderer() {
  ImGui::GetIO().Fonts->SetTexID(nullptr);
  SDL_DestroyTexture(font_);
}

void ImGuiRenderer::render(const ImDrawData& data, const ImDrawList* untextured) {
  // ImDrawVert's colour is RGBA in memory, as SDL_Color.
  static_assert(sizeof(ImU32) == sizeof(SDL_Color));
  constexpr int kStride = sizeof(ImDrawVert);
  for (int list = 0; list < data.CmdListsCount; ++list) {
    const ImDrawList& drawList = *data.CmdLists[list];
    const ImDrawVert* vertices = drawList.VtxBuffer.Data;
    const ImDrawIdx* indices = drawList.IdxBuffer.Data;
    const bool textured = &drawList != untextured;
    for (const ImDrawCmd& command : drawList.CmdBuffer) {
      if (command.UserCallback != nullptr) {
        command.UserCallback(&drawList, &command);
        continue;
      }
      const SDL_Rect clip = clipRect(command.ClipRect);
      if (clip.w <= 0 || clip.h <= 0) continue;
      SDL_RenderSetClipRect(renderer_, &clip);
      const ImDrawVert* first = vertices + command.VtxOffset;
      SDL_Texture* texture = textured ? static_cast<SDL_Texture*>(command.GetTexID()) : nullptr;
      SDL_RenderGeometryRaw(renderer_, texture, &first->pos.x, kStride,
                            reinterpret_cast<const SDL_Color*>(&first->col), kStride,
                            texture != nullptr ? &first->uv.x : nullptr, kStride,
                            drawList.VtxBuffer.Size - int(command.VtxOffset),
                            indices + command.IdxOffset, int(command.ElemCount), sizeof(ImDrawIdx));
    }
  }
  SDL_RenderSetClipRect(renderer_, nullptr);
}

}  // namespace impulse::viewer
