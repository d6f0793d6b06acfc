#include "hud.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "impulse/wire/convert.h"

namespace impulse::viewer {

namespace {

// Inside the scene's 25 px walls and floor at the default size, so text never
// sits on the grey boundary.
constexpr int kMargin = 32;
constexpr int kPad = 8;

std::string format(const char* pattern, auto... values) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

std::string onOff(bool value) { return value ? "on" : "off"; }

std::string modeName(DrawMode mode) {
  switch (mode) {
    case DrawMode::Polygon: return "Polygon";
    case DrawMode::Circle: return "Circle";
    case DrawMode::None: break;
  }
  return "none";
}

// SPEC.md's control table, as the panel shows it.
constexpr std::array<std::pair<const char*, const char*>, 14> kControlRows{{
    {"P", "polygon mode; again: create (3+ points) or cancel"},
    {"click", "place a point where the cursor is green"},
    {"O", "circle mode; again: create (if dragged) or cancel"},
    {"drag", "circle: centre at press, radius to the cursor"},
    {"C", "clear all bodies"},
    {"X", "show or hide this panel"},
    {"M", "inspector: click a body, arrows push it"},
    {"Q / G", "next shapes static / feel gravity"},
    {"KP 1-5, F5-F9", "material SOLID ICE WOOD METAL RUBBER"},
    {"1-9, F1, 0", "load preset 1-9, 10, sandbox"},
    {"W A S D", "nudge gravity while held"},
    {"Enter", "reset gravity"},
    {"Esc", "quit"},
    {"", "drawing: sandbox and presets 3, 4"},
}};

}  // namespace

Hud::Hud(SDL_Renderer* renderer, const std::string& fontPath)
    : renderer_(renderer), text_(renderer, fontPath, 14), title_(renderer, fontPath, 20) {}

void Hud::endFrame() {
  text_.endFrame();
  title_.endFrame();
}

void Hud::panel(int x, int y, int w, int h) {
  const Colour c = palette::kPanel;
  SDL_SetRenderDrawColor(renderer_, c.r, c.g, c.b, c.a);
  const SDL_Rect rect{x, y, w, h};
  SDL_RenderFillRect(renderer_, &rect);
}

void Hud::draw(const Controls& controls, const HudInput& input, int windowWidth,
               int windowHeight) {
  drawTitle(input);
  if (controls.panelVisible()) drawControlsPanel(windowWidth, windowHeight);
  if (controls.mode() != DrawMode::None) drawStatus(controls, windowHeight);
  if (controls.inspectorVisible()) drawInspector(controls, input, windowWidth);
  drawGravity(input, windowWidth, windowHeight);
  drawConnection(input, windowWidth, windowHeight);
  if (input.notice) drawNotice(*input.notice, windowWidth, windowHeight);
}

void Hud::drawTitle(const HudInput& input) {
  if (input.preset == nullptr) return;
  int y = kMargin;
  std::string title = input.preset->title;
  if (input.serverPaused) title += "  (paused)";
  title_.draw(title, kMargin, y, palette::kText);
  y += title_.lineHeight() + 2;
  for (const std::string& line : input.preset->explanation) {
    text_.draw(line, kMargin, y, palette::kDimText);
    y += text_.lineHeight();
  }
}

void Hud::drawControlsPanel(int windowWidth, int windowHeight) {
  const int line = text_.lineHeight();
  int keyWidth = 0;
  int width = 0;
  for (const auto& [key, action] : kControlRows) {
    keyWidth = std::max(keyWidth, text_.measure(key).x);
    width = std::max(width, text_.measure(action).x);
  }
  const int w = keyWidth + width + 3 * kPad;
  const int h = (int(kControlRows.size()) + 1) * line + 2 * kPad;
  const int x = std::max(kMargin, (windowWidth - w) / 2);
  const int y = std::max(kMargin, (windowHeight - h) / 2);
  panel(x, y, w, h);
  int row = y + kPad;
  text_.draw("Controls (X to hide)", x + kPad, row, palette::kMarker);
  row += line;
  for (const auto& [key, action] : kControlRows) {
    text_.draw(key, x + kPad, row, palette::kText);
    text_.draw(action, x + 2 * kPad + keyWidth, row, palette::kDimText);
    row += line;
  }
}

void Hud::drawStatus(const Controls& controls, int windowHeight) {
  std::string mode = "Mode: " + modeName(controls.mode());
  if (controls.mode() == DrawMode::Polygon) {
    mode += format(" (%zu points; P to finish)", controls.polygonPoints().size());
  } else {
    mode += " (drag from the centre; O to finish)";
  }
  const std::array<std::string, 4> lines{
      mode, "Static: " + onOff(controls.nextStatic()),
      "Gravity: " + onOff(controls.nextFeelsGravity()),
      "Material: " + materialLabel(controls.material())};
  const int line = text_.lineHeight();
  int y = windowHeight - kMargin - int(lines.size()) * line;
  for (const std::string& text : lines) {
    text_.draw(text, kMargin, y, palette::kText);
    y += line;
  }
}

void Hud::drawInspector(const Controls& controls, const HudInput& input, int windowWidth) {
  std::vector<std::string> lines{"Inspector (M)"};
  if (!controls.selectedBody()) {
    lines.push_back("click a body to select it");
  } else if (input.inspected == nullptr) {
    lines.push_back(format("body %u: waiting...", *controls.selectedBody()));
  } else {
    const v1::BodyInfo& info = *input.inspected;
    const auto& s = info.state();
    const auto material = wire::materialFromWire(info.descriptor().material());
    lines.push_back(format("body %u%s", info.descriptor().id(),
                           info.descriptor().is_static() ? " (static)" : ""));
    lines.push_back(format("position  (%.2f, %.2f) m", s.position().x(), s.position().y()));
    lines.push_back(format("velocity  (%.2f, %.2f) m/s", s.velocity().x(), s.velocity().y()));
    lines.push_back(format("angular velocity  %.2f rad/s", s.angular_velocity()));
    lines.push_back(format("mass  %.2f kg", info.mass()));
    lines.push_back(format("area  %.3f m^2", info.area()));
    lines.push_back(format("restitution  %.2f", info.restitution()));
    lines.push_back(format("friction  static %.2f, dynamic %.2f", info.static_friction(),
                           info.dynamic_friction()));
    lines.push_back("material  " + materialLabel(material.value_or(Material::Solid)));
    lines.push_back("arrows push it");
  }
  lines.push_back(format("gravity  (%.2f, %.2f) m/s^2", input.gravity.x(), input.gravity.y()));
  int w = 0;
  for (const auto& l : lines) w = std::max(w, text_.measure(l).x);
  w += 2 * kPad;
  const int line = text_.lineHeight();
  const int h = int(lines.size()) * line + 2 * kPad;
  const int x = windowWidth - kMargin - w;
  panel(x, kMargin, w, h);
  int y = kMargin + kPad;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    text_.draw(lines[i], x + kPad, y, i == 0 ? palette::kMarker : palette::kText);
    y += line;
  }
}

