#pragma once
/// The viewer application: one window, one frame loop. Each frame handles
/// input, exchanges messages with the server without blocking, samples the
/// interpolated world at the playout time and draws the scene beside the
/// side panel.

#include <SDL.h>

#include <memory>
#include <optional>
#include <string>
#include <unordered_set>

#include "connection.h"
#include "controls.h"
#include "event_flashes.h"
#include "gui.h"
#include "history.h"
#include "interpolated_world.h"
#include "joint_figure.h"
#include "key_map.h"
#include "layout.h"
#include "options.h"
#include "overlays.h"
#include "preset_catalogue.h"
#include "renderer.h"
#include "side_panel.h"
#include "scene_files.h"
#include "view_transform.h"

namespace impulse::viewer {

/// Timing of the last frame, milliseconds.
struct FrameTiming {
  double update = 0;   ///< events, network, interpolation
  double draw = 0;     ///< scene and panel into the back buffer
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
  /// The scene viewport and the side panel in the current window.
  WindowLayout layout() const;
  ViewTransform view() const;
  SDL_Window* window() const { return window_; }
  const FrameTiming& timing() const { return timing_; }
  std::uint64_t frames() const { return frames_; }
  /// The flashes of the event stream, waiting or showing.
  const EventFlashes& flashes() const { return flashes_; }
  /// Contacts of the last frame drawn with the contact overlay on.
  const std::vector<ShownContact>& shownContacts() const { return overlays_.contacts(); }
  const History& stepTimeHistory() const { return stepMs_; }
  const History& energyHistory() const { return energy_; }
  /// Seconds since the app started (the clock of every component).
  double now() const;
  /// Where the last frame's panel drew its scene picker entries.
  const PanelState& panelState() const { return panelState_; }
  /// Frames drawn per second over the last second or so.
  double framesPerSecond() const { return framesPerSecond_; }

 private:
  void handleEvent(const SDL_Event& event);
  void handleKey(const SDL_KeyboardEvent& key);
  void handleButton(const SDL_MouseButtonEvent& button);
  void handleMotion(const SDL_MouseMotionEvent& motion);
  void act(ControlKey key);
  void actOnScene(SceneKey key);
  ControlContext context() const;
  void exchange();
  void handleReplies();
  /// The number of the connection now up (counted from 1), 0 when none:
  /// what a per-connection request remembers it was sent on.
  int currentLink() const;
  /// Subscribes to the server's events while the flashes are on (again
  /// after a reconnect), unsubscribes when they go off, and turns the
  /// events received into flashes.
  void followEvents(double now);
  /// Frames the room on a new connection (scene_frame.h), once its bounds
  /// (and, for a room too large to open on, its first snapshot) are known;
  /// a reconnect to a room with the same bounds keeps the view.
  void frameRoom();
  /// The room's bounds from its welcome, in the mirror's frame.
  AABB roomBounds() const;
  /// Fits the frame (scene_frame.h) to the room as it is now: on a new
  /// connection, and on F, where a room that opens on its bodies is framed
  /// on the bodies the mirror holds now (the area sent follows the view).
  void fitFrame();
  void framePresetLanding();
  /// Sends --budget on every new connection, and --area-margin's area on
  /// every new connection once the room is framed and whenever the view
  /// moves past half the margin.
  void followView();
  void recordFigures();
  void draw();
  void drawScene(ImDrawList& list, const ViewTransform& view);
  /// The mirror's joints where the drawn (interpolated) bodies are, into
  /// jointFigures_ (reused every frame).
  void updateJointFigures();
  bool saveCapture(const std::string& path);
  /// The room joined, "default" when none was named.
  std::string roomName() const;
  /// Counts a frame that ended `at`; updates the frame rate once a second.
  void countFrame(double at);
  const client::MirrorBody* mirrored(std::uint32_t id) const;
  std::optional<BodyHit> bodyAt(const Vec2& point) const;
  std::vector<std::uint32_t> userBodies() const;

  ViewerOptions options_;
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  std::uint64_t start_ = 0;
  InterpolatedWorld world_;
  Controls controls_;
  SceneFiles sceneFiles_;
  std::unique_ptr<Connection> connection_;
  std::unique_ptr<Gui> gui_;
  WorldRenderer scene_;
  std::vector<JointFigure> jointFigures_;
  OverlayRenderer overlays_;
  EventFlashes flashes_;
  /// The connection (Connection::connections()) subscribed to events, 0 for none.
  int eventsConnection_ = 0;
  /// The connection that has the budget, and the one that has sentArea_.
  int budgetConnection_ = 0;
  int areaConnection_ = 0;
  AABB sentArea_;
  /// The connection whose room is framed, and the bounds it was framed for.
  int framedConnection_ = 0;
  std::optional<AABB> framedBounds_;
  std::uint64_t eventMessages_ = 0;
  std::optional<v1::BodyInfo> inspected_;
  double nextInspect_ = 0;
  bool presetRequested_ = false;
  /// Bodies this viewer spawned: C removes them even when static.
  std::unordered_set<std::uint32_t> spawned_;
  std::optional<v1::ServerStats> stats_;
  History stepMs_{240};
  History energy_{240};
  // The pointer in window pixels, and the right or middle button drag.
  float pointerX_ = 0;
  float pointerY_ = 0;
  std::optional<SDL_Point> altPressedAt_;
  bool leftHeld_ = false;
  bool leftPressed_ = false;  ///< since the last frame
  bool altDragged_ = false;
  std::optional<std::string> capturePath_;
  FrameTiming timing_;
  double frameMs_ = 0;
  std::uint64_t frames_ = 0;
  double framesPerSecond_ = 0;
  double windowStart_ = 0;
  int windowFrames_ = 0;
  /// Every preset's title and explanation, for the scene picker.
  std::vector<PresetInfo> presets_ = presetCatalogue();
  std::vector<std::string> sceneFileList_;
  PanelState panelState_;
  bool quit_ = false;
};

}  // namespace impulse::viewer
