#pragma once
// Test harness: the real viewer App under SDL's offscreen video driver with
// the software renderer (no display needed), driven frame by frame, with
// synthetic SDL input and screenshots written into the build tree.

#include <SDL.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "app.h"
#include "impulse/client/client.h"

namespace impulse::viewer_test {

/// Where screenshots go: <build>/viewer-screenshots (kept as CI artifacts).
std::string screenshotPath(const std::string& name);

/// A connected test client that sees the world as the server has it.
client::ConnectOptions observerOptions(std::uint16_t port);

class ViewerHarness {
 public:
  /// `token` is sent in Hello, as --token would send it; `room` is joined
  /// as --room would.
  explicit ViewerHarness(std::uint16_t port, int width = 1280, int height = 720,
                         std::string token = {}, std::string room = {});
  /// The viewer over a link made `addedRoundTrip` slower (--added-rtt),
  /// predicting its own actions or not (--no-predict).
  ViewerHarness(std::uint16_t port, std::chrono::milliseconds addedRoundTrip, bool predict);
  /// The viewer with the test's options changed by `adjust` (a flag's
  /// effect, set as the command line would set it).
  ViewerHarness(std::uint16_t port, const std::function<void(viewer::ViewerOptions&)>& adjust);

  viewer::App& app() { return *app_; }
  /// Runs frames (about 60 per second) until `done` or `timeout`; true if done.
  bool runUntil(const std::function<bool()>& done,
                std::chrono::milliseconds timeout = std::chrono::milliseconds(8000));
  void runFrames(int count);
  /// Saves the next frame as BMP at `path` and returns it loaded (ARGB8888).
  std::unique_ptr<SDL_Surface, void (*)(SDL_Surface*)> capture(const std::string& path);

  // Synthetic input, as SDL would deliver it from a window.
  /// `repeat`: the keyboard's own repeat of a held key.
  void key(SDL_Keycode key, bool down, Uint16 modifiers = KMOD_NONE, bool repeat = false);
  void tap(SDL_Keycode key, Uint16 modifiers = KMOD_NONE);
  /// Text typed into the field that has the focus (SDL_TEXTINPUT), one frame.
  void typeText(const std::string& text);
  void mouseMove(float px, float py);
  void mouseButton(float px, float py, bool down, Uint8 button = SDL_BUTTON_LEFT);
  void wheel(int notches);
  void click(const Vec2& world);
  /// A press and release of the left button at window pixel (x, y), with
  /// the frames ImGui needs to see the pointer arrive first (widgets).
  void clickPixel(float px, float py);
  /// Pixel of a world point in the current window.
  viewer::PixelPoint pixel(const Vec2& world) const { return app_->view().toPixels(world); }

 private:
  std::unique_ptr<viewer::App> app_;
};

/// Runs viewer frames while `observer` catches up with the server, until
/// `done` holds or `timeout` passes; true if done.
bool observeUntil(ViewerHarness& viewer, client::Client& observer,
                  const std::function<bool()>& done,
                  std::chrono::milliseconds timeout = std::chrono::milliseconds(5000));

/// The colour of a pixel of an ARGB8888 surface.
viewer::Colour pixelAt(SDL_Surface* surface, int x, int y);
/// Largest per-channel difference.
int colourDistance(viewer::Colour a, viewer::Colour b);
/// Pixels of `area` within `tolerance` of `colour`.
int countNear(SDL_Surface* surface, SDL_Rect area, viewer::Colour colour, int tolerance);

}  // namespace impulse::viewer_test
