#pragma once
/// The heads-up display: preset title and explanation, the controls panel,
/// drawing status lines, the inspector, the gravity vector, the connection
/// state with tick and latency figures, and notices.

#include <SDL.h>

#include <optional>
#include <string>

#include "controls.h"
#include "impulse.pb.h"
#include "impulse/preset.h"
#include "text.h"

namespace impulse::viewer {

enum class LinkState { Connecting, Connected, Lost };

/// Everything the HUD shows that is not in Controls.
struct HudInput {
  const PresetInfo* preset = nullptr;
  Vec2 gravity = Vec2::Zero();
  bool serverPaused = false;
  /// The selected body's details (QueryBody), when they arrived.
  const v1::BodyInfo* inspected = nullptr;
  LinkState link = LinkState::Connecting;
  std::string linkText;  ///< "127.0.0.1:7777", or the reason it was lost
  double retryInSeconds = 0;
  std::uint64_t tick = 0;
  double roundTripMs = -1;  ///< < 0 while unknown
  double snapshotsPerSecond = 0;
  double playoutDelayMs = 0;
  double frameMs = 0;
  std::size_t bodies = 0;
  std::optional<std::string> notice;
};

class Hud {
 public:
  Hud(SDL_Renderer* renderer, const std::string& fontPath);

  void draw(const Controls& controls, const HudInput& input, int windowWidth, int windowHeight);
  /// Once per frame, after draw.
  void endFrame();
  bool hasText() const { return text_.available(); }

 private:
  void panel(int x, int y, int w, int h);
  void drawTitle(const HudInput& input);
  void drawControlsPanel(int windowWidth, int windowHeight);
  void drawStatus(const Controls& controls, int windowHeight);
  void drawInspector(const Controls& controls, const HudInput& input, int windowWidth);
  void drawGravity(const HudInput& input, int windowWidth, int windowHeight);
  void drawConnection(const HudInput& input, int windowWidth, int windowHeight);
  void drawNotice(const std::string& notice, int windowWidth, int windowHeight);

  SDL_Renderer* renderer_;
  TextRenderer text_;
  TextRenderer title_;
};

}  // namespace impulse::viewer
