#pragma once
/// The viewer application: one window, one frame loop. Each frame handles
/// input, exchanges messages with the server without blocking, samples the
/// interpolated world at the playout time and draws it with the HUD.

#include <SDL.h>

#include <memory>
#include <optional>
#include <string>

#include "connection.h"
#include "controls.h"
#include "hud.h"
#include "interpolated_world.h"
#include "options.h"
#include "renderer.h"
#include "view_transform.h"

namespace impulse::viewer {

/// Timing of the last frame, milliseconds.
struct FrameTiming {
  double update = 0;   ///< events, network, interpolation
  double draw = 0;     ///< scene and HUD into the back buffer
  double present = 0;  ///< SDL_RenderPresent (waits for vsync when on)
};

class App {
 public:
  /// Opens the window (throws std::runtime_error when SDL cannot) and starts
  /// connecting.
  explicit App(ViewerOptions options);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  /// Runs frames until Esc, the window closes or options.frames are done;
  /// the process exit code.
  int run();
  /// One frame; false once the viewer should quit.
  bool frame();
  /// Saves the next frame as a BMP (before it is presented).
  void captureNextFrame(std::string path) { capturePath_ = std::move(path); }

  const Controls& controls() const { return controls_; }
  const Connection& connection() const { return *connection_; }
  const InterpolatedWorld& world() const { return world_; }
  ViewTransform view() const;
  SDL_Window* window() const { return window_; }
  const FrameTiming& timing() const { return timing_; }
  std::uint64_t frames() const { return frames_; }
  /// Seconds since the app started (the clock of every component).
  double now() const;

 private:
  void handleEvent(const SDL_Event& event);
  ControlContext context() const;
  void exchange();
  void draw();
  bool saveCapture(const std::string& path);
  std::optional<std::uint32_t> bodyAt(const Vec2& point) const;

  ViewerOptions options_;
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  std::uint64_t start_ = 0;
  InterpolatedWorld world_;
  Controls controls_;
  std::unique_ptr<Connection> connection_;
  std::unique_ptr<WorldRenderer> scene_;
  std::unique_ptr<Hud> hud_;
  std::optional<v1::BodyInfo> inspected_;
  double nextInspect_ = 0;
  bool presetRequested_ = false;
  std::optional<std::string> capturePath_;
  FrameTiming timing_;
  double frameMs_ = 0;
  std::uint64_t frames_ = 0;
  bool quit_ = false;
};

}  // namespace impulse::viewer
