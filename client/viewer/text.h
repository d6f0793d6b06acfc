#pragma once
/// Text on screen with SDL2_ttf: rendered lines are cached as textures and
/// dropped when unused for a while, so a steady HUD costs no rasterising.

#include <SDL.h>
#include <SDL_ttf.h>

#include <cstdint>
#include <string>
#include <unordered_map>

#include "palette.h"

namespace impulse::viewer {

class TextRenderer {
 public:
  /// Opens `fontPath` at `pointSize`; without the font, text is skipped
  /// (available() says so) and the viewer still works.
  TextRenderer(SDL_Renderer* renderer, const std::string& fontPath, int pointSize);
  ~TextRenderer();
  TextRenderer(const TextRenderer&) = delete;
  TextRenderer& operator=(const TextRenderer&) = delete;

  bool available() const { return font_ != nullptr; }
  /// Draws one line with its top-left at (x, y); returns its width.
  int draw(const std::string& text, int x, int y, Colour colour);
  /// Width and height of a line in pixels.
  SDL_Point measure(const std::string& text);
  int lineHeight() const { return lineHeight_; }
  /// Frees textures not drawn for a while; once per frame.
  void endFrame();

 private:
  struct Entry {
    SDL_Texture* texture = nullptr;
    int width = 0;
    int height = 0;
    std::uint64_t lastUsed = 0;
  };
  const Entry* entry(const std::string& text, Colour colour);

  SDL_Renderer* renderer_;
  TTF_Font* font_ = nullptr;
  int lineHeight_ = 0;
  std::uint64_t frame_ = 0;
  std::unordered_map<std::string, Entry> cache_;
};

}  // namespace impulse::viewer