void Hud::drawGravity(const HudInput& input, int windowWidth, int windowHeight) {
  // An arrow in a circle at the bottom right; its length is |g| / 20 of the
  // radius, so default gravity shows about half way.
  const float radius = 28;
  const float cx = float(windowWidth) - kMargin - radius;
  const float cy = float(windowHeight) - 3 * kMargin - 2 * text_.lineHeight() - radius;
  const Colour c = palette::kGravity;
  SDL_SetRenderDrawColor(renderer_, 70, 70, 85, 255);
  constexpr int kSegments = 32;
  std::array<SDL_FPoint, kSegments + 1> ring{};
  for (int i = 0; i <= kSegments; ++i) {
    const float a = float(i) * 6.2831853f / kSegments;
    ring[i] = {cx + radius * std::cos(a), cy + radius * std::sin(a)};
  }
  SDL_RenderDrawLinesF(renderer_, ring.data(), int(ring.size()));
  const float g = input.gravity.norm();
  SDL_SetRenderDrawColor(renderer_, c.r, c.g, c.b, c.a);
  if (g > 1e-3f) {
    const float scale = std::min(1.0f, g / 20.0f) * radius / g;
    const float ex = cx + input.gravity.x() * scale;
    const float ey = cy - input.gravity.y() * scale;
    SDL_RenderDrawLineF(renderer_, cx, cy, ex, ey);
    const float ux = (ex - cx) / (g * scale);
    const float uy = (ey - cy) / (g * scale);
    const float head = 6;
    SDL_RenderDrawLineF(renderer_, ex, ey, ex - head * (ux + 0.5f * uy), ey - head * (uy - 0.5f * ux));
    SDL_RenderDrawLineF(renderer_, ex, ey, ex - head * (ux - 0.5f * uy), ey - head * (uy + 0.5f * ux));
  }
  const std::string label = format("g (%.2f, %.2f)", input.gravity.x(), input.gravity.y());
  text_.draw(label, int(cx + radius) - text_.measure(label).x, int(cy + radius) + 2, c);
}

void Hud::drawConnection(const HudInput& input, int windowWidth, int windowHeight) {
  std::string state;
  Colour colour = palette::kDimText;
  switch (input.link) {
    case LinkState::Connecting:
      state = "connecting to " + input.linkText + "...";
      colour = palette::kWarning;
      break;
    case LinkState::Connected: state = "connected to " + input.linkText; break;
    case LinkState::Lost:
      state = format("connection lost (%s), retrying in %.1f s", input.linkText.c_str(),
                     input.retryInSeconds);
      colour = palette::kInvalid;
      break;
  }
  std::string figures = format("tick %llu  bodies %zu  snap %.0f/s", (unsigned long long)input.tick,
                               input.bodies, input.snapshotsPerSecond);
  if (input.roundTripMs >= 0) figures += format("  rtt %.1f ms", input.roundTripMs);
  figures += format("  delay %.0f ms  frame %.1f ms", input.playoutDelayMs, input.frameMs);
  const int line = text_.lineHeight();
  const int y = windowHeight - kMargin - 2 * line;
  text_.draw(state, windowWidth - kMargin - text_.measure(state).x, y, colour);
  text_.draw(figures, windowWidth - kMargin - text_.measure(figures).x, y + line,
             palette::kDimText);
}

void Hud::drawNotice(const std::string& notice, int windowWidth, int windowHeight) {
  const SDL_Point size = text_.measure(notice);
  const int x = (windowWidth - size.x) / 2;
  const int y = windowHeight / 5;
  panel(x - kPad, y - kPad / 2, size.x + 2 * kPad, size.y + kPad);
  text_.draw(notice, x, y, palette::kWarning);
}

}  // namespace impulse::viewer
