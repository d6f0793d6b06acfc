#include "text.h"

#include <cstdio>

namespace impulse::viewer {

namespace {

// Textures unused for this many frames are freed (changing figures such as
// the tick counter would otherwise pile up).
constexpr std::uint64_t kKeepFrames = 30;

}  // namespace

TextRenderer::TextRenderer(SDL_Renderer* renderer, const std::string& fontPath, int pointSize)
    : renderer_(renderer) {
  if (TTF_WasInit() == 0 && TTF_Init() != 0) {
    std::fprintf(stderr, "impulse-viewer: SDL_ttf: %s\n", TTF_GetError());
    return;
  }
  font_ = TTF_OpenFont(fontPath.c_str(), pointSize);
  if (font_ == nullptr) {
    std::fprintf(stderr, "impulse-viewer: no HUD text, cannot open font %s: %s\n",
                 fontPath.c_str(), TTF_GetError());
    return;
  }
  lineHeight_ = TTF_FontLineSkip(font_);
}

TextRenderer::~TextRenderer() {
  for (auto& [key, e] : cache_) SDL_DestroyTexture(e.texture);
  if (font_ != nullptr) TTF_CloseFont(font_);
}

const TextRenderer::Entry* TextRenderer::entry(const std::string& text, Colour colour) {
  if (font_ == nullptr || text.empty()) return nullptr;
  std::string key(reinterpret_cast<const char*>(&colour), sizeof colour);
  key += text;
  auto it = cache_.find(key);
  if (it == cache_.end()) {
    SDL_Surface* surface =
        TTF_RenderUTF8_Blended(font_, text.c_str(), SDL_Color{colour.r, colour.g, colour.b, 255});
    if (surface == nullptr) return nullptr;
    Entry e;
    e.texture = SDL_CreateTextureFromSurface(renderer_, surface);
    e.width = surface->w;
    e.height = surface->h;
    SDL_FreeSurface(surface);
    if (e.texture == nullptr) return nullptr;
    SDL_SetTextureAlphaMod(e.texture, colour.a);
    it = cache_.emplace(std::move(key), e).first;
  }
  it->second.lastUsed = frame_;
  return &it->second;
}

int TextRenderer::draw(const std::string& text, int x, int y, Colour colour) {
  const Entry* e = entry(text, colour);
  if (e == nullptr) return 0;
  const SDL_Rect target{x, y, e->width, e->height};
  SDL_RenderCopy(renderer_, e->texture, nullptr, &target);
  return e->width;
}

SDL_Point TextRenderer::measure(const std::string& text) {
  if (font_ == nullptr || text.empty()) return {0, lineHeight_};
  int w = 0;
  int h = 0;
  TTF_SizeUTF8(font_, text.c_str(), &w, &h);
  return {w, h};
}

void TextRenderer::endFrame() {
  ++frame_;
  std::erase_if(cache_, [this](auto& item) {
    if (frame_ - item.second.lastUsed <= kKeepFrames) return false;
    SDL_DestroyTexture(item.second.texture);
    return true;
  });
}

}  // namespace impulse::viewer
