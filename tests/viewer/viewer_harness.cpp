#include "viewer_harness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <utility>

namespace impulse::viewer_test {

std::string screenshotPath(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(IMPULSE_SCREENSHOT_DIR);
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

client::ConnectOptions observerOptions(std::uint16_t port) {
  client::ConnectOptions options;
  options.port = port;
  options.name = "viewer-test-observer";
  return options;
}

namespace {

viewer::ViewerOptions testOptions(std::uint16_t port) {
  // No display in CI: SDL's offscreen driver and its software renderer,
  // drawing straight into the window surface (without framebuffer
  // acceleration SDL never loads Mesa through EGL, whose unloaded drivers
  // LeakSanitizer would report in sanitizer builds).
  setenv("SDL_VIDEODRIVER", "offscreen", 1);
  setenv("SDL_RENDER_DRIVER", "software", 1);
  setenv("SDL_FRAMEBUFFER_ACCELERATION", "0", 1);
  viewer::ViewerOptions options;
  options.connect.port = port;
  options.connect.name = "viewer-under-test";
  options.fontPath = viewer::defaultFontPath();
  options.vsync = false;
  return options;
}

}  // namespace

ViewerHarness::ViewerHarness(std::uint16_t port, int width, int height, std::string token,
                             std::string room)
    : ViewerHarness(port, [&](viewer::ViewerOptions& options) {
        options.connect.token = std::move(token);
        options.connect.room = std::move(room);
        options.width = width;
        options.height = height;
      }) {}

ViewerHarness::ViewerHarness(std::uint16_t port, std::chrono::milliseconds addedRoundTrip,
                             bool predict)
    : ViewerHarness(port, [&](viewer::ViewerOptions& options) {
        options.connect.addedRoundTrip = addedRoundTrip;
        options.predict = predict;
      }) {}

ViewerHarness::ViewerHarness(std::uint16_t port,
                             const std::function<void(viewer::ViewerOptions&)>& adjust) {
  viewer::ViewerOptions options = testOptions(port);
  adjust(options);
  app_ = std::make_unique<viewer::App>(options);
}

bool ViewerHarness::runUntil(const std::function<bool()>& done,
                             std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    app_->frame();
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(16));
  }
  return false;
}

void ViewerHarness::runFrames(int count) {
  for (int i = 0; i < count; ++i) {
    app_->frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(16));
  }
}

std::unique_ptr<SDL_Surface, void (*)(SDL_Surface*)> ViewerHarness::capture(
    const std::string& path) {
  app_->captureNextFrame(path);
  app_->frame();
  SDL_Surface* loaded = SDL_LoadBMP(path.c_str());
  SDL_Surface* converted = nullptr;
  if (loaded != nullptr) {
    converted = SDL_ConvertSurfaceFormat(loaded, SDL_PIXELFORMAT_ARGB8888, 0);
    SDL_FreeSurface(loaded);
  }
  return {converted, SDL_FreeSurface};
}

void ViewerHarness::key(SDL_Keycode key, bool down, Uint16 modifiers, bool repeat) {
  SDL_Event event{};
  event.type = down ? SDL_KEYDOWN : SDL_KEYUP;
  event.key.repeat = repeat ? 1 : 0;
  event.key.state = down ? SDL_PRESSED : SDL_RELEASED;
  event.key.keysym.sym = key;
  event.key.keysym.scancode = SDL_GetScancodeFromKey(key);
  event.key.keysym.mod = modifiers;
  event.key.windowID = SDL_GetWindowID(app_->window());
  SDL_PushEvent(&event);
}

void ViewerHarness::tap(SDL_Keycode k, Uint16 modifiers) {
  key(k, true, modifiers);
  app_->frame();
  key(k, false, modifiers);
  app_->frame();
}

void ViewerHarness::typeText(const std::string& text) {
  SDL_Event event{};
  event.type = SDL_TEXTINPUT;
  event.text.windowID = SDL_GetWindowID(app_->window());
  text.copy(event.text.text, sizeof(event.text.text) - 1);
  SDL_PushEvent(&event);
  app_->frame();
}

void ViewerHarness::mouseMove(float px, float py) {
  SDL_Event event{};
  event.type = SDL_MOUSEMOTION;
  event.motion.windowID = SDL_GetWindowID(app_->window());
  event.motion.x = int(px);
  event.motion.y = int(py);
  SDL_PushEvent(&event);
}

void ViewerHarness::mouseButton(float px, float py, bool down, Uint8 button) {
  SDL_Event event{};
  event.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
  event.button.windowID = SDL_GetWindowID(app_->window());
  event.button.button = button;
  event.button.state = down ? SDL_PRESSED : SDL_RELEASED;
  event.button.clicks = 1;
  event.button.x = int(px);
  event.button.y = int(py);
  SDL_PushEvent(&event);
}

void ViewerHarness::wheel(int notches) {
  SDL_Event event{};
  event.type = SDL_MOUSEWHEEL;
  event.wheel.windowID = SDL_GetWindowID(app_->window());
  event.wheel.y = notches;
  SDL_PushEvent(&event);
}

void ViewerHarness::click(const Vec2& world) {
  const auto p = pixel(world);
  mouseMove(p.x, p.y);
  mouseButton(p.x, p.y, true);
  app_->frame();
  mouseButton(p.x, p.y, false);
  app_->frame();
}

void ViewerHarness::clickPixel(float px, float py) {
  mouseMove(px, py);
  runFrames(2);
  mouseButton(px, py, true);
  runFrames(2);
  mouseButton(px, py, false);
  runFrames(2);
}

bool observeUntil(ViewerHarness& viewer, client::Client& observer,
                  const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    observer.poll(std::chrono::milliseconds(10));
    viewer.app().frame();
    if (done()) return true;
  }
  return false;
}

viewer::Colour pixelAt(SDL_Surface* surface, int x, int y) {
  const auto* row = static_cast<const std::uint8_t*>(surface->pixels) + y * surface->pitch;
  const std::uint32_t argb = reinterpret_cast<const std::uint32_t*>(row)[x];
  return {std::uint8_t(argb >> 16), std::uint8_t(argb >> 8), std::uint8_t(argb), 255};
}

int colourDistance(viewer::Colour a, viewer::Colour b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

int countNear(SDL_Surface* surface, SDL_Rect area, viewer::Colour colour, int tolerance) {
  int count = 0;
  for (int y = area.y; y < area.y + area.h; ++y) {
    for (int x = area.x; x < area.x + area.w; ++x) {
      if (colourDistance(pixelAt(surface, x, y), colour) <= tolerance) ++count;
    }
  }
  return count;
}

}  // namespace impulse::viewer_test
